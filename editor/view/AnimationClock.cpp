#include "editor/view/AnimationClock.hpp"

#include <cmath>

namespace speculum::view {

AnimationClock::AnimationClock(QObject* parent)
    : QObject(parent) {}

double AnimationClock::time() const {
    if (!m_playing) {
        return m_base;
    }
    const double running = m_base + static_cast<double>(m_since.nsecsElapsed()) * 1e-9;
    if (m_loop > 0.0 && running >= m_loop) {
        return std::fmod(running, m_loop);
    }
    return running;
}

void AnimationClock::setLoopSeconds(double seconds) {
    const double loop = seconds > 0.0 && std::isfinite(seconds) ? seconds : 0.0;
    if (loop == m_loop) {
        return;
    }
    // Where the clock is now, under the old loop, stays where it is.
    m_base = time();
    if (m_playing) {
        m_since.start();
    }
    m_loop = loop;
}

void AnimationClock::setPlaying(bool playing) {
    if (playing == m_playing) {
        return;
    }
    m_base = time();
    m_playing = playing;
    if (playing) {
        m_since.start();
    }
    emit playingChanged(playing);
    emit timeChanged();
}

void AnimationClock::setTime(double seconds) {
    m_base = seconds;
    if (m_playing) {
        m_since.start();
    }
    emit timeChanged();
}

} // namespace speculum::view
