#pragma once

#include <string>

namespace speculum::ui {

// Sets the default OpenGL surface format, creates the QApplication and the main window, opens
// `projectPath` if not empty (or restores the recovery file `recoveryPath`: `speculum --recover FILE`, how
// one editor opens another's unsaved document in a window of its own), and runs the event loop. Returns the
// exit status.
//
// With the environment variable SPECULUM_SCREENSHOT=OUT.png the editor instead shows the window, waits
// for the viewport's first frames, saves a picture of the whole window to OUT.png and exits (0 on
// success). SPECULUM_SCREENSHOT_TIME=T freezes the animation at T seconds (default 0) so the picture
// is reproducible; SPECULUM_SCREENSHOT_SIZE=WxH sets the window size (default 1280x800).
int runEditor(int& argc, char** argv, const std::string& projectPath, const std::string& recoveryPath = {});

// The surface format the viewport needs (OpenGL 3.3 core, depth 24, stencil 8), made the default.
// Must run before the QApplication is constructed; runEditor does it, GUI tests call it themselves.
void installDefaultSurfaceFormat();

} // namespace speculum::ui
