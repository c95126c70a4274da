#pragma once

class QMenu;
class QWidget;

namespace speculum::ui {

class Viewport;

// View ▸ Front / Back / Right / Left / Top / Bottom on the numpad as in Blender (1 front, 3 right, 7 top;
// Ctrl+numpad the opposite side), and View ▸ Show Guides (grid, camera wireframe, pivot, axis gizmo). The
// shortcuts belong to `window`, so they work whichever of its widgets has focus (a text field that takes
// digits keeps them). Actions are named "viewFront", "viewBack", ..., "viewShowGuides"; `menu` may be null.
void addViewPresetActions(QWidget& window, QMenu* menu, Viewport& viewport);

} // namespace speculum::ui
