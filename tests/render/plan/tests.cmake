speculum_add_test(test_render_plan TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_planner.cpp ${CMAKE_CURRENT_LIST_DIR}/test_mirror_planner.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_reflector_planner.cpp ${CMAKE_CURRENT_LIST_DIR}/test_tile_plan.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_gpu_limits.cpp ${CMAKE_CURRENT_LIST_DIR}/test_signatures.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_envmap_mirrors.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_reflected_detail.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_prefilter_planner.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
# What the planner declares for the executor (PassWrites, ShadowPlan), against the core library alone: it
# builds and runs while the GL libraries change.
speculum_add_test(test_render_plan_writes TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_pass_writes.cpp
    LIBS speculum_render_plan)
