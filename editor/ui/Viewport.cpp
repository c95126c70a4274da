#include "editor/ui/Viewport.hpp"

#include "editor/document/Commands.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/ui/ViewportOverlay.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/math/Projection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneAnimation.hpp"

#include <QEventLoop>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QUndoStack>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

namespace speculum::ui {

using view::AnimationClock;
using view::Selection;

namespace {

constexpr int kMinPreviewShadowMap = 256; // texels a side: smaller shadows of a dragged object blur away
constexpr double kClickSlopPixels = 4.0;  // a press that moves less than this is a click, not a drag
constexpr double kLightPickPixels = 12.0;

const QColor kAxisColors[3] = {QColor(230, 70, 70), QColor(90, 200, 80), QColor(70, 130, 240)};
const QColor kActiveColor(255, 220, 60);
const QColor kSelectionColor(255, 150, 40);     // the current node's outline
const QColor kSelectedColor(190, 105, 35, 210); // the other selected nodes' outlines

// GL_SRGB8_ALPHA8 (the widget's texture format is a GL enum; no GL header is included here).
constexpr unsigned kSrgbTextureFormat = 0x8C43;

} // namespace

Viewport::Viewport(scene::Scene& scene, scene::MeshLibrary& meshes, AnimationClock& clock, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_scene(scene)
    , m_clock(clock)
    , m_meshes(meshes) {
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(true); // handle hover highlight
    setObjectName(QStringLiteral("viewport"));
    // An sRGB colour texture: the renderer draws a frame that needs no half-float buffer straight into it
    // (render::RenderTarget::srgbDepthStencil), with no copy; Qt composes it into the window as sRGB.
    setTextureFormat(kSrgbTextureFormat);
    m_view.reset(m_scene.camera());
    m_overlay = new ViewportOverlay(*this);
    m_models = new ViewportModels(m_meshes, this);
    connect(m_models, &ViewportModels::changed, this, qOverload<>(&Viewport::update));

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

scene::MeshLibrary& Viewport::meshes() {
    m_models->prepare(m_scene);
    return m_meshes;
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

std::vector<std::string> Viewport::correctModelWarnings(std::vector<std::string> warnings) {
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
    m_handleDrag = undoStack ? std::make_unique<HandleDrag>(m_scene, *undoStack) : nullptr;
    if (selection) {
        connect(selection, &Selection::changed, this, [this] {
            m_hoverAxis = -1;
            m_overlay->update();
        });
    }
}

void Viewport::setHandleMode(HandleMode mode) {
    if (mode == m_handleMode) {
        return;
    }
    m_handleMode = mode;
    m_hoverAxis = -1;
    m_overlay->update();
    emit handleModeChanged(mode);
}

void Viewport::setLookThroughSceneCamera(bool on) {
    m_sceneCameraMode = on;
    if (on) {
        resetView();
    }
}

void Viewport::resetView() {
    m_view.reset(m_scene.camera());
    update();
}

render::Camera Viewport::sceneCamera() const {
    return m_scene.camera();
}

void Viewport::setViewCamera(const render::Camera& camera) {
    ++m_gestureSerial; // a step of its own when it edits the scene camera
    m_view.place(camera.position, camera.target, camera.up);
    navigated();
}

std::pair<glm::dvec3, glm::dvec3> Viewport::viewPositionTarget() const {
    return {m_view.camera().position, m_view.camera().target};
}

void Viewport::placeView(const glm::dvec3& position, const glm::dvec3& target) {
    m_view.place(position, target);
    update();
}

void Viewport::setGuidesVisible(bool visible) {
    m_overlay->setGuidesVisible(visible);
}

bool Viewport::guidesVisible() const {
    return m_overlay->guidesVisible();
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

void Viewport::frameSelected() {
    m_models->prepare(m_scene);
    const double t = m_clock.time();
    const auto worlds = scene::worldMatrices(m_scene, t);
    render::math::Box box;
    std::vector<std::string> ignored;
    // What a node draws (its mesh, its mirror), without its children; false when it draws nothing.
    auto addOwn = [&](const scene::Node& node) {
        const auto it = worlds.find(node.id());
        if (it == worlds.end()) {
            return false;
        }
        const scene::NodeData& d = node.data();
        const glm::dmat4& world = it->second;
        bool added = false;
        if (d.mesh) {
            if (auto mesh = m_meshes.get(*d.mesh, ignored)) {
                box.add(render::math::worldBounds(scene::meshBounds(*mesh), world));
                added = true;
            }
        }
        if (d.mirror) {
            const glm::vec2 h = glm::vec2(d.mirror->size * 0.5);
            box.add(render::math::worldBounds(render::Bounds{{-h.x, 0.0f, -h.y}, {h.x, 0.0f, h.y}}, world));
            added = true;
        }
        return added;
    };
    // A selected group (an imported model's root) frames everything under it.
    std::function<bool(const scene::Node&)> addSubtree = [&](const scene::Node& node) {
        bool added = addOwn(node);
        for (const auto& child : node.children()) {
            added = addSubtree(*child) || added;
        }
        return added;
    };
    auto addNode = [&](const scene::Node& node) {
        if (!addSubtree(node)) {
            const auto it = worlds.find(node.id());
            if (it == worlds.end()) {
                return;
            }
            const glm::dvec3 p(it->second[3]);
            box.add(p - glm::dvec3(0.5));
            box.add(p + glm::dvec3(0.5));
        }
    };
    bool any = false;
    if (m_selection) {
        for (scene::NodeId id : m_selection->nodes()) {
            if (const scene::Node* node = m_scene.findNode(id)) {
                addNode(*node);
                any = true;
            }
        }
    }
    if (!any) {
        for (const auto& node : m_scene.topLevelNodes()) {
            addNode(*node);
        }
    }
    if (box.empty()) {
        return;
    }
    const double radius = std::max(glm::length(box.max - box.min) * 0.5, 1e-3);
    m_view.frame(box.center(), radius, double(width()) / std::max(height(), 1));
    navigated();
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
    std::vector<std::string> warnings;
    // Model files are read on workers (ViewportModels), never here: a file still loading draws nothing yet.
    m_models->prepare(m_scene);
    render::FrameInput input = scene::snapshot(m_scene, time, m_meshes, warnings);
    warnings = m_models->correct(std::move(warnings));
    input.camera = m_view.camera();

    // A preview while navigating: fewer pixels, scaled up by the renderer, then fewer mirror levels; the
    // environment map keeps what it has (an orbit never changes it; a handle drag would redraw it every
    // frame). The frame at rest draws everything.
    const bool previewing = m_adaptive && m_interacting;
    const int depth = input.settings.mirrorDepth;
    m_maxDepthCut = std::max(0, depth - 1);
    view::PreviewLevel level = previewing ? m_resolution.level() : view::PreviewLevel{};
    level.mirrorDepthCut = std::clamp(level.mirrorDepthCut, 0, m_maxDepthCut);
    if (level.reduced()) {
        input.settings.mirrorDepth = depth - level.mirrorDepthCut;
        if (input.reflector && input.reflector->update != render::ReflectorUpdate::Once) {
            input.reflector->update = render::ReflectorUpdate::Once; // drawn only when there is no map yet
        }
        // A handle drag changes what casts shadows every frame, so each shadow map is drawn again anyway:
        // at a size that goes with the preview's (a power of two less, never under 256²). Orbiting reuses
        // the maps as they are.
        if (m_drag == Drag::Handle) {
            for (render::Light& light : input.lights) {
                if (!light.shadows)
                    continue;
                int size = light.shadows->mapSize;
                for (double s = level.scale; s <= 0.5 && size > kMinPreviewShadowMap; s *= 2.0) {
                    size /= 2;
                }
                light.shadows->mapSize = std::min(light.shadows->mapSize, std::max(size, kMinPreviewShadowMap));
            }
        }
    }

    // The widget draws into its own FBO; framebuffer 0 is not ours.
    const qreal dpr = devicePixelRatioF();
    render::RenderTarget target{defaultFramebufferObject(), qRound(width() * dpr), qRound(height() * dpr),
                                true};
    // Qt draws the widget's texture into the window as it would a plain one: it must read the stored,
    // encoded bytes. Where it cannot, the frame goes through the renderer's own buffer and a copy.
    const QSurfaceFormat format = context()->format();
    const bool composedAsStored =
        m_skipsSrgbDecode && render::composeSrgbTextureAsStored(defaultFramebufferObject());
    target.srgbDepthStencil = textureFormat() == kSrgbTextureFormat && composedAsStored &&
                              format.depthBufferSize() >= 24 && format.stencilBufferSize() >= 8;
    render::RenderOptions options;
    options.resolutionScale = level.scale;
    m_lastReport = m_renderer->render(input, target, options);
    m_lastFrameMs = double(m_frameClock.nsecsElapsed()) * 1e-6;
    m_lastFrameTime = time;
    m_lastLevel = level;
    m_lastDrawnSize = QSize(m_lastReport.drawnWidth, m_lastReport.drawnHeight);
    m_learning = previewing;
    m_timingFrame = true; // until frameSwapped
    ++m_framesRendered;

    if (!m_fpsTimer.isValid()) {
        m_fpsTimer.start();
    }
    ++m_fpsFrames;
    if (m_fpsTimer.elapsed() >= 1000) {
        m_fps = m_fpsFrames * 1000.0 / double(m_fpsTimer.elapsed());
        m_fpsFrames = 0;
        m_fpsTimer.restart();
    }

    QStringList all;
    if (textureFormat() == kSrgbTextureFormat && !composedAsStored) {
        all << tr("The viewport may look darker than the scene: this GPU cannot show its sRGB buffer as "
                  "stored (no EXT_texture_sRGB_decode). Stills are not affected.");
    }
    for (const auto& w : warnings) {
        all << QString::fromStdString(w);
    }
    for (const auto& w : m_lastReport.warnings) {
        all << QString::fromStdString(w);
    }
    reportWarnings(std::move(all));
    m_overlay->update(); // handles follow animated nodes
    emit frameRendered(m_lastReport, time);
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

ScreenProjection Viewport::projection() const {
    return ScreenProjection(m_view.camera(), QSizeF(width(), height()));
}

void Viewport::updateGizmo() {
    const scene::Node* node = m_selection ? m_selection->selectedNode() : nullptr;
    if (!node || !m_undoStack) {
        m_gizmo = Gizmo{};
        return;
    }
    const double t = m_lastFrameTime;
    const glm::dmat4 parent = scene::parentWorldMatrix(m_scene, node->id(), t);
    const glm::dmat4 world = parent * scene::animatedLocalMatrix(node->data(), t);
    m_gizmo.setUp(m_handleMode, projection(), parent, world);
}

std::optional<QPointF> Viewport::handlePoint(int axis) {
    updateGizmo();
    if (!m_gizmo.isValid() || axis < 0 || axis > 2) {
        return std::nullopt;
    }
    const auto& line = m_gizmo.axes()[std::size_t(axis)].line;
    if (line.empty()) {
        return std::nullopt;
    }
    // The tip of a segment, or the ring point nearest the bottom of the screen (least likely hidden).
    if (m_handleMode != HandleMode::Rotate) {
        const QPointF tip = line.back();
        return line.front() + (tip - line.front()) * 0.9;
    }
    return *std::max_element(line.begin(), line.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
}

std::uint64_t Viewport::pickAt(QPointF position, bool mirrorItself) {
    const double t = m_lastFrameTime;
    const ScreenProjection screen = projection();
    // Lights have no surface: they are picked by their marker.
    std::uint64_t light = 0;
    double nearest = kLightPickPixels;
    const auto worlds = scene::worldMatrices(m_scene, t);
    m_scene.forEachNode([&](const scene::Node& node) {
        if (!node.data().light) {
            return;
        }
        if (auto p = screen.project(glm::dvec3(worlds.at(node.id())[3]))) {
            const double d = std::hypot(p->x() - position.x(), p->y() - position.y());
            if (d < nearest) {
                nearest = d;
                light = node.id();
            }
        }
    });
    if (light) {
        return light;
    }
    m_models->prepare(m_scene);
    scene::PickScene pickScene = scene::buildPickScene(m_scene, t, m_meshes);
    if (mirrorItself) {
        pickScene.mirrorDepth = 0;
    }
    const double w = std::max(width(), 1), h = std::max(height(), 1);
    const scene::Ray ray =
        scene::cameraRay(m_view.camera(), w / h, position.x() / w * 2.0 - 1.0, 1.0 - position.y() / h * 2.0);
    const auto hit = scene::pick(pickScene, ray);
    return hit ? hit->id : 0;
}

void Viewport::paintOverlay(QPainter& painter) {
    m_models->prepare(m_scene);
    if (!m_renderer) {
        return;
    }
    const ScreenProjection screen = projection();
    const double t = m_lastFrameTime;
    const auto worlds = scene::worldMatrices(m_scene, t);

    // Light markers: lights have no surface in the frame, so show where they are.
    m_scene.forEachNode([&](const scene::Node& node) {
        if (!node.data().light) {
            return;
        }
        if (auto p = screen.project(glm::dvec3(worlds.at(node.id())[3]))) {
            const glm::dvec3 c = glm::clamp(node.data().light->color, 0.0, 1.0);
            painter.setPen(QPen(QColor(30, 30, 30, 200), 1.0));
            painter.setBrush(QColor::fromRgbF(float(c.r), float(c.g), float(c.b)));
            painter.drawEllipse(*p, 5.0, 5.0);
            painter.setPen(QPen(QColor(255, 210, 60), 1.5));
            for (int i = 0; i < 8; ++i) {
                const double a = i * 3.14159265358979 / 4.0;
                painter.drawLine(*p + QPointF(std::cos(a), std::sin(a)) * 7.0,
                                 *p + QPointF(std::cos(a), std::sin(a)) * 11.0);
            }
        }
    });

    if (!m_selection) {
        return;
    }
    // Selection outlines: each selected node's local box (mesh bounds, or the mirror rectangle) in world
    // space; the current node's is brighter and drawn last, on top.
    std::vector<std::string> ignored;
    for (scene::NodeId id : m_selection->nodes()) {
        const scene::Node* node = m_scene.findNode(id);
        const auto found = worlds.find(id);
        if (!node || found == worlds.end()) {
            continue;
        }
        const glm::dmat4& world = found->second;
        const scene::NodeData& d = node->data();
        std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
        auto addBox = [&](glm::dvec3 lo, glm::dvec3 hi) {
            glm::dvec3 c[8];
            for (int i = 0; i < 8; ++i) {
                c[i] = glm::dvec3(world * glm::dvec4((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                                     (i & 4) ? hi.z : lo.z, 1.0));
            }
            static const int pairs[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                             {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
            for (const auto& p : pairs) {
                edges.emplace_back(c[p[0]], c[p[1]]);
            }
        };
        if (d.mesh) {
            if (auto mesh = m_meshes.get(*d.mesh, ignored)) {
                const render::Bounds b = scene::meshBounds(*mesh);
                addBox(glm::dvec3(b.min), glm::dvec3(b.max));
            }
        }
        if (d.mirror) {
            const glm::dvec2 h = d.mirror->size * 0.5;
            addBox({-h.x, 0.0, -h.y}, {h.x, 0.0, h.y});
        }
        const bool current = id == m_selection->node();
        painter.setPen(QPen(current ? kSelectionColor : kSelectedColor, current ? 1.5 : 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        for (const auto& [a, b] : edges) {
            const auto pa = screen.project(a), pb = screen.project(b);
            if (pa && pb) {
                painter.drawLine(*pa, *pb);
            }
        }
    }

    // Handles: on the current node only (a drag carries over to the rest of the selection).
    if (!m_undoStack) {
        return;
    }
    updateGizmo();
    const bool dragging = m_drag == Drag::Handle && m_handleDrag;
    const Gizmo& gizmo = dragging ? m_handleDrag->gizmo() : m_gizmo;
    if (!gizmo.isValid()) {
        return;
    }
    const int active = dragging ? m_handleDrag->axis() : m_hoverAxis;
    for (const auto& axis : gizmo.axes()) {
        const QColor color = axis.index == active ? kActiveColor : kAxisColors[axis.index];
        painter.setPen(QPen(color, axis.index == active ? 3.5 : 2.5, Qt::SolidLine, Qt::RoundCap));
        painter.setBrush(Qt::NoBrush);
        if (axis.line.size() < 2) {
            continue;
        }
        painter.drawPolyline(axis.line.data(), int(axis.line.size()));
        if (gizmo.mode() == HandleMode::Move || gizmo.mode() == HandleMode::Scale) {
            const QPointF tip = axis.line.back();
            painter.setBrush(color);
            if (gizmo.mode() == HandleMode::Scale) {
                painter.drawRect(QRectF(tip - QPointF(4.5, 4.5), QSizeF(9, 9)));
            } else {
                const QPointF dir = tip - axis.line.front();
                const double len = std::hypot(dir.x(), dir.y());
                if (len > 1.0) {
                    const QPointF u = dir / len, n(-u.y(), u.x());
                    const QPointF head[3] = {tip + u * 10.0, tip + n * 5.0, tip - n * 5.0};
                    painter.drawPolygon(head, 3);
                }
            }
        }
    }
    painter.setPen(QPen(Qt::white, 1.5));
    painter.setBrush(QColor(40, 40, 40));
    painter.drawEllipse(gizmo.origin(), 3.5, 3.5);
}

void Viewport::navigated() {
    if (m_sceneCameraMode && m_undoStack) {
        // Looking through the scene camera: the navigation is an edit of the document's camera.
        scene::CameraData camera = m_scene.camera();
        const render::Camera& v = m_view.camera();
        camera.position = v.position;
        camera.target = v.target;
        camera.up = v.up;
        camera.far = std::min(std::max(camera.far, v.far), camera.near * render::kMaxFarNearRatio);
        auto* command = new document::SetCameraCommand(m_scene, camera, true);
        command->setMergeKey(QStringLiteral("navigate#%1").arg(m_gestureSerial));
        document::pushEdit(*m_undoStack, command); // an orbit that ends where it began is no step
    }
    update();
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    const QPointF pos = event->position();
    const bool pan = event->button() == Qt::MiddleButton ||
                     (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    ++m_gestureSerial;
    if (pan) {
        m_drag = Drag::Pan;
    } else if (event->button() == Qt::LeftButton) {
        updateGizmo();
        // Ctrl+click always picks (to add or remove), even over a handle.
        const bool ctrl = event->modifiers() & Qt::ControlModifier;
        const int axis = m_selection && m_undoStack && !ctrl ? m_gizmo.hitTest(pos) : -1;
        if (axis >= 0 && m_handleDrag->press(m_gizmo, axis, pos, m_selection->node(), m_selection->roots(),
                                             m_lastFrameTime)) {
            m_drag = Drag::Handle;
        } else {
            m_drag = Drag::PendingClick;
        }
        m_pressPosition = pos;
        m_pressAlt = event->modifiers() & Qt::AltModifier;
        m_pressCtrl = event->modifiers() & Qt::ControlModifier;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    m_lastMouse = pos.toPoint();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF posF = event->position();
    if (m_drag == Drag::None) {
        if (m_selection && m_undoStack) {
            updateGizmo();
            const int hover = m_gizmo.hitTest(posF);
            if (hover != m_hoverAxis) {
                m_hoverAxis = hover;
                setCursor(hover >= 0 ? Qt::PointingHandCursor : Qt::ArrowCursor);
                m_overlay->update();
            }
        }
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    if (m_drag == Drag::Handle) {
        interacted();
        m_handleDrag->move(posF);
        event->accept();
        return;
    }
    if (m_drag == Drag::PendingClick) {
        if (std::hypot(posF.x() - m_pressPosition.x(), posF.y() - m_pressPosition.y()) < kClickSlopPixels) {
            event->accept();
            return;
        }
        m_drag = Drag::Orbit;
    }
    const QPoint pos = posF.toPoint();
    const QPoint delta = pos - m_lastMouse;
    m_lastMouse = pos;
    if (m_drag == Drag::Orbit) {
        // The scene follows the mouse (Blender, three.js), unless View ▸ Invert Vertical Orbit is on.
        m_view.orbitByDrag(delta.x(), delta.y(), double(height()));
    } else {
        const double perPixel = 1.0 / std::max(height(), 1);
        m_view.pan(-delta.x() * perPixel, delta.y() * perPixel);
    }
    interacted();
    navigated();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    if (m_drag == Drag::PendingClick && m_selection) {
        const std::uint64_t id = pickAt(m_pressPosition, m_pressAlt);
        if (m_pressCtrl) {
            // Ctrl+click adds or removes; Ctrl+click on nothing keeps the selection.
            m_selection->toggleNode(scene::NodeId(id));
        } else if (id) {
            m_selection->selectNode(scene::NodeId(id));
        } else {
            m_selection->clear();
        }
    }
    if (m_drag == Drag::Handle) {
        m_handleDrag->release();
    }
    m_drag = Drag::None;
    m_overlay->update();
    event->accept();
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        resetView();
        event->accept();
    }
}

void Viewport::wheelEvent(QWheelEvent* event) {
    // One notch (120 units) moves 15% closer or farther.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        m_view.zoom(std::pow(0.85, notches));
        interacted();
        navigated();
    }
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_drag == Drag::Handle) {
        // Cancel the drag: every node back as it was, and no undo step left behind.
        m_handleDrag->cancel();
        m_drag = Drag::None;
        m_overlay->update();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace speculum::ui
