// Crash recovery in the window: the autosave of the open document, and restoring what editors that
// stopped left unsaved (RecoveryDialog lists it; nothing is deleted that the user did not name).
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/RecoveryDialog.hpp"
#include "scene/model/Scene.hpp"

#include <QCoreApplication>
#include <QMessageBox>
#include <QProcess>
#include <QUndoStack>

namespace speculum::ui {

namespace {

constexpr int kEditsKept = 50; // the newest unsaved edits a recovery note names

// The edits between the saved state and now, oldest first: commands done since the save, or undone
// past it ("Undo Move Teapot"); every command when the saved state is gone from the stack.
QStringList editsSinceSave(const QUndoStack& stack) {
    QStringList edits;
    const int clean = stack.cleanIndex();
    const int now = stack.index();
    if (clean >= 0 && clean > now) {
        for (int i = clean - 1; i >= now; --i) {
            edits << QCoreApplication::translate("MainWindow", "Undo %1").arg(stack.text(i));
        }
        return edits;
    }
    for (int i = std::max(clean, 0); i < now; ++i) {
        edits << stack.text(i);
    }
    return edits;
}

} // namespace

void MainWindow::setRecoveryStore(const scene::RecoveryStore& store) {
    m_recovery = std::make_unique<scene::RecoveryStore>(store);
}

QStringList MainWindow::unsavedEdits() const {
    QStringList edits = m_restoredEdits + editsSinceSave(m_session->undoStack());
    if (edits.size() > kEditsKept) {
        edits = edits.mid(edits.size() - kEditsKept);
    }
    return edits;
}

base::Status MainWindow::autosaveNow() {
    if (!isModified()) {
        return base::Done{};
    }
    rememberEditorView();
    base::Status status = m_recovery->write(scene().toData(), scene().projectPath(), unsavedEdits());
    if (!status) {
        logMessage(tr("Autosave failed: %1").arg(QString::fromStdString(status.error())));
    }
    return status;
}

base::Status MainWindow::restoreRecovery(const scene::RecoveryStore::Recovered& recovered) {
    std::vector<std::string> warnings;
    auto data = scene::RecoveryStore::load(recovered, warnings);
    if (!data) {
        return base::Error{data.error()};
    }
    cancelImports();
    m_session->replace(std::move(*data), recovered.originalPath, true); // modified until saved
    m_restoredEdits = recovered.changes;
    // This session owns the document from here: its own recovery file holds it before the orphan goes.
    if (base::Status kept = autosaveNow(); !kept) {
        return base::Error{"restored, but its recovery file was kept because this editor cannot write its "
                           "own: " +
                           kept.error()};
    }
    scene::RecoveryStore::remove(recovered);
    for (const auto& w : warnings) {
        logMessage(QString::fromStdString(w));
    }
    logMessage(
        tr("Restored unsaved changes of %1 from %2")
            .arg(recovered.originalPath.isEmpty() ? tr("an untitled document") : recovered.originalPath,
                 recovered.savedAt.toLocalTime().toString()));
    updateTitle();
    return base::Done{};
}

base::Status MainWindow::restoreRecoveryFile(const QString& scenePath) {
    base::Result<scene::RecoveryStore::Recovered> recovered = m_recovery->orphanAt(scenePath);
    if (!recovered) {
        return base::Error{recovered.error()};
    }
    return restoreRecovery(*recovered);
}

base::Status MainWindow::restoreInNewEditor(const scene::RecoveryStore::Recovered& recovered) {
    const QString program =
        m_newEditorProgram.isEmpty() ? QCoreApplication::applicationFilePath() : m_newEditorProgram;
    // The new editor takes the document over (restoreRecoveryFile); this one leaves the files alone.
    if (!QProcess::startDetached(program, {QStringLiteral("--recover"), recovered.scenePath})) {
        return base::Error{"cannot start another editor (" + program.toStdString() + ")"};
    }
    logMessage(tr("Opened the unsaved changes of %1 in a new window").arg(recoveredName(recovered)));
    return base::Done{};
}

void MainWindow::offerRecovery(bool sayWhenNothing) {
    scene::RecoveryStore::Scan scan = m_recovery->scan();
    for (const auto& bad : scan.unreadable) {
        logMessage(tr("Could not read the recovery file %1: %2. It was moved to %3")
                       .arg(bad.recovered.scenePath, QString::fromStdString(bad.reason), bad.keptAt));
    }
    if (scan.recoverable.empty() && scan.unreadable.empty()) {
        if (sayWhenNothing) {
            QMessageBox::information(this, tr("Recover Unsaved Changes"),
                                     tr("No other editor left unsaved changes."));
        }
        return;
    }
    RecoveryDialog::Actions actions;
    actions.restoreHere = [this](const scene::RecoveryStore::Recovered& r) -> base::Status {
        if (!maybeSave()) {
            return base::Error{"the open document has unsaved changes"};
        }
        return restoreRecovery(r);
    };
    actions.restoreInNewWindow = [this](const scene::RecoveryStore::Recovered& r) {
        return restoreInNewEditor(r);
    };
    RecoveryDialog dialog(std::move(scan), std::move(actions), this);
    dialog.exec();
}

} // namespace speculum::ui
