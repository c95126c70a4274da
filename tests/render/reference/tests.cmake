# The exact reference tracer (Embree) and the error metrics: unit tier, no GL.
speculum_add_test(test_render_reference TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_tracer.cpp ${CMAKE_CURRENT_LIST_DIR}/test_tracer_robustness.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_metrics.cpp ${CMAKE_CURRENT_LIST_DIR}/test_material_tracing.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_glossy_tracer.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio PkgConfig::OIIO)
