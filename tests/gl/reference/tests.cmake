# The reference tracer against the rasterizer on the demo scenes: gl tier (headless EGL).
speculum_add_test(test_gl_reference TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_agreement.cpp
    LIBS speculum_render speculum_document)
# `speculum render --reference` as a user runs it (the binary needs EGL for its other commands: gl tier).
speculum_add_test(test_reference_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_cli.cpp
    LIBS PkgConfig::OIIO)
# The curved reflector's error against the tracer: falls with map resolution, and with parallax correction.
speculum_add_test(test_gl_reference_envmap TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_envmap.cpp
    LIBS speculum_render)
