#pragma once

#include "render/frame/FrameInput.hpp"

#include <glm/vec3.hpp>

namespace speculum::view {

// The viewport's own camera: starts as the scene camera and is moved by the mouse (orbit around the
// target, pan, zoom) without touching the document, so looking around is not an undoable edit. It follows
// the scene camera again whenever that changes (reset()).
class ViewCamera {
public:
    void reset(const render::Camera& sceneCamera);
    const render::Camera& camera() const { return m_camera; }

    // Turns around the target: yaw about the up axis, pitch about the camera's right axis (degrees).
    // Positive yaw moves the camera to its left (the scene turns right); positive pitch raises the camera
    // towards the up pole (the view looks more from above). Pitch stops 2° short of the poles so the
    // view never flips.
    void orbit(double yawDegrees, double pitchDegrees);

    // A mouse drag of (dx, dy) pixels (y grows downwards, as in Qt and the DOM) in a view `viewHeight`
    // pixels high: a drag across the full height turns 180°. The scene follows the mouse, as in Blender's
    // turntable orbit and three.js OrbitControls: there handleMouseMoveRotate calls
    // rotateUp(2π·Δy/height) with Δy = now − before, and rotateUp(a) does `phi -= a`, phi being the
    // angle from +Y; so dragging DOWN shrinks phi and raises the camera (more from above), dragging UP
    // lowers it, and dragging right moves the camera to its left (rotateLeft: theta -= a). With
    // invertedVertical() the vertical half turns the other way (View ▸ Invert Vertical Orbit).
    void orbitByDrag(double dx, double dy, double viewHeight);
    void setInvertedVertical(bool inverted) { m_invertedVertical = inverted; }
    bool invertedVertical() const { return m_invertedVertical; }

    // Puts the view where a saved editor view was (the project's "editorView"): at `position` looking at
    // `target`, with the up vector, field of view and near plane it has (those of the scene camera after
    // reset()); the far plane grows as zoom() would grow it for that distance. Nothing happens when the
    // two points coincide.
    void place(const glm::dvec3& position, const glm::dvec3& target);
    // The same with an up vector of its own (a view preset's +Y); one parallel to the view direction, or
    // not finite, keeps the current one.
    void place(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up);
    // Moves camera and target in the view plane by a fraction of the visible height.
    void pan(double rightFraction, double upFraction);
    // Multiplies the distance to the target by factor (> 0).
    void zoom(double factor);
    // Looks at center from the current direction, close enough that a sphere of `radius` fills the view
    // (aspect = width / height; the narrower field of view decides). The far plane grows to keep it.
    void frame(const glm::dvec3& center, double radius, double aspect);

private:
    render::Camera m_camera;
    double m_baseDistance = 1.0; // distance of the scene camera, to stretch the far plane when zooming out
    double m_baseFar = 10.0;
    bool m_invertedVertical = false; // a preference: reset() keeps it
};

} // namespace speculum::view
