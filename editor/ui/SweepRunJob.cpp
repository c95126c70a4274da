#include "editor/ui/SweepRunJob.hpp"

#include "accuracy/Report.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QMetaObject>
#include <QRegularExpression>
#include <algorithm>
#include <set>

namespace speculum::ui {

SweepRunJob::SweepRunJob(QObject* parent)
    : QObject(parent) {}

SweepRunJob::~SweepRunJob() {
    m_cancel = true;
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

accuracy::SweepInput SweepRunJob::inputFor(const scene::Scene& scene, scene::MeshLibrary& meshes,
                                           const QString& sceneName, bool quick,
                                           std::vector<scene::Warning>& warnings) {
    accuracy::SweepInput input;
    input.sceneName = sceneName.toStdString();
    input.quick = quick;
    input.scene = scene::snapshot(scene, 0.0, meshes, warnings);
    std::set<int> tessellations;
    scene.forEachNode([&](const scene::Node& node) {
        const auto& mesh = node.data().mesh;
        if (mesh && mesh->builtin == scene::BuiltinMesh::Teapot) {
            tessellations.insert(mesh->tessellation);
        }
    });
    if (!tessellations.empty()) {
        input.teapotTessellation = *tessellations.begin();
    }
    // The update family plays the scene forward as the editor plays it (the sweep leaves it out where
    // nothing its reflectors' maps see moves).
    if (!input.scene.reflectors.empty()) {
        input.playedFrames.push_back(input.scene);
        for (int k = 1; k < accuracy::kPlayedFrames; ++k) {
            std::vector<scene::Warning> repeated; // the first frame's warnings are reported already
            input.playedFrames.push_back(scene::snapshot(scene, k / 60.0, meshes, repeated));
        }
    }
    // The snapshot's teapots are the editor's library's meshes; the worker makes the other tessellations in
    // a library of its own (a MeshLibrary is not shared across threads) and swaps by identity, as the bench.
    std::set<const render::MeshData*> teapots;
    for (int t : tessellations) {
        teapots.insert(meshes.builtin(scene::BuiltinMesh::Teapot, t).get());
    }
    auto own = std::make_shared<scene::MeshLibrary>();
    input.tessellate = [teapots, own](const render::MeshHandle& mesh, int tessellation) {
        return teapots.count(mesh.get()) ? own->builtin(scene::BuiltinMesh::Teapot, tessellation) : mesh;
    };
    return input;
}

bool SweepRunJob::start(accuracy::SweepInput input) {
    if (running()) {
        emit failed(tr("a sweep is already running"), false);
        return false;
    }
    m_cancel = false;
    m_thread = std::thread([this, input = std::move(input)]() mutable { work(std::move(input)); });
    return true;
}

void SweepRunJob::cancel() {
    m_cancel = true;
}

void SweepRunJob::post(std::function<void()> onGuiThread) {
    QMetaObject::invokeMethod(this, std::move(onGuiThread), Qt::QueuedConnection);
}

void SweepRunJob::work(accuracy::SweepInput input) {
    // Ends the job on the GUI thread: the worker is done (or about to return), so join it first.
    auto end = [this](std::function<void()> report) {
        post([this, report = std::move(report)] {
            if (m_thread.joinable()) {
                m_thread.join();
            }
            report();
        });
    };
    auto context = render::gl::HeadlessContext::create();
    if (!context) {
        const QString why =
            tr("no OpenGL context for the sweep: %1").arg(QString::fromStdString(context.error()));
        end([this, why] { emit failed(why, false); });
        return;
    }
    const std::string rendererName = (*context)->description();
    auto renderer = render::Renderer::create();
    if (!renderer) {
        const QString why = QString::fromStdString(renderer.error());
        end([this, why] { emit failed(why, false); });
        return;
    }

    // Steps for the progress bar: each reference, each configuration, each timing round.
    const auto configs = accuracy::planSweep(
        input.scene, accuracy::sceneTraits(input.scene, input.teapotTessellation), {input.quick});
    std::set<accuracy::ReferenceKind> kinds;
    for (const auto& c : configs) {
        kinds.insert(c.reference);
    }
    const int referenceSteps = int(kinds.size());
    int done = 0;
    const int steps = referenceSteps + int(configs.size()) + accuracy::sweepTiming(input.quick).rounds;
    auto total = [steps] { return steps; };
    std::vector<accuracy::Record> records;

    accuracy::SweepObserver observer;
    observer.stop = [this] { return m_cancel.load(); };
    observer.progress = [&](const std::string& line) {
        // "[3/40] envmap: cube 128: rendering" reads "Point 3 of 40: envmap: cube 128: rendering" here.
        QString text = QString::fromStdString(line);
        static const QRegularExpression step(QStringLiteral("^\\[(\\d+)/(\\d+)\\] "));
        if (const QRegularExpressionMatch m = step.match(text); m.hasMatch()) {
            text = tr("Point %1 of %2: %3").arg(m.captured(1), m.captured(2), text.mid(m.capturedLength()));
        } else if (!text.isEmpty()) {
            text[0] = text[0].toUpper();
        }
        const int d = done, t = total();
        post([this, d, t, text] { emit progress(d, t, text); });
    };
    observer.referenceTraced = [&](const accuracy::Reference&,
                                   const accuracy::ReferenceInfo&) -> base::Status {
        ++done;
        return base::Done{};
    };
    observer.measured = [&](std::size_t index, std::size_t count, const accuracy::Record& record,
                            const accuracy::FrameCost&, const accuracy::ErrorFigures&) -> base::Status {
        ++done;
        records.push_back(record);
        const QString text = tr("Point %1 of %2: %3")
                                 .arg(index + 1)
                                 .arg(count)
                                 .arg(QString::fromStdString(accuracy::familyName(record.config.family) +
                                                             ": " + accuracy::displayName(record.config)));
        const int d = done, t = total();
        post([this, d, t, text, records] {
            emit progress(d, t, text);
            emit recordsChanged(records);
        });
        return base::Done{};
    };
    observer.timed = [&](int round, int of, const std::vector<accuracy::Record>& timed) {
        ++done;
        const QString text = tr("Timing round %1 of %2").arg(round).arg(of);
        const int d = done, t = total();
        post([this, d, t, text, timed] {
            emit progress(d, t, text);
            emit recordsChanged(timed);
        });
    };
    auto swept = accuracy::runSweep(**renderer, input, observer);
    renderer->reset(); // GL objects go before their context
    context->reset();
    if (!swept) {
        const bool cancelled = m_cancel.load();
        const QString why = QString::fromStdString(swept.error());
        end([this, why, cancelled] { emit failed(why, cancelled); });
        return;
    }
    accuracy::ResultsFile results;
    results.run = std::move(swept->run);
    results.run.scene = results.run.sceneName;
    results.run.renderer = rendererName;
    results.records = std::move(swept->records);
    end([this, results = std::move(results)] { emit finished(results); });
}

} // namespace speculum::ui
