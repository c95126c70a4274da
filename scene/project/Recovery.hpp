#pragma once

#include "base/Result.hpp"
#include "scene/model/SceneData.hpp"

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <string>
#include <vector>

namespace speculum::scene {

// Autosave for crash recovery. Each running editor writes its unsaved document to its own recovery file
// in `folder` (named after the process id, so two editors never overwrite each other), beside a small
// JSON note with the project's own path. A clean exit removes both. On the next start, recovery files
// whose process is gone are the documents of an editor that crashed: the editor offers them.
class RecoveryStore {
public:
    explicit RecoveryStore(QString folder, qint64 processId);
    // Under QStandardPaths::AppLocalDataLocation/recovery, for this process.
    static RecoveryStore forThisProcess();

    const QString& folder() const { return m_folder; }
    QString scenePath() const { return scenePathFor(m_pid); }

    // Writes the document (atomically, validated like any save). originalPath may be empty (untitled).
    base::Status write(const SceneData& data, const QString& originalPath);
    // Removes this process's recovery files (after a save or a clean exit).
    void discard();

    struct Recovered {
        QString scenePath;    // the recovery file
        QString originalPath; // the project it belongs to; empty for an untitled document
        QDateTime savedAt;
    };
    // Recovery files left by processes that no longer run, newest first.
    std::vector<Recovered> orphans() const;

    // Reads a recovery file; paths inside resolve to what they were in the document.
    static base::Result<SceneData> load(const Recovered& recovered, std::vector<std::string>& warnings);
    // Deletes an orphan's files (after it was restored or declined).
    static void remove(const Recovered& recovered);

private:
    QString scenePathFor(qint64 pid) const;
    QString notePathFor(qint64 pid) const;
    QString m_folder;
    qint64 m_pid;
};

} // namespace speculum::scene
