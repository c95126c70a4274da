#pragma once

#include "base/Result.hpp"
#include "scene/project/Recovery.hpp"

#include <QDialog>
#include <functional>
#include <vector>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace speculum::ui {

// Every document that editors left unsaved when they stopped, one row each (project, when, the unsaved
// edits), and the recovery files that could not be read (where they were moved, and why). Each row is
// restored or discarded on its own, by the user naming it; closing the dialog ("Decide Later") keeps every
// file for the next start or File ▸ Recover Unsaved Changes.
class RecoveryDialog : public QDialog {
    Q_OBJECT
public:
    using Recovered = scene::RecoveryStore::Recovered;
    // restoreHere loads a document into the window that opened the dialog; restoreInNewWindow starts
    // another editor with it. Each returns the outcome; a row goes only when its restore succeeded.
    struct Actions {
        std::function<base::Status(const Recovered&)> restoreHere;
        std::function<base::Status(const Recovered&)> restoreInNewWindow;
    };
    RecoveryDialog(scene::RecoveryStore::Scan scan, Actions actions, QWidget* parent = nullptr);

    // The rows still offered, in the order shown (newest first).
    const std::vector<Recovered>& offered() const { return m_offered; }
    // What the buttons do, for the selected row; false when the restore failed (the row stays, the error
    // is shown in the dialog) or the discard was not confirmed.
    bool restoreHere(int row);
    bool restoreInNewWindow(int row);
    // Asks "Discard the unsaved changes to NAME?" first; the files are deleted only on Yes.
    bool discard(int row);
    // The text shown about unreadable files (empty when there are none).
    QString unreadableText() const;
    QString lastError() const { return m_lastError; }

private:
    void fillRows();
    void updateButtons();
    int selectedRow() const;
    bool restoreWith(int row, const std::function<base::Status(const Recovered&)>& action);
    void removeRow(int row);

    std::vector<Recovered> m_offered;
    std::vector<scene::RecoveryStore::Unreadable> m_unreadable;
    Actions m_actions;
    QTreeWidget* m_list = nullptr;
    QLabel* m_problem = nullptr;
    QPushButton* m_restoreHere = nullptr;
    QPushButton* m_restoreNew = nullptr;
    QPushButton* m_discard = nullptr;
    QString m_lastError;
};

// How a recovered document is named to the user: its project's file name, or "an untitled document".
QString recoveredName(const scene::RecoveryStore::Recovered& recovered);

} // namespace speculum::ui
