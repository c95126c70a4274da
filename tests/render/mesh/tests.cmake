# render/mesh: built-in meshes (teapot, primitives), bounds, mesh repair and simplification. Unit tier.
speculum_add_test(RenderMeshTest TIER unit
    SOURCES MeshRepairTest.cpp PrimitivesTest.cpp SimplifyTest.cpp TeapotTest.cpp
    LIBS speculum_render_mesh)
