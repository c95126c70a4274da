#include "editor/document/ProjectFileWatch.hpp"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QFileSystemWatcher>

namespace speculum::document {

ProjectFileWatch::ProjectFileWatch(QObject* parent)
    : QObject(parent) {}

void ProjectFileWatch::watch() {
    if (!m_watcher) {
        if (!QCoreApplication::instance()) {
            return;
        }
        m_watcher = new QFileSystemWatcher(this);
        connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &ProjectFileWatch::onFileEvent);
        // A save by rename (ours and most editors') replaces the file: the watch on the old one ends, and
        // the folder's change is what says the name points at new bytes.
        connect(m_watcher, &QFileSystemWatcher::directoryChanged, this, &ProjectFileWatch::onFileEvent);
    }
    if (!m_watcher->files().isEmpty()) {
        m_watcher->removePaths(m_watcher->files());
    }
    if (!m_watcher->directories().isEmpty()) {
        m_watcher->removePaths(m_watcher->directories());
    }
    if (!m_path.isEmpty()) {
        m_watcher->addPath(QFileInfo(m_path).absolutePath());
        if (QFileInfo::exists(m_path)) {
            m_watcher->addPath(m_path);
        }
    }
}

QByteArray ProjectFileWatch::digestOf(const QString& path) {
    // Only a regular file is read: a FIFO put in the project's place must not block the editor.
    if (!QFileInfo(path).isFile()) {
        return {};
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData(&file);
    return hash.result();
}

void ProjectFileWatch::track(const QString& absolutePath) {
    m_path = absolutePath;
    m_reported = false;
    m_digest = m_path.isEmpty() ? QByteArray() : digestOf(m_path);
    watch();
}

bool ProjectFileWatch::changed() const {
    if (m_path.isEmpty()) {
        return false;
    }
    const QByteArray now = digestOf(m_path);
    return !now.isEmpty() && now != m_digest;
}

void ProjectFileWatch::onFileEvent() {
    if (m_path.isEmpty()) {
        return;
    }
    if (QFileInfo::exists(m_path) && !m_watcher->files().contains(m_path)) {
        m_watcher->addPath(m_path); // the file that replaced the watched one
    }
    if (!m_reported && changed()) {
        m_reported = true;
        emit changedOnDisk(m_path);
    }
}

} // namespace speculum::document
