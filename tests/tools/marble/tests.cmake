# tools/marble: the procedural marble texture. Unit tier.
speculum_add_test(ToolsMarbleTest TIER unit SOURCES MarbleTest.cpp LIBS speculum_tools_marble speculum_render_imageio)
