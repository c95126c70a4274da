# Runs the real speculum binary on an EGL surfaceless context (no display), hence the gl tier.
speculum_add_test(test_app_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_cli.cpp
    LIBS Qt6::Core PkgConfig::OIIO speculum_render)
