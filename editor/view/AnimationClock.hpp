#pragma once

#include <QElapsedTimer>
#include <QObject>

namespace speculum::view {

// The editor's animation time: runs on the wall clock while playing, holds still while paused. A view
// asks for time() when it draws, so a slow frame skips animation time instead of slowing it down.
class AnimationClock : public QObject {
    Q_OBJECT

public:
    explicit AnimationClock(QObject* parent = nullptr);

    bool isPlaying() const { return m_playing; }
    double time() const; // seconds

public slots:
    void setPlaying(bool playing);
    void togglePlaying() { setPlaying(!m_playing); }
    void setTime(double seconds);

signals:
    void playingChanged(bool playing);
    void timeChanged(); // on jumps (setTime) and play/pause, not continuously

private:
    bool m_playing = false;
    double m_base = 0.0;   // time at the last start/jump
    QElapsedTimer m_since; // wall time since then, while playing
};

} // namespace speculum::view
