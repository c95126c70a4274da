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

# The core's declared links: GLM, meshoptimizer (the simplified level of big meshes, CPU only) and the
# warning flags, nothing else.
file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/layers/core-links.txt
     CONTENT "$<TARGET_PROPERTY:speculum_render_core,LINK_LIBRARIES>\n")
add_test(NAME layers_core_links
         COMMAND ${CMAKE_COMMAND} -DLINKS=${CMAKE_CURRENT_BINARY_DIR}/layers/core-links.txt
                 "-DALLOWED=glm::glm|meshoptimizer::meshoptimizer|speculum_warnings" -P ${layers_dir}/CheckLinks.cmake)
set_tests_properties(layers_core_links PROPERTIES LABELS unit TIMEOUT 60)

# The model and the view link nothing that draws (no render GL, tracer or accuracy, no epoxy or EGL), so
# test_editor_view and the document's users that do not render link no GL: the still export and the
# sweep's results are speculum_document_renderer's.
function(speculum_check_links name library allowed)
    file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/layers/${name}.txt
         CONTENT "$<TARGET_PROPERTY:${library},LINK_LIBRARIES>\n")
    add_test(NAME ${name}
             COMMAND ${CMAKE_COMMAND} -DLINKS=${CMAKE_CURRENT_BINARY_DIR}/layers/${name}.txt
                     "-DALLOWED=${allowed}" -P ${layers_dir}/CheckLinks.cmake)
    set_tests_properties(${name} PROPERTIES LABELS unit TIMEOUT 60)
endfunction()
speculum_check_links(layers_document_links speculum_document_core
    "speculum_render_core|speculum_render_images|Qt6::Core|Qt6::Gui|assimp::assimp|PkgConfig::OIIO|meshoptimizer::meshoptimizer|speculum_warnings")
speculum_check_links(layers_view_links speculum_view "speculum_document_core|Qt6::Core|speculum_warnings")

# Includes across the layers (scripts/check-layers), with the render libraries as CMake defines them,
# and the checker's own test.
add_test(NAME layers_includes
         COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --root ${SPECULUM_SOURCE_ROOT}
                 --libraries ${CMAKE_BINARY_DIR}/render-libraries.txt)
add_test(NAME layers_includes_self_test
         COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --self-test)
set_tests_properties(layers_includes layers_includes_self_test PROPERTIES LABELS unit TIMEOUT 60)

# The include roots above render (editor/CMakeLists.txt, app/CMakeLists.txt): a header is compiled alone
# with exactly the include directories and definitions a library's sources get. A header of a layer above
# (or, for the model, the renderer's) is not found, while one of the library's own compiles, so a
# failure of the first kind says the root works and not that the flags are broken.
function(speculum_include_probe name library header expect)
    set(probe ${CMAKE_CURRENT_BINARY_DIR}/layers/${name}.cpp)
    file(WRITE ${probe} "#include \"${header}\"\n")
    # Without the compiler's own /usr/include, which as a -I would break libstdc++'s #include_next (the
    # build leaves it out too).
    set(includes "$<TARGET_PROPERTY:${library},INCLUDE_DIRECTORIES>")
    add_test(NAME ${name}
             COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -fPIC
                     "-D$<JOIN:$<TARGET_PROPERTY:${library},COMPILE_DEFINITIONS>,;-D>"
                     "-I$<JOIN:$<FILTER:${includes},EXCLUDE,^/usr/include/?$>,;-I>" ${probe}
             COMMAND_EXPAND_LISTS)
    set_tests_properties(${name} PROPERTIES LABELS unit TIMEOUT 60)
    if(expect STREQUAL "missing")
        string(REPLACE "." "\\." escaped "${header}")
        # gcc: "fatal error: editor/ui/MainWindow.hpp: No such file or directory"; clang: "'...' file not
        # found". Any other error does not match, so it fails the test.
        set_tests_properties(${name} PROPERTIES
                             PASS_REGULAR_EXPRESSION "${escaped}: No such file|${escaped}' file not found")
    endif()
endfunction()
speculum_include_probe(layers_document_sees_own_headers speculum_document_core editor/document/Scene.hpp found)
speculum_include_probe(layers_document_sees_no_view speculum_document_core editor/view/Selection.hpp missing)
speculum_include_probe(layers_document_sees_no_ui speculum_document_core editor/ui/MainWindow.hpp missing)
# The model draws nothing: the renderer is for the still export and the sweep (speculum_document_renderer).
speculum_include_probe(layers_document_sees_no_renderer speculum_document_core render/Renderer.hpp missing)
speculum_include_probe(layers_view_sees_the_document speculum_view editor/view/Selection.hpp found)
speculum_include_probe(layers_view_sees_no_ui speculum_view editor/ui/Viewport.hpp missing)
speculum_include_probe(layers_ui_sees_no_app speculum_ui app/CliOptions.hpp missing)
speculum_include_probe(layers_accuracy_sees_no_editor speculum_accuracy editor/document/Scene.hpp missing)

# Test builds keep assertions on (no NDEBUG).
speculum_add_test(test_layers_assertions TIER unit SOURCES ${layers_dir}/test_assertions.cpp)
