# The layers hold by construction (each folder a library with an include root of its own); these tests
# (unit tier) fail when they stop holding.
set(layers_dir ${CMAKE_CURRENT_LIST_DIR})

# Every include and link against the libraries as the CMakeLists.txt files declare them (libraries.txt,
# cmake/Library.cmake), and the rules no link may break: app/ and scene/ never use editor/, the scene's
# model and project files link no Assimp and nothing that draws, render/ is Qt-free, no enum is defined
# twice. With the checker's own test.
add_test(NAME layers_check
         COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --root ${SPECULUM_SOURCE_ROOT}
                 --graph ${CMAKE_BINARY_DIR}/libraries.txt)
add_test(NAME layers_check_self_test COMMAND ${SPECULUM_SOURCE_ROOT}/scripts/check-layers --self-test)
set_tests_properties(layers_check layers_check_self_test PROPERTIES LABELS unit TIMEOUT 60)

# Links only the planner (and what it links), and has only their include roots: a GL, Embree or
# OpenImageIO header or symbol reached from the planner breaks this program's build.
add_executable(test_layers_core_only ${layers_dir}/test_core_only.cpp)
target_link_libraries(test_layers_core_only PRIVATE speculum_render_plan GTest::gtest GTest::gtest_main
                                                    speculum_warnings)
gtest_discover_tests(test_layers_core_only DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit TIMEOUT 60)

# What each library's archive needs from outside, by symbol name: what the links say, seen in the objects.
set(gl_symbols "^(epoxy_|gl[A-Z]|egl[A-Z])")
set(embree_symbols "^rtc[A-Z]")
set(oiio_symbols "OpenImageIO|OIIO::")
set(assimp_symbols "Assimp::|^ai[A-Z]")
set(qt_symbols "(^|[^A-Za-z])Q[A-Z][A-Za-z]*::|^qt_")
function(speculum_check_symbols name library forbidden)
    add_test(NAME ${name}
             COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DARCHIVE=$<TARGET_FILE:${library}>
                     "-DFORBIDDEN=${forbidden}" ${ARGN} -P ${layers_dir}/CheckSymbols.cmake)
    set_tests_properties(${name} PROPERTIES LABELS unit TIMEOUT 60)
endfunction()
foreach(library math envmap plan mesh)
    speculum_check_symbols(layers_render_${library}_symbols speculum_render_${library}
                           "${gl_symbols}|${embree_symbols}|${oiio_symbols}|${qt_symbols}")
endforeach()
speculum_check_symbols(layers_render_imageio_symbols speculum_render_imageio
                       "${gl_symbols}|${embree_symbols}|${qt_symbols}")
speculum_check_symbols(layers_render_reference_symbols speculum_render_reference "${gl_symbols}|${qt_symbols}")
foreach(library model project)
    speculum_check_symbols(layers_scene_${library}_symbols speculum_scene_${library}
                           "${gl_symbols}|${assimp_symbols}|${embree_symbols}")
endforeach()
# The check itself: the GL library does call GL, the import does call Assimp.
speculum_check_symbols(layers_symbol_check_sees_gl speculum_render_gl "${gl_symbols}" -DEXPECT_FORBIDDEN=ON)
speculum_check_symbols(layers_symbol_check_sees_assimp speculum_scene_import "${assimp_symbols}"
                       -DEXPECT_FORBIDDEN=ON)

# The include roots: a header is compiled alone with exactly the include directories and definitions a
# library's sources get. A header of a layer above (or, for the model, the renderer's) is not found, while
# one of the library's own compiles, so a failure of the first kind says the root works and not that the
# flags are broken.
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
speculum_include_probe(layers_model_sees_own_headers speculum_scene_model scene/model/Scene.hpp found)
speculum_include_probe(layers_model_sees_no_import speculum_scene_model scene/import/MeshLibrary.hpp missing)
speculum_include_probe(layers_model_sees_no_renderer speculum_scene_model render/renderer/Renderer.hpp missing)
speculum_include_probe(layers_project_sees_no_editing speculum_scene_project editor/document/Commands.hpp
                       missing)
speculum_include_probe(layers_document_sees_no_view speculum_editor_document editor/view/Selection.hpp missing)
speculum_include_probe(layers_document_sees_no_ui speculum_editor_document editor/ui/MainWindow.hpp missing)
speculum_include_probe(layers_view_sees_own_headers speculum_editor_view editor/view/Selection.hpp found)
speculum_include_probe(layers_view_sees_no_ui speculum_editor_view editor/ui/Viewport.hpp missing)
speculum_include_probe(layers_view_sees_no_editing speculum_editor_view editor/document/Commands.hpp missing)
speculum_include_probe(layers_app_sees_no_editor speculum_app editor/ui/Editor.hpp missing)
speculum_include_probe(layers_accuracy_sees_no_scene speculum_accuracy scene/model/Scene.hpp missing)
speculum_include_probe(layers_plan_sees_no_gl speculum_render_plan render/gl/Objects.hpp missing)

# Test builds keep assertions on (no NDEBUG).
speculum_add_test(test_layers_assertions TIER unit SOURCES ${layers_dir}/test_assertions.cpp)
