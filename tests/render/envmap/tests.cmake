# render/envmap: environment-map mappings, layouts, seams, CPU maps and solid angles. Unit tier.
speculum_add_test(RenderEnvmapTest TIER unit
    SOURCES CaptureMathTest.cpp MappingTest.cpp CpuMapSeamsTest.cpp SolidAngleTest.cpp
    LIBS speculum_render_envmap)
# The GLSL twins of the mappings, compared with the C++ ones on a headless context. Gl tier.
speculum_add_test(RenderEnvmapGLTest TIER gl
    SOURCES MappingGLTest.cpp ${SPECULUM_TEST_SUPPORT}/GlslRunner.cpp
    LIBS speculum_render_envmap speculum_render_passes speculum_render_renderer)
