# render/reference: the exact reference tracer (Embree): geometry, robustness, glossy sampling,
# materials. Unit tier.
speculum_add_test(RenderReferenceTest TIER unit
    SOURCES TracerTest.cpp TracerRobustnessTest.cpp TracerGlossyTest.cpp TracerMaterialsTest.cpp
    LIBS speculum_render_reference speculum_render_imageio PkgConfig::OIIO)
# The tracer against the rasterizer: the demo scenes, rough mirrors, materials, the curved reflector's
# error, values at the scene limits. Gl tier.
speculum_add_test(RenderReferenceGLTest TIER gl
    SOURCES DemoScenesAgreementGLTest.cpp GlossyAgreementGLTest.cpp MaterialAgreementGLTest.cpp
            ReflectorAgreementGLTest.cpp SceneLimitsAgreementGLTest.cpp MirrorDepthLimitAgreementGLTest.cpp
            GlossyFurnaceGLTest.cpp ReflectorBouncesAgreementGLTest.cpp
    LIBS speculum_render_reference speculum_render_renderer speculum_render_metrics speculum_render_imageio
         PkgConfig::OIIO speculum_scene_project speculum_scene_evaluate speculum_accuracy_run)
