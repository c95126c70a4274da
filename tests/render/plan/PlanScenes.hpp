#pragma once
// Small scenes the planner tests share: mirrors facing a camera at the origin that looks down −Z; and what
// they look up in a plan.
#include "render/frame/FrameInput.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/FramePlan.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>
#include <string>

namespace speculum::render::test {

// A 2 × 2 (or size × size) mirror in the plane z = zPlane facing +Z (or −Z).
inline Mirror wall(const std::string& name, double zPlane, bool facingPlusZ = true, double size = 2.0) {
    Mirror m;
    m.name = name;
    m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, zPlane)),
                          glm::radians(facingPlusZ ? 90.0 : -90.0), glm::dvec3(1, 0, 0));
    m.size = {size, size};
    return m;
}

// A sphere reflector of this roughness ("Ball") at the origin beside a box, seen from +Z.
inline FrameInput roughBall(double roughness, GlossyFilter filter = GlossyFilter::Footprint) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 5.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 50.0;
    static const auto box = std::make_shared<const MeshData>(makeBox());
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(16));
    input.items.push_back({"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)), box, {}, true});
    input.settings.glossyFilter = filter;
    Reflector r;
    r.name = "Ball";
    r.mesh = sphere;
    r.roughness = roughness;
    input.reflectors = {r};
    return input;
}

inline FrameInput cameraAtOrigin() {
    FrameInput input;
    input.camera.position = {0, 0, 0};
    input.camera.target = {0, 0, -1};
    input.camera.far = 100.0;
    return input;
}

// The first pass of this kind the plan holds, or null.
inline const PlannedPass* passOf(const FramePlan& plan, PassKind kind) {
    for (const PlannedPass& pass : plan.passes)
        if (pass.kind == kind)
            return &pass;
    return nullptr;
}

// The code of the plan's first skip of `target`, or none.
inline std::optional<PlanReason> skipCode(const FramePlan& plan, const std::string& target) {
    for (const SkippedEffect& s : plan.skipped)
        if (s.target == target)
            return s.code;
    return std::nullopt;
}

// The reason the plan gives for the first skip of `target`, or nothing.
inline std::string skipReason(const FramePlan& plan, const std::string& target) {
    for (const SkippedEffect& s : plan.skipped)
        if (s.target == target)
            return s.reason();
    return {};
}

} // namespace speculum::render::test
