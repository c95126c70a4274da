#pragma once

namespace speculum::scene {

class Scene;
struct NodeData;

// Whether a node moves with time: a bounce or an orbit whose period is a positive finite number (any
// other period means no motion, NodeMath's phase()).
bool nodeIsAnimated(const NodeData& node);

// Whether anything in the scene moves with time. A scene where nothing does looks the same at every
// time, so the viewport need not draw while the clock runs (a static scene costs nothing).
bool sceneHasAnimation(const Scene& scene);

// One loop of the scene's animation, in seconds: the shortest time after which every animation is back
// where it started (the least common multiple of the periods, to the millisecond), for the time slider's
// range. When that is longer than kMaxAnimationLoopSeconds, the longest period; without animation,
// kStaticTimelineSeconds.
double animationLoopSeconds(const Scene& scene);

inline constexpr double kMaxAnimationLoopSeconds = 600.0;
inline constexpr double kStaticTimelineSeconds = 10.0;

} // namespace speculum::scene
