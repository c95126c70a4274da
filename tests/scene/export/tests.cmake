# scene/export: glTF export, checked by reading it back through Assimp. Unit tier.
speculum_add_test(SceneExportTest TIER unit
    SOURCES GltfExportTest.cpp
    LIBS speculum_scene_export speculum_scene_project speculum_render_imageio assimp::assimp PkgConfig::OIIO
         speculum_editor_document)
