speculum_add_test(test_editor_reliability TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_save_failures.cpp ${CMAKE_CURRENT_LIST_DIR}/test_round_trip.cpp
    LIBS speculum_editor_document speculum_scene_export)
