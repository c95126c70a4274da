# scene/import: model files through Assimp (real files from Debian's assimp-testmodels, broken and hostile
# files written by the tests), their parts, materials and node trees, the read in a child process, and
# every file of the corpus in a child process of its own. Unit tier, no GL. Links Assimp directly to
# cross-check the flattening against its own PreTransformVertices step. The forking tests need no other
# thread running: ctest runs each test in a process of its own.
speculum_add_test(SceneImportTest TIER unit
    SOURCES ModelImportTest.cpp ModelImportPartsTest.cpp ModelImportHostileTest.cpp ModelImportProcessTest.cpp
            ModelImportCorpusTest.cpp
    LIBS speculum_scene_import speculum_render_imageio assimp::assimp)
# A glTF quad read through the model import shows its texture upright in both renderers. Gl tier.
speculum_add_test(SceneImportGLTest TIER gl
    SOURCES ModelImportGLTest.cpp
    LIBS speculum_scene_import speculum_render_renderer speculum_render_reference speculum_render_metrics
         speculum_render_imageio PkgConfig::OIIO)
