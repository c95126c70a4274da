# scene/evaluate: the scene at a time as the renderer's frame input (the demo scenes too), and picking.
# Unit tier.
speculum_add_test(SceneEvaluateTest TIER unit
    SOURCES SnapshotTest.cpp SnapshotDemoScenesTest.cpp PickingTest.cpp
    LIBS speculum_scene_evaluate speculum_scene_project speculum_editor_document)
