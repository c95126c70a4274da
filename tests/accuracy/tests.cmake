# The accuracy sweep's planning and analysis, its results files and its output folder, without GL.
speculum_add_test(test_accuracy TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_sweep.cpp ${CMAKE_CURRENT_LIST_DIR}/test_staging.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_results.cpp
    LIBS speculum_accuracy Qt6::Core)
