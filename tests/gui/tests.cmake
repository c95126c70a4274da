# GUI tier: each binary runs as one CTest entry under scripts/with-display (Xvfb with GLX on llvmpipe
# when there is no display). The tests have their own main() (they need a QApplication), which takes
# precedence over gtest_main's.
speculum_add_test(test_main_window TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_main_window.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui)
find_package(Qt6 REQUIRED COMPONENTS Test) # QTest mouse events
speculum_add_test(test_editor_workflow TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_editor_workflow.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# Runs the real speculum binary to compare Export Still with `speculum render`.
speculum_add_test(test_editor_output TIER gui USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_editor_output.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui)
# Kills a real editor process (this binary started again) after its autosave, then recovers in a new
# one; has its own main() for the child's side and a temporary XDG home for both.
speculum_add_test(test_crash_recovery TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_crash_recovery.cpp
    LIBS speculum_editor_ui)
# The Accuracy dock: compare with the exact tracer, the chart of a bench run.
speculum_add_test(test_accuracy_panel TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_accuracy_panel.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# How a handle drag carries over to the other selected nodes (the Selection itself: tests/editor/view).
speculum_add_test(test_follow_drag TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_follow_drag.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui)
# Model import in the editor: worker thread, progress and cancel, one undo step, placement, pick hierarchy.
speculum_add_test(test_model_import_gui TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_model_import.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test assimp::assimp)
# issue 14: Import and Open of hostile files (FIFOs, devices, DAG and deep node graphs, duplicate keys,
# overflowing values) show an error, keep the event loop running and leave the open document as it was.
speculum_add_test(test_hostile_files_gui TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_hostile_files.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 15: Esc during a handle drag restores the node and leaves no undo step and a clean document.
speculum_add_test(test_handle_cancel TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_handle_cancel.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 16: no frame is drawn while nothing changes; edits, time, navigation and playback draw (and stop).
speculum_add_test(test_idle_redraw TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_idle_redraw.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 16: the timeline's time slider, and the clock starting over on Open and New.
speculum_add_test(test_time_slider TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_time_slider.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 16 (items 2, 4, 6): the wheel over unfocused fields, tiny values, the parallax proxy, Export
# Still's exact reference with cancel, and the Accuracy panel's explanation, hover labels and reset.
speculum_add_test(test_inspector_input TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_inspector_input.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 16 (items 3 and 7, the viewport): adaptive resolution while navigating and dragging, the view
# presets and guides actions, the vertical orbit's direction, a saved view placed after a reset.
speculum_add_test(test_viewport_navigation TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_viewport_navigation.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
# issue 16 (items 2 and 3, the window): shortcuts from the scene tree that leave text fields their keys,
# the new document's floor, sun and raised camera, new objects and duplicates placed beside each other.
speculum_add_test(test_editor_input TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_editor_input.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_editor_ui Qt6::Test)
