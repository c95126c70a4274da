// The passes that draw a map of their own: a light's shadow map, the reflector's environment map (with the
// mirror passes planned inside it) and its GGX pre-filtered chain.
#include "render/passes/PassExecutors.hpp"

#include <algorithm>

namespace speculum::render::passes {

PassResult runShadow(const PlannedPass& pass, FrameExecution& frame) {
    bindWrites(pass.writes, frame);
    FrameResources& r = frame.resources;
    const ShadowPlan* shadow = frame.plan.shadowOf(pass.lightIndex);
    if (!shadow) // the planner plans every shadow pass's map: nothing to draw into otherwise
        return {false, {}};
    const std::vector<int>& missing = frame.shadowsMissing;
    if (std::find(missing.begin(), missing.end(), pass.lightIndex) != missing.end()) {
        frame.skipped.push_back(
            {pass.target, PlanReason::ShadowMapNotAllocated, {.mapSize = shadow->mapSize}});
        return {false, {}};
    }
    r.shadows.render(frame.input, *shadow, r.meshes, r.shadowProgram, &r.textures);
    frame.commits.shadowSignatures[pass.lightIndex] = shadow->signature;
    return {};
}

PassResult runEnvmap(const PlannedPass& pass, FrameExecution& frame) {
    if (pass.envmap < 0 || static_cast<std::size_t>(pass.envmap) >= frame.plan.envmaps.size())
        return {false, {}}; // the planner plans every envmap pass's map
    const EnvmapPlan& map = frame.plan.envmaps[static_cast<std::size_t>(pass.envmap)];
    const auto reflector = static_cast<std::size_t>(map.reflector);
    if (reflector >= frame.envmapAllocated.size() || !frame.envmapAllocated[reflector]) {
        frame.skipped.push_back({map.target, PlanReason::EnvmapNotAllocated});
        return {false, {}};
    }
    bindWrites(pass.writes, frame);
    FrameResources& r = frame.resources;
    // A context of its own: the capture sets per-face state (mirror meshes, culling) on it.
    MainPassContext context{
        r.meshProgram,          r.meshes,   r.textures, r.shadows, frame.plan.shadows, r.dummyShadow2D.id(),
        r.dummyShadowCube.id(), r.unitPlane};
    context.coarseItems = frame.plan.coarseItems;
    // The mirror passes planned inside the map run in the face they were planned in, with the executors
    // of the camera's mirrors.
    auto runFacePasses = [&](const ViewSpace& face) {
        for (const PlannedPass& pass : map.passes)
            if (face.view(pass.view).face == face.face)
                runPass(pass, frame, face);
    };
    if (base::Status captured =
            r.reflector.capture(frame.input, map, context, {r.flatProgram, r.mirrorProgram}, runFacePasses);
        !captured) {
        frame.warnings.push_back(captured.error());
        return {};
    }
    recordEnvmap(map, frame.commits);
    return {};
}

PassResult runPrefilter(const PlannedPass& pass, FrameExecution& frame) {
    const auto index = static_cast<std::size_t>(pass.reflector);
    const Reflector* reflector =
        index < frame.input.reflectors.size() ? &frame.input.reflectors[index] : nullptr;
    FrameResources& r = frame.resources;
    if (!reflector || !r.reflector.hasMap(pass.reflector, *reflector)) { // not allocated or not drawn
        frame.skipped.push_back({pass.target, PlanReason::PrefilterNoMap});
        return {false, {}};
    }
    bindWrites(pass.writes, frame);
    if (base::Status filtered =
            r.reflector.prefilter(pass.reflector, *reflector, frame.input.settings.prefilterSamples);
        !filtered) {
        frame.warnings.push_back(filtered.error());
        return {};
    }
    frame.commits.mapOf(pass.reflector).prefilterKey = pass.signature;
    return {};
}

} // namespace speculum::render::passes
