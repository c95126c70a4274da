# Image IO (OpenImageIO) and the procedural marble: unit tier, no GL.
speculum_add_test(test_render_image TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_color_space.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_image_writer.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_texture_loader.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_marble.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_write_failures.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio speculum_tools_marble PkgConfig::OIIO)
