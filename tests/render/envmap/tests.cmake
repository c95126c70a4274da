speculum_add_test(test_render_envmap TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_mapping.cpp ${CMAKE_CURRENT_LIST_DIR}/test_seams.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_solid_angle.cpp ${CMAKE_CURRENT_LIST_DIR}/test_capture_math.cpp
    LIBS speculum_render_plan)
