# The editor's view state without widgets: the selection, the view's own camera, the animation clock.
# Unit tier: no GL, no display (a QCoreApplication for queued connections).
find_package(Qt6 REQUIRED COMPONENTS Test) # QSignalSpy
speculum_add_test(test_editor_view TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_selection.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_view_camera.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_view_presets.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_adaptive_resolution.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_animation_clock.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_animation_loop.cpp
            ${CMAKE_CURRENT_LIST_DIR}/view_main.cpp
    LIBS speculum_editor_view speculum_editor_document Qt6::Test)
