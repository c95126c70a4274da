# The scene document: model, project files, snapshot, undo commands. Unit tier, no GL.
speculum_add_test(test_editor_document TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_project_file.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_project_errors.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_project_materials.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_snapshot.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_commands.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_sweep_results.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_project_limits.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_printable.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_limits_agree.cpp
    LIBS speculum_editor_document speculum_scene_export)
