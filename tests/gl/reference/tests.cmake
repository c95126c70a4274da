# The reference tracer against the rasterizer on the demo scenes: gl tier (headless EGL).
speculum_add_test(test_gl_reference TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_agreement.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio speculum_editor_document speculum_scene_export)
# `speculum render --reference` as a user runs it (the binary needs EGL for its other commands: gl tier).
speculum_add_test(test_reference_cli TIER gl USES_CLI
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_cli.cpp
    LIBS PkgConfig::OIIO)
# The curved reflector's error against the tracer: falls with map resolution, and with parallax correction.
speculum_add_test(test_gl_reference_envmap TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reference_envmap.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
# Rough planar mirrors: roughness 0 is the sharp image, the Footprint filter's error against the tracer
# falls with its taps and beats the Mip filter, nothing non-finite at the extremes, blur grows with distance.
speculum_add_test(test_gl_glossy_agreement TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_glossy_agreement.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
