#include "scene/project/Recovery.hpp"

#include "base/AtomicFile.hpp"
#include "base/FileKind.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
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

const QRegularExpression& recoveryName() {
    static const QRegularExpression name(QStringLiteral("^recovery-(\\d+)\\.speculum\\.json$"));
    return name;
}

const QString kSceneSuffix = QStringLiteral(".speculum.json");
const QString kNoteSuffix = QStringLiteral(".note.json");

// The note beside a recovery file: recovery-PID.note.json for recovery-PID.speculum.json.
QString notePathOf(const QString& scenePath) {
    return scenePath.chopped(kSceneSuffix.size()) + kNoteSuffix;
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

base::Status RecoveryStore::write(const SceneData& data, const QString& originalPath,
                                  const QStringList& changes) {
    if (!QDir().mkpath(m_folder)) {
        return base::Error{"cannot create the recovery folder " + m_folder.toStdString()};
    }
    if (auto saved = saveProject(data, scenePath()); !saved) {
        return saved;
    }
    const QJsonObject o{{QStringLiteral("project"), originalPath},
                        {QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)},
                        {QStringLiteral("changes"), QJsonArray::fromStringList(changes)}};
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

std::optional<RecoveryStore::Recovered> RecoveryStore::orphanFile(const QString& scenePath) const {
    const QFileInfo file(scenePath);
    const auto match = recoveryName().match(file.fileName());
    if (!match.hasMatch() || QFileInfo(file.absolutePath()) != QFileInfo(m_folder)) {
        return std::nullopt;
    }
    const qint64 pid = match.captured(1).toLongLong();
    if (pid == m_pid || processRuns(pid)) {
        return std::nullopt;
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
        for (const QJsonValue& change : o.value(QStringLiteral("changes")).toArray()) {
            r.changes << change.toString();
        }
    }
    return r;
}

std::vector<RecoveryStore::Recovered> RecoveryStore::orphans() const {
    std::vector<Recovered> out;
    const QDir dir(m_folder);
    for (const QFileInfo& file :
         dir.entryInfoList({QStringLiteral("recovery-*.speculum.json")}, QDir::Files)) {
        if (auto r = orphanFile(file.absoluteFilePath())) {
            out.push_back(std::move(*r));
        }
    }
    std::sort(out.begin(), out.end(),
              [](const Recovered& a, const Recovered& b) { return a.savedAt > b.savedAt; });
    return out;
}

RecoveryStore::Scan RecoveryStore::scan() const {
    Scan scan;
    for (Recovered& r : orphans()) {
        std::vector<std::string> warnings;
        const base::Result<SceneData> data = load(r, warnings);
        if (data) {
            scan.recoverable.push_back(std::move(r));
            continue;
        }
        Unreadable bad{r, r.scenePath, data.error()};
        if (base::Result<QString> kept = quarantine(r)) {
            bad.keptAt = *kept;
        } else {
            bad.reason += "; it stays where it is (" + kept.error() + ")";
        }
        scan.unreadable.push_back(std::move(bad));
    }
    return scan;
}

base::Result<RecoveryStore::Recovered> RecoveryStore::orphanAt(const QString& scenePath) const {
    if (auto r = orphanFile(scenePath)) {
        return std::move(*r);
    }
    return base::Error{"not a recovery file left by an editor that stopped: " + scenePath.toStdString()};
}

base::Result<QString> RecoveryStore::quarantine(const Recovered& recovered) const {
    if (!QDir().mkpath(quarantineFolder())) {
        return base::Error{"cannot create " + quarantineFolder().toStdString()};
    }
    // A name of its own in the quarantine, so an earlier unreadable file of a reused process id stays.
    const QString stem = quarantineFolder() + QLatin1Char('/') +
                         QFileInfo(recovered.scenePath).fileName().chopped(kSceneSuffix.size());
    QString kept = stem;
    for (int n = 2; QFile::exists(kept + kSceneSuffix); ++n) {
        kept = stem + QLatin1Char('-') + QString::number(n);
    }
    if (!QFile::rename(recovered.scenePath, kept + kSceneSuffix)) {
        return base::Error{"cannot move it into " + quarantineFolder().toStdString()};
    }
    QFile::rename(notePathOf(recovered.scenePath), kept + kNoteSuffix);
    return kept + kSceneSuffix;
}

base::Result<SceneData> RecoveryStore::load(const Recovered& recovered, std::vector<std::string>& warnings) {
    return loadProject(recovered.scenePath, warnings);
}

void RecoveryStore::remove(const Recovered& recovered) {
    QFile::remove(recovered.scenePath);
    QFile::remove(notePathOf(recovered.scenePath));
}

} // namespace speculum::scene
