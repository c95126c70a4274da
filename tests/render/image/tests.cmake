# render/image: colour conversions of plain pixel buffers. Unit tier.
speculum_add_test(RenderImageTest TIER unit SOURCES ColorSpaceTest.cpp LIBS speculum_render_image)
