# render/inspect: one pixel explained, the tracer's recorded path beside the rasterizer's recipe (probes
# read back after each pass), the map lookup's texel and seams, and the hard cases (the depth limit, far
# from the origin). Gl tier.
speculum_add_test(RenderInspectGLTest TIER gl
    SOURCES PixelExplanationGLTest.cpp
    LIBS speculum_render_inspect speculum_render_renderer speculum_render_reference)
