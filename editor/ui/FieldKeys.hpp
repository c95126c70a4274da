#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

class QWidget;

namespace speculum::ui {

// The keyboard after a field, as in Blender: Enter commits a text or number field and hands the keyboard
// back to `home` (the viewport), so that Ctrl+Z, W/E/R, F and Delete act on the document again; Esc puts
// the field back to what it held when it got focus, commits nothing and hands the keyboard back too. The
// scene tree's rename editor (F2) does the same. Fields of dialogs keep their keys (Enter presses the
// dialog's default button there).
class FieldKeys : public QObject {
public:
    // Watches the fields of `window` and of its docks, floating ones too; owned by `window`.
    FieldKeys(QWidget& window, QWidget& home);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // A line edit or spin box of the window (not of a dialog), or null.
    QWidget* fieldOf(QObject* watched) const;
    // Once the key has done its own work (the field committed, the rename editor closed): the keyboard
    // to `home`, unless something else took focus meanwhile.
    void handBackAfter(QWidget* field);
    void revert(QWidget* field);

    QWidget& m_window;
    QWidget& m_home;
    QPointer<QWidget> m_focused; // the field whose text m_textAtFocus holds
    QString m_textAtFocus;
};

} // namespace speculum::ui
