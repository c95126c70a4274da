#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

class QFileSystemWatcher;

namespace speculum::document {

// The open document's project file as this editor last read or wrote it, and whether the file on disk is
// still that: another editor or program may save over it while it is open. The file's bytes are compared
// by digest, so touching it, or a save of identical bytes, is no change; a file that was deleted is none
// either (saving only writes it again). Qt's watcher reports changes as they happen; changed() reads the
// file again, so a check right before a save never relies on a notification having arrived.
class ProjectFileWatch : public QObject {
    Q_OBJECT
public:
    explicit ProjectFileWatch(QObject* parent = nullptr);

    // The file is now as this editor knows it (just opened or saved); empty: no file (untitled).
    void track(const QString& absolutePath);
    const QString& path() const { return m_path; }
    // The file on disk differs from what this editor last read or wrote.
    bool changed() const;

signals:
    // The file was written by someone else (once per change: a later save or track() re-arms it).
    void changedOnDisk(const QString& path);

private:
    void watch(); // the file and its folder, from now on
    void onFileEvent();
    static QByteArray digestOf(const QString& path);

    QString m_path;
    QByteArray m_digest; // empty: the file did not exist
    // Made on the first track() where an application runs (the watcher needs its event loop); changed()
    // works without it.
    QFileSystemWatcher* m_watcher = nullptr;
    bool m_reported = false;
};

} // namespace speculum::document
