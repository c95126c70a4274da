#include "render/plan/Planner.hpp"

#include "render/math/Projection.hpp"
#include "render/math/ShadowFrustum.hpp"
#include "render/plan/FrameHashing.hpp"

#include <bit>
#include <cstring>
#include <functional>

namespace speculum::render {

std::string_view toString(PassKind kind) {
    switch (kind) {
    case PassKind::Shadow:
        return "shadow";
    case PassKind::MirrorMask:
        return "mirror-mask";
    case PassKind::Mirror:
        return "mirror";
    case PassKind::MirrorSurface:
        return "mirror-surface";
    case PassKind::Envmap:
        return "envmap";
    case PassKind::Main:
        return "main";
    case PassKind::Composite:
        return "composite";
    }
    return "unknown";
}

namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string lightLabel(const Light& light, int index) {
    return light.name.empty() ? "light " + std::to_string(index) : light.name;
}

} // namespace

glm::dmat4 cameraProjection(const FrameInput& input, const PlanViewport& viewport) {
    const double aspect = double(std::max(viewport.width, 1)) / double(std::max(viewport.height, 1));
    const glm::dmat4 projection =
        math::perspective(input.camera.fovY, aspect, input.camera.near, input.camera.far);
    return math::jitter(projection, viewport.jitterPixels.x, viewport.jitterPixels.y,
                        std::max(viewport.width, 1), std::max(viewport.height, 1));
}

std::uint64_t shadowSignature(const FrameInput& input, int lightIndex) {
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    Hasher h;
    h.add(light.type);
    h.add(light.position);
    h.add(light.direction);
    h.add(light.spotAngle);
    h.add(light.shadows.mapSize);
    if (const auto frustum = math::shadowFrustum(input, light, light.shadows.mapSize)) {
        for (const auto& m : frustum->viewProjection)
            h.add(m);
        h.add(frustum->faceMask);
    }
    for (const DrawItem& item : input.items) {
        if (!item.castsShadows || !item.mesh)
            continue;
        h.add(item.mesh.get());
        h.add(item.world);
        addShadowAlpha(h, item.material); // masked casters cut holes into their shadows
    }
    if (input.reflector) {
        h.add(input.reflector->mesh.get());
        h.add(input.reflector->world);
    }
    return h.value;
}

FramePlan planFrame(const FrameInput& input, const PlannerState& state, const PlanViewport& viewport) {
    FramePlan plan;
    std::size_t casters = 0;
    for (const DrawItem& item : input.items)
        if (item.castsShadows && item.mesh)
            ++casters;
    if (input.reflector && input.reflector->mesh)
        ++casters;

    int shadowSlots = 0;
    const int lightCount = static_cast<int>(input.lights.size());
    for (int i = 0; i < lightCount; ++i) {
        const Light& light = input.lights[static_cast<std::size_t>(i)];
        const std::string name = lightLabel(light, i);
        if (i >= kMaxLights) {
            plan.skipped.push_back(
                {name, "more than " + std::to_string(kMaxLights) + " lights: this light is ignored"});
            continue;
        }
        if (!light.shadows.enabled) {
            plan.skipped.push_back({name, "shadow pass not needed: shadows are off for this light"});
            continue;
        }
        if (casters == 0) {
            plan.skipped.push_back({name, "shadow pass not needed: nothing in the scene casts a shadow"});
            continue;
        }
        if (shadowSlots >= kMaxShadowedLights) {
            plan.skipped.push_back({name, "shadow pass skipped: at most " +
                                              std::to_string(kMaxShadowedLights) +
                                              " lights cast shadows; this one lights without them"});
            continue;
        }
        const auto frustum = math::shadowFrustum(input, light, light.shadows.mapSize);
        if (!frustum) {
            plan.skipped.push_back(
                {name, "shadow pass not needed: nothing in the scene can receive a shadow"});
            continue;
        }
        ++shadowSlots;
        plan.shadowedLights.push_back(i);
        const auto previous = state.shadowSignatures.find(i);
        const std::uint64_t signature = shadowSignature(input, i);
        if (previous != state.shadowSignatures.end() && previous->second == signature) {
            plan.skipped.push_back(
                {name, "shadow map reused: light and casters unchanged since the last frame"});
            continue;
        }
        std::string reason = "light casts shadows (" + std::to_string(light.shadows.mapSize) + "² map, PCF " +
                             std::to_string(light.shadows.pcf) + "×" + std::to_string(light.shadows.pcf) +
                             ") from " + plural(casters, "caster", "casters");
        if (frustum->cube)
            reason +=
                "; " + std::to_string(std::popcount(frustum->faceMask)) + " of 6 cube faces hold casters";
        reason += previous == state.shadowSignatures.end() ? "; no map yet" : "; light or casters changed";
        PlannedPass pass;
        pass.kind = PassKind::Shadow;
        pass.target = name;
        pass.reason = std::move(reason);
        pass.lightIndex = i;
        pass.signature = signature;
        plan.passes.push_back(std::move(pass));
    }

    // Mirror views are planned first (their passes run after the main pass): the environment pass, which
    // runs before the main pass, is needed only if the reflector is seen directly or in one of them.
    FramePlan mirrors;
    planMirrors(input, viewport, mirrors);
    planReflector(input, state, viewport, mirrors, plan);

    PlannedPass main;
    main.kind = PassKind::Main;
    main.reason =
        "draws " +
        plural(input.items.size() + input.mirrors.size() + (input.reflector ? 1 : 0), "object", "objects") +
        " lit by " + plural(std::min<std::size_t>(input.lights.size(), kMaxLights), "light", "lights") +
        " into the linear colour buffer";
    plan.passes.push_back(std::move(main));

    // The mirror passes keep their view indices: plan.views is empty until here.
    plan.views = std::move(mirrors.views);
    for (PlannedPass& pass : mirrors.passes)
        plan.passes.push_back(std::move(pass));
    for (SkippedEffect& skip : mirrors.skipped)
        plan.skipped.push_back(std::move(skip));

    PlannedPass composite;
    composite.kind = PassKind::Composite;
    composite.reason = "resolves the linear colour buffer into the output (sRGB encoding for 8-bit targets)";
    plan.passes.push_back(std::move(composite));
    return plan;
}

} // namespace speculum::render
