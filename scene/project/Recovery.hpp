#pragma once

#include "base/Result.hpp"
#include "scene/model/SceneData.hpp"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <optional>
#include <string>
#include <vector>

namespace speculum::scene {

// Autosave for crash recovery. Each running editor writes its unsaved document to its own recovery file
// in `folder` (named after the process id, so two editors never overwrite each other), beside a small
// JSON note with the project's own path, the time and the edits not yet saved. A clean exit removes both.
// On the next start, recovery files whose process is gone are the documents of editors that crashed: the
// editor lists every one of them. Nothing here deletes a recovery file the user did not restore or
// discard by name; one that cannot be read is moved aside into quarantineFolder(), never deleted.
class RecoveryStore {
public:
    explicit RecoveryStore(QString folder, qint64 processId);
    // Under QStandardPaths::AppLocalDataLocation/recovery, for this process.
    static RecoveryStore forThisProcess();

    const QString& folder() const { return m_folder; }
    QString quarantineFolder() const { return m_folder + QStringLiteral("/unreadable"); }
    QString scenePath() const { return scenePathFor(m_pid); }

    // Writes the document (atomically, validated like any save). originalPath may be empty (untitled);
    // changes names the edits since the last save, newest last ("Move Teapot").
    base::Status write(const SceneData& data, const QString& originalPath, const QStringList& changes = {});
    // Removes this process's recovery files (after a save or a clean exit).
    void discard();

    struct Recovered {
        QString scenePath;    // the recovery file
        QString originalPath; // the project it belongs to; empty for an untitled document
        QDateTime savedAt;
        QStringList changes; // the unsaved edits, newest last; empty when the note did not say
    };
    struct Unreadable {
        Recovered recovered; // as it was found (scenePath: where it was)
        QString keptAt;      // where it is now, in quarantineFolder()
        std::string reason;  // why it could not be read
    };
    struct Scan {
        std::vector<Recovered> recoverable; // newest first
        std::vector<Unreadable> unreadable;
    };

    // Recovery files left by processes that no longer run, newest first (not read, only listed).
    std::vector<Recovered> orphans() const;
    // Every orphan read in full: those that load are recoverable; one that does not is moved into
    // quarantineFolder() with its note (so it is neither offered again nor lost) and listed as unreadable.
    Scan scan() const;
    // The orphan at scenePath with what its note says (the editor's --recover); an error when the file is
    // not a recovery file of this store's folder or its process still runs.
    base::Result<Recovered> orphanAt(const QString& scenePath) const;

    // Reads a recovery file; paths inside resolve to what they were in the document.
    static base::Result<SceneData> load(const Recovered& recovered, std::vector<std::string>& warnings);
    // Deletes an orphan's files: only for one the user restored or discarded by name.
    static void remove(const Recovered& recovered);

private:
    QString scenePathFor(qint64 pid) const;
    QString notePathFor(qint64 pid) const;
    std::optional<Recovered> orphanFile(const QString& scenePath) const;
    base::Result<QString> quarantine(const Recovered& recovered) const;
    QString m_folder;
    qint64 m_pid;
};

} // namespace speculum::scene
