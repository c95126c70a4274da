# The layers hold by construction; these tests (unit tier) fail when they stop holding.
set(layers_dir ${CMAKE_CURRENT_LIST_DIR})

# Links only the GL-free core, and has only the core's include root: a GL, Embree or OpenImageIO header
# or symbol reached from the planner breaks this program's build.
add_executable(test_layers_core_only ${layers_dir}/test_core_only.cpp)
target_link_libraries(test_layers_core_only PRIVATE speculum_render_core GTest::gtest GTest::gtest_main
                                                    speculum_warnings)
gtest_discover_tests(test_layers_core_only DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit TIMEOUT 60)

# What each render library's archive needs from outside, by symbol name: the core no GL (epoxy's
# pointers, gl*/egl* functions), no Embree (rtc*), no OpenImageIO and no Qt; images and the tracer no GL.
set(gl_symbols "^(epoxy_|gl[A-Z]|egl[A-Z])")
set(embree_symbols "^rtc[A-Z]")
set(oiio_symbols "OpenImageIO|OIIO::")
set(qt_symbols "(^|[^A-Za-z])Q[A-Z][A-Za-z]*::|^qt_")
function(speculum_check_symbols name library forbidden)
    add_test(NAME ${name}
             COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DARCHIVE=$<TARGET_FILE:${library}>
                     "-DFORBIDDEN=${forbidden}" ${ARGN} -P ${layers_dir}/CheckSymbols.cmake)
    set_tests_properties(${name} PROPERTIES LABELS unit TIMEOUT 60)
endfunction()
speculum_check_symbols(layers_core_symbols speculum_render_core
                       "${gl_symbols}|${embree_symbols}|${oiio_symbols}|${qt_symbols}")
speculum_check_symbols(layers_images_symbols speculum_render_images
                       "${gl_symbols}|${embree_symbols}|${qt_symbols}")
speculum_check_symbols(layers_tracer_symbols speculum_render_tracer
                       "${gl_symbols}|${oiio_symbols}|${qt_symbols}")
# The check itself: the GL library does call GL.
speculum_check_symbols(layers_symbol_check_sees_gl speculum_render_gl "${gl_symbols}" -DEXPECT_FORBIDDEN=ON)

# The core's declared links: GLM and the warning flags, nothing else.
file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/layers/core-links.txt
     CONTENT "$<TARGET_PROPERTY:speculum_render_core,LINK_LIBRARIES>\n")
add_test(NAME layers_core_links
         COMMAND ${CMAKE_COMMAND} -DLINKS=${CMAKE_CURRENT_BINARY_DIR}/layers/core-links.txt
                 "-DALLOWED=glm::glm|speculum_warnings" -P ${layers_dir}/CheckLinks.cmake)
set_tests_properties(layers_core_links PROPERTIES LABELS unit TIMEOUT 60)

# Includes across the layers (scripts/check-layers), with the render libraries as CMake defines them,
# and the checker's own test.
add_test(NAME layers_includes
         COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --root ${SPECULUM_SOURCE_ROOT}
                 --libraries ${CMAKE_BINARY_DIR}/render-libraries.txt)
add_test(NAME layers_includes_self_test
         COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --self-test)
set_tests_properties(layers_includes layers_includes_self_test PROPERTIES LABELS unit TIMEOUT 60)

# Test builds keep assertions on (no NDEBUG).
speculum_add_test(test_layers_assertions TIER unit SOURCES ${layers_dir}/test_assertions.cpp)
