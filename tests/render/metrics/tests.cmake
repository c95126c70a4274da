# render/metrics: error metrics between two images. Unit tier.
speculum_add_test(RenderMetricsTest TIER unit
    SOURCES ErrorMetricsTest.cpp PerceptualMetricsTest.cpp
    LIBS speculum_render_metrics speculum_render_imageio speculum_render_reference)
