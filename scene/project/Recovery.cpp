#include "scene/project/Recovery.hpp"

#include "base/AtomicFile.hpp"
#include "base/FileKind.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QStandardPaths>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <signal.h>
#include <sys/types.h>

namespace speculum::scene {

namespace {

// Whether a process with this id runs (POSIX: signal 0 checks without sending anything).
bool processRuns(qint64 pid) {
    if (pid <= 0) {
        return false;
    }
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

} // namespace

RecoveryStore::RecoveryStore(QString folder, qint64 processId)
    : m_folder(std::move(folder))
    , m_pid(processId) {}

RecoveryStore RecoveryStore::forThisProcess() {
    return RecoveryStore(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
                             QStringLiteral("/recovery"),
                         QCoreApplication::applicationPid());
}

QString RecoveryStore::scenePathFor(qint64 pid) const {
    return m_folder + QStringLiteral("/recovery-%1.speculum.json").arg(pid);
}

QString RecoveryStore::notePathFor(qint64 pid) const {
    return m_folder + QStringLiteral("/recovery-%1.note.json").arg(pid);
}

base::Status RecoveryStore::write(const SceneData& data, const QString& originalPath) {
    if (!QDir().mkpath(m_folder)) {
        return base::Error{"cannot create the recovery folder " + m_folder.toStdString()};
    }
    if (auto saved = saveProject(data, scenePath()); !saved) {
        return saved;
    }
    const QJsonObject o{{QStringLiteral("project"), originalPath},
                        {QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}};
    // Staged like every other file (base::AtomicFile): a full disk leaves the previous note intact.
    const QByteArray note = QJsonDocument(o).toJson();
    return base::writeFileAtomically(
        QFile::encodeName(notePathFor(m_pid)).toStdString(),
        std::string_view(note.constData(), static_cast<std::size_t>(note.size())));
}

void RecoveryStore::discard() {
    QFile::remove(scenePath());
    QFile::remove(notePathFor(m_pid));
}

std::vector<RecoveryStore::Recovered> RecoveryStore::orphans() const {
    std::vector<Recovered> out;
    static const QRegularExpression name(QStringLiteral("^recovery-(\\d+)\\.speculum\\.json$"));
    const QDir dir(m_folder);
    for (const QFileInfo& file :
         dir.entryInfoList({QStringLiteral("recovery-*.speculum.json")}, QDir::Files)) {
        const auto match = name.match(file.fileName());
        if (!match.hasMatch()) {
            continue;
        }
        const qint64 pid = match.captured(1).toLongLong();
        if (pid == m_pid || processRuns(pid)) {
            continue;
        }
        Recovered r;
        r.scenePath = file.absoluteFilePath();
        r.savedAt = file.lastModified();
        // Only a regular file, read without blocking: a FIFO planted in the folder must not hang startup.
        const base::Result<std::string> note =
            base::readRegularFile(QFile::encodeName(notePathFor(pid)).toStdString(), 1 << 20);
        if (note) {
            const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(*note)).object();
            r.originalPath = o.value(QStringLiteral("project")).toString();
            const QDateTime at =
                QDateTime::fromString(o.value(QStringLiteral("savedAt")).toString(), Qt::ISODate);
            if (at.isValid()) {
                r.savedAt = at;
            }
        }
        out.push_back(r);
    }
    std::sort(out.begin(), out.end(),
              [](const Recovered& a, const Recovered& b) { return a.savedAt > b.savedAt; });
    return out;
}

base::Result<SceneData> RecoveryStore::load(const Recovered& recovered, std::vector<std::string>& warnings) {
    return loadProject(recovered.scenePath, warnings);
}

void RecoveryStore::remove(const Recovered& recovered) {
    QFile::remove(recovered.scenePath);
    QString note = recovered.scenePath;
    note.replace(QStringLiteral(".speculum.json"), QStringLiteral(".note.json"));
    QFile::remove(note);
}

} // namespace speculum::scene
