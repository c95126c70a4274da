#include "render/passes/LightingVariant.hpp"

#include "render/plan/Planner.hpp"

#include <algorithm>

namespace speculum::render::passes {

std::string lightingVariant(const FrameInput& input, const std::vector<int>& shadowedLights) {
    const int count = std::min<int>(static_cast<int>(input.lights.size()), kMaxLights);
    std::string defines = "#define LIGHT_COUNT " + std::to_string(count) + "\n";
    for (int i = 0; i < count; ++i) {
        const auto slot = std::find(shadowedLights.begin(), shadowedLights.end(), i);
        const bool shadowed = slot != shadowedLights.end();
        const std::string n = std::to_string(i);
        // The values of LIGHT_POINT, LIGHT_DIRECTIONAL and LIGHT_SPOT in shaders/lighting.glsl.
        const LightType type = input.lights[static_cast<std::size_t>(i)].type;
        defines += "#define LIGHT_TYPE_" + n +
                   (type == LightType::Directional ? " 1\n"
                    : type == LightType::Spot      ? " 2\n"
                                                   : " 0\n");
        defines += "#define LIGHT_SLOT_" + n + " " +
                   std::to_string(shadowed ? static_cast<int>(slot - shadowedLights.begin()) : -1) + "\n";
        // Point lights render cube maps; spot and directional lights one 2D map (math/ShadowFrustum).
        const bool cube = shadowed && input.lights[static_cast<std::size_t>(i)].type == LightType::Point;
        defines += "#define LIGHT_CUBE_" + n + (cube ? " 1\n" : " 0\n");
    }
    return defines;
}

} // namespace speculum::render::passes
