#pragma once

#include "render/FrameInput.hpp"

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
    // Pitch stops short of the poles so the view never flips.
    void orbit(double yawDegrees, double pitchDegrees);
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
};

} // namespace speculum::view
