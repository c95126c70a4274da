speculum_add_test(test_gl_envmap TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/GlslRunner.cpp ${CMAKE_CURRENT_LIST_DIR}/test_glsl_mapping.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_capture.cpp ${CMAKE_CURRENT_LIST_DIR}/test_prefilter.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
