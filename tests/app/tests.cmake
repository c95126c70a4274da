# Runs the real speculum binary on an EGL surfaceless context (no display), hence the gl tier.
speculum_add_test(test_app_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_cli.cpp
    LIBS Qt6::Core PkgConfig::OIIO speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
# The sweep's planning and analysis without GL: tests/accuracy.
# `speculum bench --quick` on tiny scenes made by the test (the binary renders on EGL: gl tier).
speculum_add_test(test_bench_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_bench_cli.cpp
    LIBS Qt6::Core PkgConfig::OIIO)
# The same on the chrome and mirrors demos at the quick size: tens of seconds each, so labelled slow.
speculum_add_test(test_bench_demos TIER gl USES_CLI LABELS slow
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_bench_demos.cpp
    LIBS Qt6::Core)
# Outputs onto a "full disk" (`ulimit -f`): render in each format, reference EXR, bench, export (gl tier).
speculum_add_test(test_cli_write_failures TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_cli_write_failures.cpp
    LIBS Qt6::Core)
# `speculum time`: frame-time statistics, the camera buffer, reuse in static frames, bad input (gl tier).
speculum_add_test(test_time_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_time_cli.cpp
    LIBS Qt6::Core)
