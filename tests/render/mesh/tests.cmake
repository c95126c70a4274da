# Built-in meshes (teapot, primitives), bounds and mesh repair: unit tier, no GL.
speculum_add_test(test_render_mesh TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_teapot.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_primitives.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_mesh_repair.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_simplify.cpp
    LIBS speculum_render_plan)
