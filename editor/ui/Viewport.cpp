#include "editor/ui/Viewport.hpp"

#include "editor/document/Scene.hpp"
#include "editor/document/Snapshot.hpp"
#include "editor/ui/AnimationClock.hpp"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

namespace speculum::ui {

Viewport::Viewport(document::Scene& scene, AnimationClock& clock, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_scene(scene)
    , m_clock(clock) {
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    m_view.reset(document::toRender(m_scene.camera()));

    connect(&m_scene, &document::Scene::changed, this, qOverload<>(&Viewport::update));
    // A camera edit or a newly opened document: show the document's camera again.
    connect(&m_scene, &document::Scene::cameraChanged, this, &Viewport::resetView);
    connect(&m_scene, &document::Scene::sceneReset, this, [this] {
        m_meshes.clear(); // meshes of the old document are not needed any more
        resetView();
    });

    // ~60 fps while playing. A timer rather than update() from paintGL: Xvfb and some drivers do not
    // throttle swaps, and an unthrottled loop would starve the rest of the UI.
    m_tick.setInterval(16);
    m_tick.setTimerType(Qt::PreciseTimer);
    connect(&m_tick, &QTimer::timeout, this, qOverload<>(&Viewport::update));
    connect(&m_clock, &AnimationClock::playingChanged, this, &Viewport::updateTicking);
    connect(&m_clock, &AnimationClock::timeChanged, this, qOverload<>(&Viewport::update));
    updateTicking();
}

Viewport::~Viewport() {
    releaseGlResources();
}

void Viewport::resetView() {
    m_view.reset(document::toRender(m_scene.camera()));
    update();
}

void Viewport::updateTicking() {
    if (m_clock.isPlaying()) {
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
    const double time = m_clock.time();
    std::vector<std::string> warnings;
    render::FrameInput input = document::snapshot(m_scene, time, m_meshes, warnings);
    input.camera = m_view.camera();

    // The widget draws into its own FBO; framebuffer 0 is not ours.
    const qreal dpr = devicePixelRatioF();
    const render::RenderTarget target{defaultFramebufferObject(), qRound(width() * dpr),
                                      qRound(height() * dpr), true};
    m_lastReport = m_renderer->render(input, target);
    m_lastFrameTime = time;
    ++m_framesRendered;

    QStringList all;
    for (const auto& w : warnings) {
        all << QString::fromStdString(w);
    }
    for (const auto& w : m_lastReport.warnings) {
        all << QString::fromStdString(w);
    }
    reportWarnings(std::move(all));
    emit frameRendered(m_lastReport, time);
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

void Viewport::mousePressEvent(QMouseEvent* event) {
    const bool pan = event->button() == Qt::MiddleButton ||
                     (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (pan) {
        m_drag = Drag::Pan;
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::Orbit;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    m_lastMouse = event->position().toPoint();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPoint pos = event->position().toPoint();
    const QPoint delta = pos - m_lastMouse;
    m_lastMouse = pos;
    if (m_drag == Drag::Orbit) {
        // A drag across the full height turns the view by 180°.
        const double degreesPerPixel = 180.0 / std::max(height(), 1);
        m_view.orbit(delta.x() * degreesPerPixel, delta.y() * degreesPerPixel);
    } else {
        const double perPixel = 1.0 / std::max(height(), 1);
        m_view.pan(-delta.x() * perPixel, delta.y() * perPixel);
    }
    update();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    m_drag = Drag::None;
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
        update();
    }
    event->accept();
}

} // namespace speculum::ui
