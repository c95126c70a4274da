// Viewport: the frames. The renderer's lifetime, what each frame draws (with the previews of adaptive
// resolution) and when frames are drawn at all. The input handed on to navigation and the handles is in
// ViewportInput.cpp, the marks painted over the frame in ViewportMarks.cpp.
#include "editor/ui/Viewport.hpp"

#include "editor/ui/CameraGizmo.hpp"
#include "editor/ui/CoarseLevelJobs.hpp"
#include "editor/ui/ViewGrid.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/ui/ViewportOverlay.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "render/plan/MapCost.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneAnimation.hpp"

#include <QEventLoop>
#include <QOpenGLContext>
#include <QPainter>
#include <algorithm>

namespace speculum::ui {

using view::AnimationClock;
using view::Selection;

namespace {

// GL_SRGB8_ALPHA8 (the widget's texture format is a GL enum; no GL header is included here).
constexpr unsigned kSrgbTextureFormat = 0x8C43;

} // namespace

Viewport::Viewport(scene::Scene& scene, scene::MeshLibrary& meshes, AnimationClock& clock, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_scene(scene)
    , m_clock(clock)
    , m_meshes(meshes)
    , m_navigation(scene)
    , m_handles(scene, [this]() -> scene::MeshLibrary& { return this->meshes(); }) {
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(true); // handle hover highlight
    setObjectName(QStringLiteral("viewport"));
    // An sRGB colour texture: the renderer draws a frame that needs no half-float buffer straight into it
    // (render::RenderTarget::srgbDepthStencil), with no copy; Qt composes it into the window as sRGB.
    setTextureFormat(kSrgbTextureFormat);
    m_overlay = new ViewportOverlay(*this);
    m_models = new ViewportModels(m_meshes, this);
    connect(m_models, &ViewportModels::changed, this, qOverload<>(&Viewport::update));
    // A reflection draws a big mesh whole until its simplified level is built, then at that level.
    m_coarseLevels = new CoarseLevelJobs(this);
    connect(m_coarseLevels, &CoarseLevelJobs::levelBuilt, this, qOverload<>(&Viewport::update));

    // The viewport draws only when what it shows changes (a static scene costs nothing at idle):
    // an edit, a new document, navigation, a time jump, a model read in, a resize, or the clock running
    // over a scene where something moves. Nothing the frame reports leads back to another frame.
    connect(&m_scene, &scene::Scene::changed, this, [this] {
        updateTicking(); // an edit may add or remove the scene's only animation
        update();
    });
    // A camera edit or a newly opened document: show the document's camera again.
    connect(&m_scene, &scene::Scene::cameraChanged, this, &Viewport::resetView);
    // The session has replaced its mesh library by then (on aboutToReset): the reads running for the old
    // document are of no use.
    // Connected here, in the constructor, so it runs before any connection made to sceneReset once the
    // viewport exists: viewReset() is emitted when the view is back on the new scene camera.
    connect(&m_scene, &scene::Scene::sceneReset, this, [this] {
        m_models->clear();
        updateTicking();
        resetView();
        emit viewReset();
    });

    m_rest.setSingleShot(true);
    m_rest.setInterval(kRestMs);
    connect(&m_rest, &QTimer::timeout, this, &Viewport::rested);
    connect(this, &QOpenGLWidget::frameSwapped, this, &Viewport::frameOnScreen);

    // ~60 fps while playing. A timer rather than update() from paintGL: Xvfb and some drivers do not
    // throttle swaps, and an unthrottled loop would starve the rest of the UI.
    m_tick.setInterval(16);
    m_tick.setTimerType(Qt::PreciseTimer);
    connect(&m_tick, &QTimer::timeout, this, qOverload<>(&Viewport::update));
    connect(&m_clock, &AnimationClock::playingChanged, this, &Viewport::updateTicking);
    connect(&m_clock, &AnimationClock::timeChanged, this, qOverload<>(&Viewport::update)); // jumps only
    updateTicking();
}

Viewport::~Viewport() {
    releaseGlResources();
}

void Viewport::readModels() {
    m_models->prepare(m_scene);
}

bool Viewport::modelsLoading() const {
    return m_models->isLoading();
}

void Viewport::waitForModels() {
    m_models->prepare(m_scene);
    if (!m_models->isLoading()) {
        return;
    }
    QEventLoop loop; // the window keeps painting and taking input meanwhile
    const auto connection = connect(m_models, &ViewportModels::changed, &loop, [&] {
        if (!m_models->isLoading()) {
            loop.quit();
        }
    });
    loop.exec();
    disconnect(connection);
}

std::vector<scene::Warning> Viewport::correctModelWarnings(std::vector<scene::Warning> warnings) {
    m_models->prepare(m_scene);
    return m_models->correct(std::move(warnings), false);
}

void Viewport::adoptModel(const std::string& absolutePath,
                          std::shared_ptr<const scene::ImportedModel> model) {
    m_models->adopt(absolutePath, std::move(model));
}

void Viewport::setEditing(Selection* selection, QUndoStack* undoStack) {
    m_selection = selection;
    m_undoStack = undoStack;
    m_navigation.setUndoStack(undoStack);
    m_handles.setEditing(selection, undoStack);
    if (selection) {
        connect(selection, &Selection::changed, this, [this] {
            m_handles.clearHover();
            m_overlay->update();
        });
    }
}

void Viewport::setGuidesVisible(bool visible) {
    m_overlay->setGuidesVisible(visible);
}

bool Viewport::guidesVisible() const {
    return m_overlay->guidesVisible();
}

void Viewport::setScreenSpaceSourcesVisible(bool visible) {
    if (visible == m_screenSpaceSources)
        return;
    m_screenSpaceSources = visible;
    update();
}

void Viewport::setAdaptiveResolution(bool on) {
    if (on == m_adaptive) {
        return;
    }
    m_adaptive = on;
    if (!on && lastFrameReduced()) {
        update(); // what is shown was a preview: draw it whole now
    }
}

void Viewport::setPreviewFrameBudget(double milliseconds) {
    m_resolution.setBudget(milliseconds);
}

void Viewport::interacted() {
    if (!m_interacting) {
        m_interacting = true;
        // A gesture starts at the level the last one ended at, unless the widget has changed size since.
        if (m_previewSizeFor != size()) {
            m_resolution.forget();
            m_previewSizeFor = size();
        }
        m_resolution.begin(m_fullFrameMs);
    }
    m_rest.start();
}

void Viewport::rested() {
    m_interacting = false;
    if (lastFrameReduced()) {
        update(); // the frame at full quality
    }
}

void Viewport::frameOnScreen() {
    if (!m_timingFrame) {
        return;
    }
    m_timingFrame = false;
    // From the start of paintGL until the window has shown the frame: drawing and composition.
    const double totalMs = double(m_frameClock.nsecsElapsed()) * 1e-6;
    if (m_learning) {
        m_resolution.learn(m_lastFrameMs, totalMs, m_maxDepthCut);
    } else {
        m_fullFrameMs = totalMs;
    }
}

void Viewport::updateTicking() {
    m_sceneAnimated = scene::sceneHasAnimation(m_scene);
    // A clock running over a scene where nothing moves draws nothing new: no frames then.
    if (m_clock.isPlaying() && m_sceneAnimated) {
        m_tick.start();
    } else {
        m_tick.stop();
    }
}

void Viewport::initializeGL() {
    // The context can be replaced (e.g. when the widget moves to another top-level window); the old one's
    // objects must go while it is still current.
    releaseGlResources();
    m_rendererError.clear();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGlResources,
            Qt::UniqueConnection);

    const QSurfaceFormat format = context()->format();
    // Asked once per context (Qt keeps the list): paintGL relies on it for every frame.
    m_skipsSrgbDecode = context()->hasExtension(QByteArrayLiteral("GL_EXT_texture_sRGB_decode"));
    if (!context()->isValid() || format.version() < qMakePair(3, 3)) {
        m_rendererError = tr("This viewport needs OpenGL 3.3; the system provides OpenGL %1.%2.")
                              .arg(format.majorVersion())
                              .arg(format.minorVersion());
    }
    if (m_rendererError.isEmpty()) {
        auto renderer = render::Renderer::create();
        if (renderer) {
            m_renderer = std::move(*renderer);
            m_renderer->setCoarseLevelRequest(
                [this](const std::vector<render::MeshHandle>& meshes) { m_coarseLevels->request(meshes); });
        } else {
            m_rendererError =
                tr("The renderer could not start: %1").arg(QString::fromStdString(renderer.error()));
        }
    }
    if (!m_rendererError.isEmpty()) {
        qWarning("Viewport: %s", qPrintable(m_rendererError));
        emit rendererFailed(m_rendererError);
    }
}

void Viewport::releaseGlResources() {
    if (!m_renderer) {
        return;
    }
    makeCurrent();
    m_renderer->releaseGlResources();
    m_renderer.reset();
    doneCurrent();
}

void Viewport::paintGL() {
    if (!m_renderer) {
        paintError();
        return;
    }
    frameOnScreen(); // the last frame, when its composition was never reported: timed by its drawing
    m_frameClock.start();
    const double time = m_clock.time();
    std::vector<scene::Warning> warnings;
    // Model files are read on workers (ViewportModels), never here: a file still loading draws nothing yet.
    m_models->prepare(m_scene);
    render::FrameInput input = scene::snapshot(m_scene, time, m_meshes, warnings);
    warnings = m_models->correct(std::move(warnings));
    input.camera = m_navigation.camera();

    const bool previewing = m_adaptive && m_interacting;
    const view::PreviewLevel level = previewLevel(previewing, input.settings.mirrorDepth);
    // Qt draws the widget's texture into the window as it would a plain one: it must read the stored,
    // encoded bytes. Where it cannot, the frame goes through the renderer's own buffer and a copy.
    const bool composedAsStored =
        m_skipsSrgbDecode && render::composeSrgbTextureAsStored(defaultFramebufferObject());
    render::RenderOptions options;
    // A handle drag changes what casts shadows every frame, so the preview draws the shadow maps smaller.
    options.preview = {level.scale, level.mirrorDepthCut,
                       m_handles.press() == ViewportHandles::Press::Handle};
    if (m_overlay->guidesVisible())
        options.guides = guideLines();
    options.guides.insert(options.guides.end(), m_inspectionGuides.begin(), m_inspectionGuides.end());
    options.showScreenSpaceSources = m_screenSpaceSources;
    // The view stays interactive whatever the reflector's settings: a map that would take longer is drawn
    // smaller while editing (a warning says so); Export Still draws it as the scene asks.
    options.maxMapSeconds = render::kInteractiveMapSeconds;
    m_lastReport = m_renderer->render(input, frameTarget(composedAsStored), options);
    // A map did not fit at its planned size: the next frame draws it at one that does. A time-sliced map
    // draws its next face.
    if (m_lastReport.drawAgain || m_lastReport.mapSettling)
        QTimer::singleShot(0, this, qOverload<>(&Viewport::update));
    m_lastFrameMs = double(m_frameClock.nsecsElapsed()) * 1e-6;
    m_lastFrameTime = time;
    m_lastLevel = level;
    m_lastDrawnSize = QSize(m_lastReport.drawnWidth, m_lastReport.drawnHeight);
    m_learning = previewing;
    m_timingFrame = true; // until frameSwapped
    ++m_framesRendered;

    countFrame();
    reportFrameWarnings(composedAsStored, warnings);
    m_overlay->update(); // handles follow animated nodes
    emit frameRendered(m_lastReport, time);
}

// The guides the renderer draws in the frame, behind what stands in front of them: the ground grid and the
// scene camera. (The pivot, the axes in the corner and the handles are painted over the frame.)
std::vector<render::GuideLine> Viewport::guideLines() const {
    const render::Camera& view = m_navigation.camera();
    std::vector<render::GuideLine> lines = groundGrid(view).lines;
    const double aspect = double(width()) / std::max(height(), 1);
    addCameraGizmoGuides(sceneCamera(), view, aspect, lines);
    return lines;
}

// The level of a preview while navigating: fewer pixels, then fewer mirror levels (of the scene's
// `mirrorDepth`, down to one). The renderer's planner applies it (render::PreviewPolicy). The frame at rest
// draws everything.
view::PreviewLevel Viewport::previewLevel(bool previewing, int mirrorDepth) {
    m_maxDepthCut = std::max(0, mirrorDepth - 1);
    view::PreviewLevel level = previewing ? m_resolution.level() : view::PreviewLevel{};
    level.mirrorDepthCut = std::clamp(level.mirrorDepthCut, 0, m_maxDepthCut);
    return level;
}

// The widget's own FBO (framebuffer 0 is not ours), in device pixels. The frame is drawn straight into
// its sRGB texture when the window composes that texture as stored and it has depth and stencil.
render::RenderTarget Viewport::frameTarget(bool composedAsStored) const {
    const qreal dpr = devicePixelRatioF();
    render::RenderTarget target{defaultFramebufferObject(), qRound(width() * dpr), qRound(height() * dpr),
                                true};
    const QSurfaceFormat format = context()->format();
    target.srgbDepthStencil = textureFormat() == kSrgbTextureFormat && composedAsStored &&
                              format.depthBufferSize() >= 24 && format.stencilBufferSize() >= 8;
    return target;
}

// Frames per second, over each second of drawing.
void Viewport::countFrame() {
    if (!m_fpsTimer.isValid()) {
        m_fpsTimer.start();
    }
    ++m_fpsFrames;
    if (m_fpsTimer.elapsed() >= 1000) {
        m_fps = m_fpsFrames * 1000.0 / double(m_fpsTimer.elapsed());
        m_fpsFrames = 0;
        m_fpsTimer.restart();
    }
}

// The frame's warnings: the viewport's own, the snapshot's and the renderer's.
void Viewport::reportFrameWarnings(bool composedAsStored, const std::vector<scene::Warning>& warnings) {
    QStringList all;
    if (textureFormat() == kSrgbTextureFormat && !composedAsStored) {
        all << tr("The viewport may look darker than the scene: this GPU cannot show its sRGB buffer as "
                  "stored (no EXT_texture_sRGB_decode). Stills are not affected.");
    }
    for (const scene::Warning& w : warnings) {
        all << QString::fromStdString(w.message);
    }
    for (const auto& w : m_lastReport.warnings) {
        all << QString::fromStdString(w);
    }
    reportWarnings(std::move(all));
}

void Viewport::resizeEvent(QResizeEvent* event) {
    QOpenGLWidget::resizeEvent(event);
    m_overlay->setGeometry(rect());
}

void Viewport::paintError() {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(40, 20, 20));
    painter.setPen(Qt::white);
    const QString text = m_rendererError.isEmpty() ? tr("The viewport is not available.") : m_rendererError;
    painter.drawText(rect().adjusted(20, 20, -20, -20), Qt::AlignCenter | Qt::TextWordWrap, text);
}

void Viewport::reportWarnings(QStringList warnings) {
    if (warnings == m_warnings) {
        return;
    }
    m_warnings = std::move(warnings);
    emit warningsChanged(m_warnings);
}

} // namespace speculum::ui
