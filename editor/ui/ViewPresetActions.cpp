#include "editor/ui/ViewPresetActions.hpp"

#include "editor/ui/KeypadKeys.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/ViewPresets.hpp"

#include <QAction>
#include <QMenu>
#include <QWidget>

namespace speculum::ui {

namespace {

struct PresetEntry {
    view::ViewPreset preset;
    const char* name;
    const char* text;
    KeypadKey key;
    bool ctrl;
};

// Blender's keypad steps, 15° each: 4 and 6 orbit the camera to its left and right about the vertical (the
// scene turns the other way), 8 and 2 up over the target and down under it; + and − zoom a wheel notch.
constexpr double kOrbitStepDegrees = 15.0;

void bindKeypadSteps(KeypadKeys& keypad, Viewport& viewport) {
    Viewport* v = &viewport;
    keypad.bind(KeypadKey::Digit4, false, [v] { v->orbitView(kOrbitStepDegrees, 0.0); });
    keypad.bind(KeypadKey::Digit6, false, [v] { v->orbitView(-kOrbitStepDegrees, 0.0); });
    keypad.bind(KeypadKey::Digit8, false, [v] { v->orbitView(0.0, kOrbitStepDegrees); });
    keypad.bind(KeypadKey::Digit2, false, [v] { v->orbitView(0.0, -kOrbitStepDegrees); });
    keypad.bind(KeypadKey::Plus, false, [v] { v->zoomView(1.0); });
    keypad.bind(KeypadKey::Minus, false, [v] { v->zoomView(-1.0); });
    keypad.bind(KeypadKey::Digit0, false, [v] { v->resetView(); });
    keypad.bind(KeypadKey::Decimal, false, [v] { v->frameSelected(); });
}

} // namespace

void addViewPresetActions(QWidget& window, QMenu* menu, Viewport& viewport) {
    QMenu* presets = menu ? menu->addMenu(QObject::tr("View &Presets")) : nullptr;
    static const PresetEntry entries[] = {
        {view::ViewPreset::Front, "viewFront", "&Front", KeypadKey::Digit1, false},
        {view::ViewPreset::Back, "viewBack", "&Back", KeypadKey::Digit1, true},
        {view::ViewPreset::Right, "viewRight", "&Right", KeypadKey::Digit3, false},
        {view::ViewPreset::Left, "viewLeft", "&Left", KeypadKey::Digit3, true},
        {view::ViewPreset::Top, "viewTop", "&Top", KeypadKey::Digit7, false},
        {view::ViewPreset::Bottom, "viewBottom", "B&ottom", KeypadKey::Digit7, true},
    };
    auto* keypad = new KeypadKeys(window);
    for (const PresetEntry& e : entries) {
        auto* action = new QAction(QObject::tr(e.text), &window);
        action->setObjectName(QString::fromLatin1(e.name));
        // The key the menu shows; the keypad filter, not Qt's shortcut map, sees that it works (KeypadKeys).
        const int digit = Qt::Key_0 + static_cast<int>(e.key);
        action->setShortcut(
            QKeySequence(Qt::KeypadModifier | (e.ctrl ? int(Qt::ControlModifier) : 0) | digit));
        action->setShortcutContext(Qt::WindowShortcut);
        keypad->bind(e.key, e.ctrl, [action] { action->trigger(); });
        const view::ViewPreset preset = e.preset;
        QObject::connect(action, &QAction::triggered, &viewport, [&viewport, preset] {
            viewport.setViewCamera(view::presetView(viewport.viewCamera(), preset));
        });
        window.addAction(action);
        if (presets) {
            presets->addAction(action);
        }
    }

    bindKeypadSteps(*keypad, viewport);

    auto* guides = new QAction(QObject::tr("Show &Guides"), &window);
    guides->setObjectName(QStringLiteral("viewShowGuides"));
    guides->setCheckable(true);
    guides->setChecked(viewport.guidesVisible());
    QObject::connect(guides, &QAction::toggled, &viewport, &Viewport::setGuidesVisible);
    window.addAction(guides);
    if (menu) {
        menu->addAction(guides);
    }

    auto* sources = new QAction(QObject::tr("Show Screen-Space &Sources"), &window);
    sources->setObjectName(QStringLiteral("viewShowScreenSpaceSources"));
    sources->setCheckable(true);
    sources->setChecked(viewport.screenSpaceSourcesVisible());
    sources->setStatusTip(
        QObject::tr("Colour each screen-space mirror's pixels by where their reflection comes "
                    "from: green, the image; blue, the reflector's map; red, the background"));
    QObject::connect(sources, &QAction::toggled, &viewport, &Viewport::setScreenSpaceSourcesVisible);
    window.addAction(sources);
    if (menu) {
        menu->addAction(sources);
    }
}

} // namespace speculum::ui
