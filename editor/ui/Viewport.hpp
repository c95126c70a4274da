#pragma once

#include "editor/document/MeshLibrary.hpp"
#include "editor/ui/ViewCamera.hpp"
#include "render/Renderer.hpp"

#include <QOpenGLWidget>
#include <QPoint>
#include <QStringList>
#include <QTimer>
#include <memory>

namespace speculum::document {
class Scene;
}

namespace speculum::ui {

class AnimationClock;

// The live 3D view: draws a snapshot of the document every frame with render::Renderer into this widget's
// framebuffer object. All GL work happens inside render/; this class only manages the renderer's lifetime
// (created in initializeGL, freed on QOpenGLContext::aboutToBeDestroyed) and feeds it.
//
// Mouse: left drag orbits around the camera target, middle (or Shift+left) drag pans, the wheel zooms,
// double-click returns to the scene camera. This moves only the view's own camera, never the document.
class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    Viewport(document::Scene& scene, AnimationClock& clock, QWidget* parent = nullptr);
    ~Viewport() override;

    // Frames drawn since the widget was created (tests wait on this).
    int framesRendered() const { return m_framesRendered; }
    const render::FrameReport& lastReport() const { return m_lastReport; }
    double lastFrameTime() const { return m_lastFrameTime; }
    // Why the viewport cannot draw (no OpenGL 3.3, shader errors); empty when it can.
    const QString& rendererError() const { return m_rendererError; }

    // Back to the scene's camera after mouse navigation.
    void resetView();

    QSize sizeHint() const override { return {960, 600}; }

signals:
    // After every frame, with the renderer's report and the animation time it showed.
    void frameRendered(const speculum::render::FrameReport& report, double animationTime);
    // When the set of warnings (snapshot + renderer) differs from the previous frame's.
    void warningsChanged(const QStringList& warnings);
    void rendererFailed(const QString& message);

protected:
    void initializeGL() override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void releaseGlResources();
    void paintError();
    void updateTicking();
    void reportWarnings(QStringList warnings);

    document::Scene& m_scene;
    AnimationClock& m_clock;
    document::MeshLibrary m_meshes; // kept across frames: the renderer keys GPU meshes on the handles
    std::unique_ptr<render::Renderer> m_renderer;
    QString m_rendererError;
    ViewCamera m_view;
    QTimer m_tick; // drives repaints while the animation plays

    render::FrameReport m_lastReport;
    double m_lastFrameTime = 0.0;
    int m_framesRendered = 0;
    QStringList m_warnings;

    enum class Drag { None, Orbit, Pan };
    Drag m_drag = Drag::None;
    QPoint m_lastMouse;
};

} // namespace speculum::ui
