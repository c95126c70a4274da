// Viewport: the inspect tool. A click explains one pixel: the frame is drawn once more, offscreen at the
// view's size, with the pixel's value read back after every pass (render::RenderOptions::probePixel), the
// exact tracer follows the pixel's paths, and render::inspect puts the two side by side. Nothing is
// recorded in the frames the view draws otherwise.
#include "editor/ui/InspectPanel.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/view/AnimationClock.hpp"
#include "render/reference/Tracer.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QGuiApplication>
#include <algorithm>

namespace speculum::ui {

void Viewport::setInspecting(bool on) {
    m_inspecting = on;
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    if (!on)
        clearInspection();
}

void Viewport::clearInspection() {
    m_inspected.reset();
    if (m_inspectionGuides.empty())
        return;
    m_inspectionGuides.clear();
    update();
}

void Viewport::highlightInspectedStep(int vertex) {
    if (!m_inspected)
        return;
    m_inspectionGuides = pathGuides(m_inspected->first, m_inspected->second, vertex);
    update();
}

void Viewport::inspectAt(QPointF position) {
    if (!m_renderer)
        return;
    const qreal dpr = devicePixelRatioF();
    const int w = std::max(1, int(width() * dpr)), h = std::max(1, int(height() * dpr));
    const glm::ivec2 pixel(std::clamp(int(position.x() * dpr), 0, w - 1),
                           std::clamp(int(position.y() * dpr), 0, h - 1));
    std::vector<scene::Warning> warnings;
    m_models->prepare(m_scene);
    render::FrameInput input = scene::snapshot(m_scene, m_clock.time(), m_meshes, warnings);
    input.camera = m_navigation.camera();
    QGuiApplication::setOverrideCursor(Qt::WaitCursor);
    makeCurrent();
    // In one piece whatever the view's size, so that the pixel's recipe is recorded.
    render::StillSettings settings{w, h, 1, render::maxStillSize()};
    settings.probePixel = pixel;
    settings.reuseMaps = false; // the recipe then holds every map the pixel reads, drawn in this frame
    auto still = render::renderStill(*m_renderer, input, settings);
    auto source = still ? render::screenSpaceSourceAt(*m_renderer, input, settings, pixel)
                        : base::Result<std::optional<glm::dvec3>>(std::optional<glm::dvec3>());
    doneCurrent();
    auto fail = [&](const std::string& message) {
        QGuiApplication::restoreOverrideCursor();
        emit inspectionFailed(QString::fromStdString(message));
    };
    if (!still)
        return fail("the frame could not be drawn: " + still.error());
    if (!source)
        return fail("the screen-space sources could not be drawn: " + source.error());
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer)
        return fail(tracer.error());
    render::reference::TraceSettings trace;
    trace.width = w;
    trace.height = h;
    auto paths = tracer->explainPixel(trace, pixel.x, pixel.y);
    if (!paths)
        return fail(paths.error());
    auto explained =
        render::inspect::explainPixel(input, still->firstSample, still->image, *paths, *tracer, *source);
    if (!explained)
        return fail(explained.error());
    QGuiApplication::restoreOverrideCursor();
    m_inspectionGuides = pathGuides(*explained, input);
    m_inspected.emplace(*explained, input);
    emit pixelInspected(*explained, input);
    update();
}

} // namespace speculum::ui
