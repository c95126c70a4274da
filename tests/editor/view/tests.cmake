# editor/view: the editor's view state without widgets: the selection, the view's own camera and presets,
# adaptive resolution, the animation clock. Unit tier: no GL, no display (a QCoreApplication for queued
# connections, view_main.cpp).
find_package(Qt6 REQUIRED COMPONENTS Test) # QSignalSpy
speculum_add_test(EditorViewTest TIER unit
    SOURCES AdaptiveResolutionTest.cpp AnimationClockTest.cpp SelectionTest.cpp ViewCameraTest.cpp
            ViewPresetsTest.cpp view_main.cpp
    LIBS speculum_editor_view speculum_editor_document Qt6::Test)
