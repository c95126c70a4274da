# scene/model: what is animated in a scene. Unit tier.
speculum_add_test(SceneModelTest TIER unit
    SOURCES SceneAnimationTest.cpp
    LIBS speculum_scene_model speculum_editor_view)
