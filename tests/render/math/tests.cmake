# render/math: mirror planes and matrices, oblique projections, GGX. Unit tier.
speculum_add_test(RenderMathTest TIER unit
    SOURCES GgxTest.cpp MirrorTest.cpp
    LIBS speculum_render_math speculum_render_plan)
