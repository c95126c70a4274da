#pragma once

class QMenu;
class QWidget;

namespace speculum::ui {

class Viewport;

// View ▸ Front / Back / Right / Left / Top / Bottom on the numpad as in Blender (1 front, 3 right, 7 top;
// Ctrl+numpad the opposite side), and View ▸ Show Guides (grid, camera wireframe, pivot, axis gizmo). The
// rest of Blender's keypad comes with them: 4 / 6 and 8 / 2 orbit 15°, + and − zoom, 0 goes back to the
// scene camera, the decimal point frames the selection. The keypad belongs to `window`, in either NumLock
// state (KeypadKeys), whichever of its widgets has focus (a text field that takes digits keeps it).
// Actions are named "viewFront", "viewBack", ..., "viewShowGuides"; `menu` may be null.
void addViewPresetActions(QWidget& window, QMenu* menu, Viewport& viewport);

} // namespace speculum::ui
