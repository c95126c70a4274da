#include "render/frame/Reflector.hpp"

namespace speculum::render {

std::optional<std::pair<std::string_view, std::string>> parallaxProblem(const ParallaxParams& proxy) {
    if (proxy.shape != ParallaxShape::Box)
        return std::nullopt;
    for (int i = 0; i < 3; ++i) {
        if (!(proxy.min[i] < 0.0 && proxy.max[i] > 0.0))
            return std::pair{
                proxy.min[i] < 0.0 ? std::string_view("max") : std::string_view("min"),
                std::string("the box must contain the capture point (min < 0 < max on every axis)")};
        for (const auto& [name, distance] : {std::pair{std::string_view("min"), -proxy.min[i]},
                                             std::pair{std::string_view("max"), proxy.max[i]}})
            if (distance < kMinScale || distance > kMaxCoordinate)
                return std::pair{name, "the distances to the box's faces must be in " +
                                           shortestNumber(kMinScale) + ".." + shortestNumber(kMaxCoordinate) +
                                           ", got " + shortestNumber(distance)};
    }
    return std::nullopt;
}

} // namespace speculum::render
