# render/plan: which passes a frame runs and why, what each writes, signatures, tiles, GPU limits. Unit
# tier, no GL.
speculum_add_test(RenderPlanTest TIER unit
    SOURCES PlannerTest.cpp PlannerReflectedDetailTest.cpp PlannerSignaturesTest.cpp MirrorPlannerTest.cpp
            MirrorPlannerEnvmapTest.cpp ReflectorPlannerTest.cpp ReflectorPlannerPrefilterTest.cpp
            ReflectorBouncesPlannerTest.cpp
            PassWritesTest.cpp TilePlanTest.cpp GpuLimitsTest.cpp PlanReasonTest.cpp
            PlannerPreviewTest.cpp PlannerMapCostTest.cpp
    LIBS speculum_render_plan speculum_render_imageio speculum_render_gl)
