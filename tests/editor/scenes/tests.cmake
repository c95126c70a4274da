speculum_add_test(test_editor_demo_scenes TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_demo_scenes.cpp
    LIBS speculum_editor_document speculum_scene_export)
