#include "scene/model/SceneAnimation.hpp"

#include "scene/model/Scene.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace speculum::scene {

namespace {

bool moves(double period) {
    return period > 0.0 && std::isfinite(period);
}

std::vector<double> periodsOf(const Scene& scene) {
    std::vector<double> periods;
    scene.forEachNode([&](const Node& node) {
        const auto& animation = node.data().animation;
        if (!animation) {
            return;
        }
        if (animation->bounce && moves(animation->bounce->period)) {
            periods.push_back(animation->bounce->period);
        }
        if (animation->orbit && moves(animation->orbit->period)) {
            periods.push_back(animation->orbit->period);
        }
    });
    return periods;
}

} // namespace

bool nodeIsAnimated(const NodeData& node) {
    if (!node.animation) {
        return false;
    }
    return (node.animation->bounce && moves(node.animation->bounce->period)) ||
           (node.animation->orbit && moves(node.animation->orbit->period));
}

bool sceneHasAnimation(const Scene& scene) {
    bool animated = false;
    scene.forEachNode([&](const Node& node) { animated = animated || nodeIsAnimated(node.data()); });
    return animated;
}

double animationLoopSeconds(const Scene& scene) {
    const std::vector<double> periods = periodsOf(scene);
    if (periods.empty()) {
        return kStaticTimelineSeconds;
    }
    double longest = 0.0;
    for (double p : periods) {
        longest = std::max(longest, p);
    }
    if (longest > kMaxAnimationLoopSeconds) {
        return longest;
    }
    // In whole milliseconds, so that 2 s and 6 s loop after 6 s and 2.5 s and 6 s after 30 s; a period
    // shorter than a millisecond counts as one.
    constexpr std::int64_t kCap = std::int64_t(kMaxAnimationLoopSeconds * 1000.0);
    std::int64_t loop = 1;
    for (double p : periods) {
        const std::int64_t ms = std::max<std::int64_t>(1, std::llround(p * 1000.0));
        loop = std::lcm(loop, ms);
        if (loop > kCap) {
            return longest; // incommensurate periods: no short loop
        }
    }
    return double(loop) / 1000.0;
}

} // namespace speculum::scene
