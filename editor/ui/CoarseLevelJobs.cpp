#include "editor/ui/CoarseLevelJobs.hpp"

#include "render/mesh/Simplify.hpp"

#include <QMetaObject>
#include <QThread>
#include <memory>

namespace speculum::ui {

CoarseLevelJobs::CoarseLevelJobs(QObject* parent)
    : QObject(parent) {
    // One at a time: each build is memory-hungry, and the renderer and the GUI come first.
    m_pool.setMaxThreadCount(1);
    m_pool.setThreadPriority(QThread::LowPriority);
}

CoarseLevelJobs::~CoarseLevelJobs() {
    m_pool.clear(); // the queued ones are not started
    m_pool.waitForDone();
}

void CoarseLevelJobs::request(const std::vector<render::MeshHandle>& meshes) {
    for (const render::MeshHandle& mesh : meshes) {
        if (!mesh || mesh->coarse.ready() || !m_pending.insert(mesh.get()).second)
            continue;
        const std::weak_ptr<const render::MeshData> weak = mesh;
        const render::MeshData* key = mesh.get();
        // The destructor waits for the pool, so `this` outlives every job; a reply posted to it after it
        // is gone is dropped with it.
        m_pool.start([this, weak, key] {
            if (const render::MeshHandle alive = weak.lock())
                render::coarseLevel(*alive);
            QMetaObject::invokeMethod(
                this,
                [this, key] {
                    m_pending.erase(key);
                    emit levelBuilt();
                },
                Qt::QueuedConnection);
        });
    }
}

} // namespace speculum::ui
