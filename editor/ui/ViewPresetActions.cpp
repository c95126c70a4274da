#include "editor/ui/ViewPresetActions.hpp"

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
    int key;
    bool ctrl;
};

} // namespace

void addViewPresetActions(QWidget& window, QMenu* menu, Viewport& viewport) {
    QMenu* presets = menu ? menu->addMenu(QObject::tr("View &Presets")) : nullptr;
    static const PresetEntry entries[] = {
        {view::ViewPreset::Front, "viewFront", "&Front", Qt::Key_1, false},
        {view::ViewPreset::Back, "viewBack", "&Back", Qt::Key_1, true},
        {view::ViewPreset::Right, "viewRight", "&Right", Qt::Key_3, false},
        {view::ViewPreset::Left, "viewLeft", "&Left", Qt::Key_3, true},
        {view::ViewPreset::Top, "viewTop", "&Top", Qt::Key_7, false},
        {view::ViewPreset::Bottom, "viewBottom", "B&ottom", Qt::Key_7, true},
    };
    for (const PresetEntry& e : entries) {
        auto* action = new QAction(QObject::tr(e.text), &window);
        action->setObjectName(QString::fromLatin1(e.name));
        const int modifiers = Qt::KeypadModifier | (e.ctrl ? int(Qt::ControlModifier) : 0);
        action->setShortcut(QKeySequence(modifiers | e.key));
        action->setShortcutContext(Qt::WindowShortcut);
        const view::ViewPreset preset = e.preset;
        QObject::connect(action, &QAction::triggered, &viewport, [&viewport, preset] {
            viewport.setViewCamera(view::presetView(viewport.viewCamera(), preset));
        });
        window.addAction(action);
        if (presets) {
            presets->addAction(action);
        }
    }

    auto* guides = new QAction(QObject::tr("Show &Guides"), &window);
    guides->setObjectName(QStringLiteral("viewShowGuides"));
    guides->setCheckable(true);
    guides->setChecked(viewport.guidesVisible());
    QObject::connect(guides, &QAction::toggled, &viewport, &Viewport::setGuidesVisible);
    window.addAction(guides);
    if (menu) {
        menu->addAction(guides);
    }
}

} // namespace speculum::ui
