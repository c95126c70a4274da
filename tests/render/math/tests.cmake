speculum_add_test(test_render_math TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_mirror_math.cpp ${CMAKE_CURRENT_LIST_DIR}/test_ggx.cpp
    LIBS speculum_render_plan)
