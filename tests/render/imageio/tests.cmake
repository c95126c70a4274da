# render/imageio: image files written and read through OpenImageIO, in each format, onto a full disk and
# onto FIFOs and devices. Unit tier.
speculum_add_test(RenderImageioTest TIER unit
    SOURCES ImageWriterTest.cpp TextureLoaderTest.cpp ImageWriterFailuresTest.cpp
    LIBS speculum_render_imageio PkgConfig::OIIO ZLIB::ZLIB)
