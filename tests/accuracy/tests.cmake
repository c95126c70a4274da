# accuracy/: the sweep's planning and analysis, its results files and its output folder. Unit tier, no GL.
speculum_add_test(AccuracyTest TIER unit
    SOURCES SweepTest.cpp ResultsTest.cpp StagedOutputTest.cpp ShardMergeTest.cpp
    LIBS speculum_accuracy Qt6::Core)
