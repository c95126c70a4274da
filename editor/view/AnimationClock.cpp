#include "editor/view/AnimationClock.hpp"

namespace speculum::view {

AnimationClock::AnimationClock(QObject* parent)
    : QObject(parent) {}

double AnimationClock::time() const {
    if (!m_playing) {
        return m_base;
    }
    return m_base + static_cast<double>(m_since.nsecsElapsed()) * 1e-9;
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
