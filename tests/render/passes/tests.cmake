# The CPU side of render passes (mesh subdivision for the direct environment fill): unit tier, no GL.
speculum_add_test(test_render_passes TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_warp_meshes.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
