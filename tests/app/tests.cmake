# app/: the real speculum binary run as a user runs it (render, explain, export, render --reference,
# bench, time, render --frames and join, clips read back through libavformat; outputs onto a "full
# disk"), and bench --shard and --merge through bench::run. It renders
# on an EGL surfaceless context (no display), hence the gl tier.
speculum_add_test(AppGLTest TIER gl USES_CLI
    SOURCES CliGLTest.cpp CliReferenceGLTest.cpp CliWriteFailuresGLTest.cpp CliTexturesGLTest.cpp
            CliSignalsGLTest.cpp BenchCommandGLTest.cpp TimeCommandGLTest.cpp CliReflectorsGLTest.cpp
            CliPixelGLTest.cpp BenchShardsGLTest.cpp CliAnimationGLTest.cpp
    LIBS Qt6::Core PkgConfig::OIIO ZLIB::ZLIB speculum_render_renderer speculum_app speculum_render_video)
# `speculum bench` on the chrome and mirrors demos at the quick size: tens of seconds each, so slow.
speculum_add_test(AppSlowGLTest TIER gl USES_CLI LABELS slow
    SOURCES BenchCommandDemosSlowGLTest.cpp
    LIBS Qt6::Core)
