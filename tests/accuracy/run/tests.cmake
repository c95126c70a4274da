# accuracy/run: the parts of a bench run that render and trace (the white furnace). Gl tier.
speculum_add_test(AccuracyRunGLTest TIER gl
    SOURCES FurnaceGLTest.cpp
    LIBS speculum_accuracy_run)
