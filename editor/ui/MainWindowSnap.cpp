// The main window's snapping: View ▸ Snap While Dragging and Snap Steps…, remembered between sessions.
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/SnapSettings.hpp"
#include "editor/ui/Viewport.hpp"

#include <QAction>
#include <QMenu>
#include <QStatusBar>

namespace speculum::ui {

void MainWindow::createSnapActions(QMenu* view) {
    m_snapAlwaysAction = makeAction(view, QStringLiteral("actionSnapAlways"), tr("S&nap While Dragging"));
    m_snapAlwaysAction->setCheckable(true);
    m_snapAlwaysAction->setStatusTip(
        tr("Handle drags snap to the snap steps without Ctrl; Ctrl then drags freely"));
    connect(m_snapAlwaysAction, &QAction::toggled, this, [this](bool on) {
        SnapSettings settings = m_viewport->snapSettings();
        if (settings.always != on) {
            settings.always = on;
            settings.save();
            setSnapSettings(settings);
        }
    });
    connect(makeAction(view, QStringLiteral("actionSnapSteps"), tr("Snap S&teps…")), &QAction::triggered,
            this, &MainWindow::editSnapSettings);
    setSnapSettings(SnapSettings::load()); // the viewport starts with the remembered settings
}

void MainWindow::setSnapSettings(const SnapSettings& settings) {
    m_viewport->setSnapSettings(settings);
    if (m_snapAlwaysAction && m_snapAlwaysAction->isChecked() != settings.always) {
        m_snapAlwaysAction->setChecked(settings.always); // toggles into the lambda, which finds it done
    }
}

// Opened window-modal, so the editor keeps drawing; accepting saves the steps and hands them over.
void MainWindow::editSnapSettings() {
    auto* dialog = new SnapSettingsDialog(m_viewport->snapSettings(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        setSnapSettings(dialog->settings());
        statusBar()->showMessage(tr("Snap steps saved"), 3000);
    });
    dialog->open();
}

} // namespace speculum::ui
