# render/passes: the CPU side of the passes (mesh subdivision for the direct environment fill). Unit tier.
speculum_add_test(RenderPassesTest TIER unit SOURCES WarpMeshesTest.cpp LIBS speculum_render_passes)
# The pass executors on a headless context: shadow maps, mirrors and their occlusion, lighting variants,
# the main pass's back faces and materials, reflected detail, the reflector, environment capture and its
# fill, GGX pre-filtering, the convolved chain of a rough mirror, GPU allocations that do not fit,
# screen-space mirrors. Gl tier.
speculum_add_test(RenderPassesGLTest TIER gl
    SOURCES ShadowMapsGLTest.cpp MirrorPassesGLTest.cpp MirrorOcclusionGLTest.cpp LightingVariantGLTest.cpp
            MainPassBackFaceCullingGLTest.cpp MainPassMaterialsGLTest.cpp ReflectedDetailGLTest.cpp
            ReflectorPassGLTest.cpp EnvironmentCaptureGLTest.cpp EnvironmentCaptureFillGLTest.cpp
            GgxPrefilterGLTest.cpp GpuAllocationGLTest.cpp MipConvolveGLTest.cpp ScreenSpaceGLTest.cpp
            ${SPECULUM_TEST_SUPPORT}/GlslRunner.cpp
    LIBS speculum_render_passes speculum_render_renderer speculum_render_metrics speculum_render_imageio
         PkgConfig::OIIO ZLIB::ZLIB)
# Real 8192 reflectors drawn at the size the driver holds (seconds each on llvmpipe): slow.
speculum_add_test(RenderPassesSlowGLTest TIER gl LABELS slow
    SOURCES GpuAllocationGLTest.cpp
    LIBS speculum_render_passes speculum_render_renderer)
target_compile_definitions(RenderPassesSlowGLTest PRIVATE SPECULUM_SLOW_ALLOCATION_TESTS=1)
