// Viewport: input. The mouse, the wheel and the keys handed on to navigation (ViewportNavigation) and to
// picking and the handles (ViewportHandles), and the public calls that move the view or ask the handles,
// each followed by the repaint, the cursor or the preview (adaptive resolution) it calls for.
#include "editor/ui/Viewport.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/ui/ViewportOverlay.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

namespace speculum::ui {

void Viewport::setLookThroughSceneCamera(bool on) {
    m_navigation.setLookThroughSceneCamera(on);
    if (on) {
        update();
    }
}

void Viewport::resetView() {
    m_navigation.reset();
    update();
}

render::Camera Viewport::sceneCamera() const {
    return m_scene.camera();
}

void Viewport::setViewCamera(const render::Camera& camera) {
    m_navigation.setCamera(camera);
    update();
}

void Viewport::orbitView(double yawDegrees, double pitchDegrees) {
    m_navigation.orbitStep(yawDegrees, pitchDegrees);
    update();
}

void Viewport::zoomView(double notches) {
    m_navigation.zoomStep(notches);
    update();
}

std::pair<glm::dvec3, glm::dvec3> Viewport::viewPositionTarget() const {
    return m_navigation.positionTarget();
}

void Viewport::placeView(const glm::dvec3& position, const glm::dvec3& target) {
    m_navigation.place(position, target);
    update();
}

void Viewport::frameSelected() {
    m_models->prepare(m_scene);
    if (m_navigation.frameSelected(m_selection, m_meshes, m_clock.time(), size())) {
        update();
    }
}

void Viewport::setHandleMode(HandleMode mode) {
    if (!m_handles.setMode(mode)) {
        return;
    }
    m_overlay->update();
    emit handleModeChanged(mode);
}

ScreenProjection Viewport::projection() const {
    return ScreenProjection(m_navigation.camera(), QSizeF(width(), height()));
}

ViewOnScreen Viewport::viewOnScreen() const {
    return {projection(), m_lastFrameTime};
}

std::optional<QPointF> Viewport::handlePoint(int axis) {
    return m_handles.handlePoint(axis, viewOnScreen());
}

std::uint64_t Viewport::pickAt(QPointF position, bool mirrorItself) {
    return m_handles.pickAt(position, mirrorItself, viewOnScreen());
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    const QPointF position = event->position();
    const bool left = event->button() == Qt::LeftButton;
    const bool pan =
        event->button() == Qt::MiddleButton || (left && (event->modifiers() & Qt::ShiftModifier));
    if (left && m_inspecting && event->modifiers() == Qt::NoModifier) {
        inspectAt(position);
        event->accept();
        return;
    }
    m_navigation.beginGesture();
    // A press of the pan or the left button ends whatever gesture the last one started, finishing nothing.
    if (pan) {
        m_handles.forgetPress();
        m_navigation.beginDrag(ViewportNavigation::Drag::Pan, position.toPoint());
    } else if (left) {
        m_navigation.endDrag();
        m_handles.press(position, event->modifiers(), viewOnScreen());
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF position = event->position();
    if (m_handles.press() == ViewportHandles::Press::Handle) {
        interacted();
        m_handles.dragHandle(position, m_snap.forDrag(event->modifiers().testFlag(Qt::ControlModifier)));
        event->accept();
        return;
    }
    if (m_handles.press() == ViewportHandles::Press::PendingClick) {
        if (!m_handles.leavesClick(position)) {
            event->accept();
            return;
        }
        // A left drag away from the handles orbits, from where the button went down.
        m_navigation.beginDrag(ViewportNavigation::Drag::Orbit, m_handles.pressPosition().toPoint());
    }
    if (m_navigation.isDragging()) {
        m_navigation.dragTo(position.toPoint(), height());
        interacted();
        update();
        event->accept();
        return;
    }
    if (m_handles.hover(position, viewOnScreen())) {
        setCursor(m_handles.hoverAxis() >= 0 ? Qt::PointingHandCursor : Qt::ArrowCursor);
        m_overlay->update();
    }
    QOpenGLWidget::mouseMoveEvent(event);
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    const bool navigating = m_navigation.endDrag();
    const bool pressed = m_handles.release(viewOnScreen());
    if (!navigating && !pressed) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
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
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        m_navigation.zoom(notches);
        interacted();
        update();
    }
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_handles.cancelHandleDrag()) {
        m_overlay->update();
        event->accept();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace speculum::ui
