#include "editor/ui/RecoveryDialog.hpp"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace speculum::ui {

namespace {

constexpr int kEditsShown = 3; // the newest edits named in a row; the rest are counted

QString editsText(const QStringList& changes) {
    if (changes.isEmpty()) {
        return RecoveryDialog::tr("(not recorded)");
    }
    QStringList newest;
    for (qsizetype i = changes.size() - 1; i >= 0 && newest.size() < kEditsShown; --i) {
        newest << changes[i];
    }
    QString text = newest.join(QStringLiteral(", "));
    if (changes.size() > kEditsShown) {
        text += RecoveryDialog::tr(" … (%1 edits in all)").arg(changes.size());
    }
    return text;
}

QString timeText(const QDateTime& at) {
    return QLocale().toString(at.toLocalTime(), QLocale::ShortFormat);
}

} // namespace

QString recoveredName(const scene::RecoveryStore::Recovered& recovered) {
    return recovered.originalPath.isEmpty() ? RecoveryDialog::tr("an untitled document")
                                            : QFileInfo(recovered.originalPath).fileName();
}

RecoveryDialog::RecoveryDialog(scene::RecoveryStore::Scan scan, Actions actions, QWidget* parent)
    : QDialog(parent)
    , m_offered(std::move(scan.recoverable))
    , m_unreadable(std::move(scan.unreadable))
    , m_actions(std::move(actions)) {
    setWindowTitle(tr("Recover Unsaved Changes"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("speculum did not shut down properly, and these documents had unsaved "
                                "changes. Restore each one you want, or discard it; whatever you leave "
                                "is offered again next time."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    m_list = new QTreeWidget(this);
    m_list->setObjectName(QStringLiteral("recoveryList"));
    m_list->setHeaderLabels({tr("Document"), tr("Saved"), tr("Unsaved edits")});
    m_list->setRootIsDecorated(false);
    m_list->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    layout->addWidget(m_list);

    m_problem = new QLabel(unreadableText(), this);
    m_problem->setWordWrap(true);
    m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->setVisible(!m_unreadable.empty());
    layout->addWidget(m_problem);

    auto* buttons = new QDialogButtonBox(this);
    m_restoreHere = buttons->addButton(tr("&Restore"), QDialogButtonBox::ActionRole);
    m_restoreNew = buttons->addButton(tr("Restore in &New Window"), QDialogButtonBox::ActionRole);
    m_discard = buttons->addButton(tr("&Discard…"), QDialogButtonBox::DestructiveRole);
    m_restoreHere->setDefault(true);
    buttons->addButton(tr("Decide &Later"), QDialogButtonBox::RejectRole);
    layout->addWidget(buttons);
    connect(m_restoreHere, &QPushButton::clicked, this, [this] { restoreHere(selectedRow()); });
    connect(m_restoreNew, &QPushButton::clicked, this, [this] { restoreInNewWindow(selectedRow()); });
    connect(m_discard, &QPushButton::clicked, this, [this] { discard(selectedRow()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_list, &QTreeWidget::itemSelectionChanged, this, &RecoveryDialog::updateButtons);

    fillRows();
    resize(720, 360);
}

void RecoveryDialog::fillRows() {
    m_list->clear();
    for (const Recovered& r : m_offered) {
        auto* item =
            new QTreeWidgetItem(m_list, {recoveredName(r), timeText(r.savedAt), editsText(r.changes)});
        const QString where = r.originalPath.isEmpty() ? tr("never saved") : r.originalPath;
        item->setToolTip(0, tr("%1\nRecovery file: %2").arg(where, r.scenePath));
        item->setToolTip(2, r.changes.join(QLatin1Char('\n')));
    }
    if (m_list->topLevelItemCount() > 0) {
        m_list->setCurrentItem(m_list->topLevelItem(0));
    }
    updateButtons();
}

void RecoveryDialog::updateButtons() {
    const bool any = selectedRow() >= 0;
    m_restoreHere->setEnabled(any);
    m_restoreNew->setEnabled(any);
    m_discard->setEnabled(any);
}

int RecoveryDialog::selectedRow() const {
    QTreeWidgetItem* item = m_list->currentItem();
    return item ? m_list->indexOfTopLevelItem(item) : -1;
}

bool RecoveryDialog::restoreHere(int row) {
    return restoreWith(row, m_actions.restoreHere);
}

bool RecoveryDialog::restoreInNewWindow(int row) {
    return restoreWith(row, m_actions.restoreInNewWindow);
}

bool RecoveryDialog::restoreWith(int row, const std::function<base::Status(const Recovered&)>& action) {
    if (row < 0 || row >= int(m_offered.size()) || !action) {
        return false;
    }
    const base::Status status = action(m_offered[std::size_t(row)]);
    if (!status) {
        m_lastError =
            tr("Could not restore %1: %2")
                .arg(recoveredName(m_offered[std::size_t(row)]), QString::fromStdString(status.error()));
        m_problem->setText(m_lastError +
                           (m_unreadable.empty() ? QString() : QStringLiteral("\n\n") + unreadableText()));
        m_problem->setVisible(true);
        return false;
    }
    removeRow(row);
    return true;
}

bool RecoveryDialog::discard(int row) {
    if (row < 0 || row >= int(m_offered.size())) {
        return false;
    }
    const Recovered& r = m_offered[std::size_t(row)];
    const auto answer =
        QMessageBox::warning(this, tr("Discard Unsaved Changes"),
                             tr("Discard the unsaved changes to %1 from %2?\n\nThis cannot be undone.")
                                 .arg(recoveredName(r), timeText(r.savedAt)),
                             QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Discard) {
        return false;
    }
    scene::RecoveryStore::remove(r);
    removeRow(row);
    return true;
}

void RecoveryDialog::removeRow(int row) {
    m_offered.erase(m_offered.begin() + row);
    fillRows();
    if (m_offered.empty() && m_unreadable.empty()) {
        accept(); // nothing left to decide
    }
}

QString RecoveryDialog::unreadableText() const {
    QStringList lines;
    for (const auto& bad : m_unreadable) {
        lines << tr("The recovery of %1 from %2 could not be read (%3). It was kept, not deleted: %4")
                     .arg(recoveredName(bad.recovered), timeText(bad.recovered.savedAt),
                          QString::fromStdString(bad.reason), bad.keptAt);
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace speculum::ui
