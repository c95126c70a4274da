# render/renderer: whole frames (camera-relative drawing, missing textures, resizing, supersampling,
# reuse of unchanged maps), resolution scale, the camera's colour buffer, the frame report, the GPU's
# size limits, stills in tiles, the editor's guide lines. Gl tier; the demo scenes come through the scene libraries.
speculum_add_test(RenderRendererGLTest TIER gl
    SOURCES RendererGLTest.cpp RendererResolutionScaleGLTest.cpp RendererCameraBufferGLTest.cpp
            RendererFrameReportGLTest.cpp RendererGpuLimitsGLTest.cpp StillRendererGLTest.cpp
            RendererGuidesGLTest.cpp
    LIBS speculum_render_renderer speculum_scene_project speculum_scene_evaluate)
# 1000-frame soak runs on the demo scenes: slow, left out of the default test run (ctest -L slow).
speculum_add_test(RenderRendererSlowGLTest TIER gl LABELS slow
    SOURCES RendererSoakSlowGLTest.cpp
    LIBS speculum_render_renderer speculum_scene_project speculum_scene_evaluate)
