// The animation clock on its own: paused it holds still, playing it follows the wall clock from where it
// was, and jumps and play/pause tell the views to draw again.
#include "editor/view/AnimationClock.hpp"

#include <QSignalSpy>
#include <QThread>
#include <gtest/gtest.h>

namespace {

using speculum::view::AnimationClock;

TEST(AnimationClock, HoldsStillWhilePausedAndRunsOnTheWallClockWhilePlaying) {
    AnimationClock clock;
    EXPECT_FALSE(clock.isPlaying());
    EXPECT_EQ(clock.time(), 0.0);
    clock.setTime(1.5);
    QThread::msleep(20);
    EXPECT_EQ(clock.time(), 1.5) << "paused: no time passes";

    clock.setPlaying(true);
    QThread::msleep(50);
    const double running = clock.time();
    EXPECT_GE(running, 1.5 + 0.045);
    EXPECT_LT(running, 1.5 + 5.0);

    clock.setPlaying(false);
    const double paused = clock.time();
    EXPECT_GE(paused, running);
    QThread::msleep(20);
    EXPECT_EQ(clock.time(), paused) << "pausing keeps the time reached";

    clock.togglePlaying();
    EXPECT_TRUE(clock.isPlaying());
    clock.setTime(0.0); // a jump while playing runs on from there
    EXPECT_LT(clock.time(), 1.0);
    EXPECT_GE(clock.time(), 0.0);
}

TEST(AnimationClock, JumpsAndPlayPauseAreSignalledButARepeatedStateIsNot) {
    AnimationClock clock;
    QSignalSpy playing(&clock, &AnimationClock::playingChanged);
    QSignalSpy time(&clock, &AnimationClock::timeChanged);
    clock.setPlaying(true);
    clock.setPlaying(true);
    ASSERT_EQ(playing.count(), 1);
    EXPECT_TRUE(playing.front().front().toBool());
    EXPECT_EQ(time.count(), 1);
    clock.setTime(2.0);
    EXPECT_EQ(time.count(), 2);
    clock.setPlaying(false);
    EXPECT_EQ(playing.count(), 2);
    EXPECT_EQ(time.count(), 3);
}

} // namespace
