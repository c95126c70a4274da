#pragma once

#include <QIcon>
#include <QString>

namespace speculum::ui {

// The application id: the desktop entry's, the icon's and the AppStream metainfo's name
// (resources/desktop/), which Wayland compositors match windows by.
inline constexpr const char* kApplicationId = "org.speculum.Speculum";

// The folder of the example projects: installed, <prefix>/share/speculum/scenes beside the executable's
// bin/; run from a build folder, the source tree's resources/scenes. Empty when neither exists.
QString examplesFolder();

// The icon of the installed hicolor theme, or the same picture drawn here when it is not installed (run
// from a build folder; Qt here has no SVG icon engine to read the file itself).
QIcon applicationIcon();

} // namespace speculum::ui
