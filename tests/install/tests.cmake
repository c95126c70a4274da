# The install check (check-install.sh): `cmake --install` into a staging folder, every file a desktop user
# gets, the desktop entry, MIME type and metainfo validated, the staged binary run on a staged example,
# and the Debian package built from the same rules. Labelled `install`: the release run includes it, the
# sanitizer run (unit and gl tiers) does not.
add_test(NAME install_check
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/check-install.sh ${CMAKE_BINARY_DIR}
                 ${CMAKE_BINARY_DIR}/install-check)
set_tests_properties(install_check PROPERTIES LABELS install TIMEOUT 300)
