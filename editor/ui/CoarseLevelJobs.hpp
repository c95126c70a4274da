#pragma once

#include "render/mesh/MeshData.hpp"

#include <QObject>
#include <QThreadPool>
#include <set>
#include <vector>

namespace speculum::ui {

// Builds big meshes' simplified levels (render::coarseLevel) on a worker thread when the viewport's
// renderer asks for them (Renderer::setCoarseLevelRequest), so that the first reflection of a
// multi-million-triangle model never stalls the editor: the frame draws the mesh whole meanwhile. Holds
// each mesh weakly: one the document let go of before its turn is not built.
class CoarseLevelJobs : public QObject {
    Q_OBJECT

public:
    explicit CoarseLevelJobs(QObject* parent = nullptr);
    // Waits for a level being built (seconds at most): the mesh it reads must outlive it.
    ~CoarseLevelJobs() override;

    // Queues the meshes not built and not queued yet; the renderer calls it every frame until they are.
    void request(const std::vector<render::MeshHandle>& meshes);
    // Levels queued or being built.
    int pending() const { return static_cast<int>(m_pending.size()); }
    // Tests: waits until every queued level is built (or its mesh is gone).
    void waitForDone() { m_pool.waitForDone(); }

signals:
    // On the GUI thread, after a level is built: the next frame can draw it.
    void levelBuilt();

private:
    QThreadPool m_pool;
    std::set<const render::MeshData*> m_pending;
};

} // namespace speculum::ui
