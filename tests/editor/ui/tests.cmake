# editor/ui without a widget: the handle-drag state machine (plain mouse positions and the handles as the
# view camera sets them up), how a handle drag carries over to the other selected nodes, and the levels an
# exact comparison refines through. Unit tier, no display, although they live in the UI library.
speculum_add_test(EditorUiTest TIER unit SOURCES HandleDragTest.cpp GizmoTest.cpp ComparisonLevelsTest.cpp
    LIBS speculum_editor_ui)

# Gui tier: each program runs as one CTest entry under scripts/with-display (Xvfb with GLX on llvmpipe
# when there is no display), with a QApplication and a temporary XDG home of its own. The programs have
# their own main() (support/gui_main.cpp), which takes precedence over gtest_main's.
find_package(Qt6 REQUIRED COMPONENTS Test) # QTest mouse and key events
set(gui_main ${SPECULUM_TEST_SUPPORT}/gui_main.cpp)
# The main window on the reference project: the viewport draws it, edits mark the title as modified and
# undo clears it, a broken file leaves the open document alone; two editors on one file ask before the
# second save.
speculum_add_test(MainWindowGuiTest TIER gui SOURCES MainWindowGuiTest.cpp MainWindowDiskChangesGuiTest.cpp ${gui_main}
    LIBS speculum_editor_ui)
# The editor as a user drives it: the Add menu and the inspector, undo and redo, save and reopen, the
# scene tree, click-to-select and handle drags, multiple selection.
speculum_add_test(MainWindowWorkflowGuiTest TIER gui
    SOURCES MainWindowWorkflowGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# What the editor shows and writes: the viewport after an inspector edit, the render passes panel,
# Export Still. Runs the real speculum binary to compare Export Still with `speculum render`.
speculum_add_test(MainWindowOutputGuiTest TIER gui USES_CLI
    SOURCES MainWindowOutputGuiTest.cpp ${gui_main} LIBS speculum_editor_ui PkgConfig::OIIO)
# Shortcuts from the scene tree that leave text fields their keys, the new document's floor, sun and
# raised camera, new objects and duplicates placed beside each other.
speculum_add_test(MainWindowInputGuiTest TIER gui
    SOURCES MainWindowInputGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# The numeric keypad from a real X keyboard (xdotool's XTEST), NumLock on and off: views, orbit and zoom
# steps, and the keys it shares with Home and Delete doing neither.
speculum_add_test(KeypadKeysGuiTest TIER gui SOURCES KeypadKeysGuiTest.cpp ${gui_main} LIBS speculum_editor_ui)
# The keyboard after a field on a real X keyboard: Enter commits and hands it back, Esc reverts.
speculum_add_test(FieldKeysGuiTest TIER gui SOURCES FieldKeysGuiTest.cpp ${gui_main} LIBS speculum_editor_ui)
# Import and Open of hostile files (FIFOs, devices, DAG and deep node graphs, duplicate keys, overflowing
# values) show an error, keep the event loop running and leave the open document as it was.
speculum_add_test(MainWindowHostileFilesGuiTest TIER gui
    SOURCES MainWindowHostileFilesGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# Kills a real editor process (this program started again) after its autosave, then recovers in a new
# one; has its own main() for the child's side and a temporary XDG home for both.
speculum_add_test(EditorRecoveryGuiTest TIER gui SOURCES EditorRecoveryGuiTest.cpp LIBS speculum_editor_ui)
# The Accuracy dock: compare with the exact tracer, the chart of a bench run.
speculum_add_test(AccuracyPanelGuiTest TIER gui
    SOURCES AccuracyPanelGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# Model import in the editor: worker thread, progress and cancel, one undo step, placement, pick hierarchy;
# the viewport's warnings about the model files it reads on workers.
speculum_add_test(ModelImportJobGuiTest TIER gui
    SOURCES ModelImportJobGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test assimp::assimp)
# Esc during a handle drag restores the node and leaves no undo step and a clean document.
speculum_add_test(HandleDragGuiTest TIER gui
    SOURCES HandleDragGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# The viewport draws only when what it shows changes: no frame while nothing changes; edits, time,
# navigation and playback draw (and stop).
speculum_add_test(ViewportRedrawGuiTest TIER gui
    SOURCES ViewportRedrawGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# The timeline's time slider, and the clock starting over on Open and New.
speculum_add_test(TimeSliderGuiTest TIER gui
    SOURCES TimeSliderGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# The inspector: the wheel over unfocused fields, tiny values, the parallax proxy; also Export Still's
# exact reference with cancel, and the Accuracy panel's explanation, hover labels and reset.
speculum_add_test(InspectorGuiTest TIER gui
    SOURCES InspectorGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# The viewport: adaptive resolution while navigating and dragging, the view presets and guides actions,
# the vertical orbit's direction, a saved view placed after a reset.
speculum_add_test(ViewportNavigationGuiTest TIER gui
    SOURCES ViewportNavigationGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# View ▸ Inspect Pixel: a click explains the pixel in the Pixel Inspector and draws its path in the view.
speculum_add_test(PixelInspectorGuiTest TIER gui
    SOURCES PixelInspectorGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
# File ▸ Export Animation: the dialog's defaults and remembered choices, a PNG sequence through the menu
# and a GIF clip of the teapot demo while the event loop runs, Cancel (the sequence's finished frames kept,
# no clip), exact frames, closing the editor mid-export; the document unchanged throughout.
speculum_add_test(ExportAnimationGuiTest TIER gui
    SOURCES ExportAnimationGuiTest.cpp ${gui_main} LIBS speculum_editor_ui Qt6::Test)
