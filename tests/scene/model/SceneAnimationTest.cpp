// What is animated in a scene (a static one need not be drawn again while the clock runs) and
// how long one loop of its animation lasts (the time slider's range), and the clock looping over it.
#include "scene/model/SceneAnimation.hpp"

#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"

#include <QThread>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace {

using namespace speculum::scene;
using speculum::view::AnimationClock;

speculum::scene::NodeTree nodeWith(std::optional<double> bouncePeriod, std::optional<double> orbitPeriod) {
    speculum::scene::NodeTree tree;
    tree.data.name = "n";
    if (bouncePeriod || orbitPeriod) {
        tree.data.animation.emplace();
        if (bouncePeriod) {
            tree.data.animation->bounce = speculum::scene::BounceAnimation{1.0, *bouncePeriod};
        }
        if (orbitPeriod) {
            tree.data.animation->orbit = speculum::scene::OrbitAnimation{{}, 1.0, *orbitPeriod};
        }
    }
    return tree;
}

void fill(speculum::scene::Scene& scene, std::vector<speculum::scene::NodeTree> nodes) {
    speculum::scene::SceneData data;
    data.nodes = std::move(nodes);
    scene.reset(std::move(data));
}

TEST(SceneAnimation, AStaticSceneHasNoAnimationAndATenSecondTimeline) {
    speculum::scene::Scene scene;
    EXPECT_FALSE(speculum::scene::sceneHasAnimation(scene));
    fill(scene, {nodeWith(std::nullopt, std::nullopt)});
    EXPECT_FALSE(speculum::scene::sceneHasAnimation(scene));
    EXPECT_DOUBLE_EQ(speculum::scene::animationLoopSeconds(scene), speculum::scene::kStaticTimelineSeconds);
}

TEST(SceneAnimation, APeriodThatIsNotPositiveMovesNothing) {
    speculum::scene::Scene scene;
    fill(scene, {nodeWith(0.0, -1.0), nodeWith(std::numeric_limits<double>::infinity(), std::nullopt)});
    EXPECT_FALSE(speculum::scene::sceneHasAnimation(scene));
}

TEST(SceneAnimation, AnAnimatedChildMakesTheSceneAnimated) {
    speculum::scene::Scene scene;
    speculum::scene::NodeTree parent = nodeWith(std::nullopt, std::nullopt);
    parent.children.push_back(nodeWith(2.0, std::nullopt));
    fill(scene, {parent});
    EXPECT_TRUE(speculum::scene::sceneHasAnimation(scene));
    EXPECT_DOUBLE_EQ(speculum::scene::animationLoopSeconds(scene), 2.0);
}

TEST(SceneAnimation, OneLoopIsTheLeastCommonMultipleOfThePeriods) {
    speculum::scene::Scene scene;
    fill(scene, {nodeWith(2.0, std::nullopt), nodeWith(std::nullopt, 6.0)}); // the teapot demo
    EXPECT_DOUBLE_EQ(speculum::scene::animationLoopSeconds(scene), 6.0);
    fill(scene, {nodeWith(2.5, 6.0)});
    EXPECT_DOUBLE_EQ(speculum::scene::animationLoopSeconds(scene), 30.0);
    // No short common loop: the longest period.
    fill(scene, {nodeWith(1.001, 7.0), nodeWith(std::nullopt, 9.973)});
    EXPECT_DOUBLE_EQ(speculum::scene::animationLoopSeconds(scene), 9.973);
}

TEST(AnimationClockLoop, PlayingWrapsAtTheLoopsEndAndPausedHoldsAnyTime) {
    AnimationClock clock;
    clock.setLoopSeconds(0.1);
    EXPECT_DOUBLE_EQ(clock.loopSeconds(), 0.1);
    clock.setTime(0.09);
    clock.setPlaying(true);
    QThread::msleep(40);
    const double wrapped = clock.time();
    EXPECT_GE(wrapped, 0.0);
    EXPECT_LT(wrapped, 0.09) << "past the end it starts over";
    clock.setPlaying(false);
    clock.setTime(5.0);
    EXPECT_DOUBLE_EQ(clock.time(), 5.0) << "paused: the time is where it was set";
    clock.setLoopSeconds(std::nan(""));
    EXPECT_DOUBLE_EQ(clock.loopSeconds(), 0.0) << "not a length: no loop";
}

} // namespace
