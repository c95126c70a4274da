#pragma once

#include "render/frame/FrameInput.hpp"
#include "scene/model/SceneData.hpp"

#include <QPointF>
#include <QSizeF>
#include <array>
#include <glm/mat4x4.hpp>
#include <optional>
#include <vector>

namespace speculum::ui {

enum class HandleMode { Select, Move, Rotate, Scale };

// What a snapped handle drag rounds to (SnapSettings remembers the user's choice): a move to multiples of
// `move` (0: the ground grid's spacing where the handles are seen from, so the step follows the zoom), a
// turn to multiples of `rotate` degrees, a scale factor to multiples of `scale`.
struct SnapSteps {
    double move = 0.0;
    double rotate = 15.0;
    double scale = 0.1;
    bool operator==(const SnapSteps&) const = default;
};

// Projects world points to widget pixels with the renderer's own matrices (render/math/Projection.hpp),
// so overlays drawn with QPainter line up with the GL frame.
class ScreenProjection {
public:
    ScreenProjection() = default;
    ScreenProjection(const render::Camera& camera, QSizeF size);
    // Widget position (logical pixels, y down), or nothing when the point is behind the camera.
    std::optional<QPointF> project(const glm::dvec3& world) const;
    // World units per pixel at the depth of a point.
    double worldPerPixel(const glm::dvec3& world) const;
    const render::Camera& camera() const { return m_camera; }
    QSizeF size() const { return m_size; }

private:
    render::Camera m_camera;
    QSizeF m_size{1, 1};
    glm::dmat4 m_viewProjection{1.0};
};

// The move / rotate / scale handles of one node: geometry in widget pixels for drawing and hit-testing,
// and the node data a drag produces. Move works along the parent's axes (it edits translate), scale along
// the node's own axes (scale), rotate around the axes of the Euler angles (rotate x, y, z: rings drawn
// where each angle turns the node).
class Gizmo {
public:
    static constexpr double kHandlePixels = 90.0; // on-screen length of the axes
    static constexpr double kHitPixels = 7.0;
    static constexpr double kCentrePixels = 9.0; // around the origin: the uniform-scale handle

    struct Axis {
        int index = 0;             // 0 x, 1 y, 2 z
        std::vector<QPointF> line; // polyline: a segment (move, scale) or a ring (rotate)
        glm::dvec3 direction{0.0}; // world direction, unit
    };

    // Sets the handles up for a node. `parentWorld` is its parent's world matrix, `world` its own (with
    // animation applied, as drawn).
    void setUp(HandleMode mode, const ScreenProjection& projection, const glm::dmat4& parentWorld,
               const glm::dmat4& world);
    bool isValid() const { return m_valid; }
    HandleMode mode() const { return m_mode; }
    QPointF origin() const { return m_originPx; }
    const std::array<Axis, 3>& axes() const { return m_axes; }

    // The axis under a widget point, or -1.
    int hitTest(QPointF point) const;

    // The centre of the scale handles (hitTest, drag): scales the three axes together.
    static constexpr int kUniformAxis = 3;

    // The node data after dragging `axis` from `from` to `to` (widget pixels), starting from `start`. What
    // the drag changes is rounded to what a pixel can mean (a thousandth of the ground grid's spacing,
    // 0.01°, 4 significant digits of a scale), so no value carries the noise of the pixels' maths; with
    // `snap` to its steps (by default the ground grid's lines, 15° and scale factors in steps of 0.1).
    scene::NodeData drag(const scene::NodeData& start, int axis, QPointF from, QPointF to,
                         const std::optional<SnapSteps>& snap = std::nullopt) const;
    // The ground grid's spacing where the handles are seen from (ViewGrid's).
    double gridStep() const;

private:
    static double scaled(double scale, double factor, const std::optional<SnapSteps>& snap);
    bool m_valid = false;
    HandleMode m_mode = HandleMode::Select;
    ScreenProjection m_projection;
    glm::dmat4 m_parentWorld{1.0};
    glm::dvec3 m_origin{0.0};
    QPointF m_originPx;
    double m_length = 1.0; // world length of the axes
    std::array<Axis, 3> m_axes;
};

// Carries a handle drag of the node the handles sit on (from `leadStart` to `leadNow`, its parent's world
// matrix `leadParentWorld`) over to another selected node (`start`, `parentWorld`): Move shifts it by the
// same world-space displacement, expressed in its own parent's space; Rotate adds the same Euler-angle
// change, so it turns about its own origin; Scale multiplies each axis by the lead node's factor (an axis on
// which the lead node started at zero scale has no factor and stays as it is). Only the transform changes.
scene::NodeData followDrag(HandleMode mode, const scene::NodeData& leadStart, const scene::NodeData& leadNow,
                           const glm::dmat4& leadParentWorld, const scene::NodeData& start,
                           const glm::dmat4& parentWorld);

} // namespace speculum::ui
