# accuracy/run: the parts of a bench run that render and trace. The white furnace: Gl tier.
speculum_add_test(AccuracyRunGLTest TIER gl
    SOURCES FurnaceGLTest.cpp
    LIBS speculum_accuracy_run)
# The reference's convergence (the tracer only): Unit tier.
speculum_add_test(AccuracyRunTest TIER unit
    SOURCES ConvergenceTest.cpp
    LIBS speculum_accuracy_run)
