# 1000-frame soak runs: slow, left out of the default test run (ctest -L slow runs them).
speculum_add_test(test_gl_soak TIER gl LABELS slow
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_soak.cpp
    LIBS speculum_editor_document speculum_scene_export speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
