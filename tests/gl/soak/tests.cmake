# 1000-frame soak runs: slow, left out of the default test run (ctest -L slow runs them).
speculum_add_test(test_gl_soak TIER gl LABELS slow
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_soak.cpp
    LIBS speculum_document speculum_render)
