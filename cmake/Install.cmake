# What `cmake --install` puts where (GNUInstallDirs), and the Debian package CPack builds from it.
# The installed editor finds its example projects in ${datadir}/speculum/scenes (app/ResourcePaths.cpp
# looks beside the executable: ../share/speculum/scenes).
include(GNUInstallDirs)

set(speculum_app_id org.speculum.Speculum)
set(desktop ${CMAKE_CURRENT_SOURCE_DIR}/resources/desktop)

install(TARGETS speculum RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The example projects keep their layout: models.speculum.json names ../models/toyset.glb.
install(DIRECTORY resources/scenes resources/models DESTINATION ${CMAKE_INSTALL_DATADIR}/speculum)
install(FILES ${desktop}/${speculum_app_id}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${desktop}/${speculum_app_id}.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${desktop}/${speculum_app_id}.mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME ${speculum_app_id}.xml)
install(FILES ${desktop}/${speculum_app_id}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES docs/speculum.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# cpack -G DEB (the `package` preset): one binary package; dpkg-shlibdeps finds the library packages the
# binary links, so the run-time dependencies are Debian's own, not a list kept by hand.
set(CPACK_PACKAGE_NAME speculum)
set(CPACK_PACKAGE_VENDOR "speculum")
set(CPACK_PACKAGE_CONTACT "speculum maintainers <speculum@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "scene editor for mirrors and reflections")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "scene editor for mirrors and reflections\n speculum builds scenes with planar mirrors and one curved reflector, shows them live\n and exports stills; every approximation can be measured against an exact\n ray-traced reference.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What dpkg-shlibdeps cannot see: libepoxy opens EGL and GL at run time, and Qt loads its platform plugins
# (xcb, wayland) the same way. The driver itself is the user's; Mesa's gives software GL anywhere.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1, qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri, libegl-mesa0, fonts-dejavu-core")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
include(CPack)
