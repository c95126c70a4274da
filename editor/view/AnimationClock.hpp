#pragma once

#include <QElapsedTimer>
#include <QObject>

namespace speculum::view {

// The editor's animation time: runs on the wall clock while playing, holds still while paused. A view
// asks for time() when it draws, so a slow frame skips animation time instead of slowing it down.
// With a loop length set, playing wraps back to 0 at its end (as a timeline loops over its range).
class AnimationClock : public QObject {
    Q_OBJECT

public:
    explicit AnimationClock(QObject* parent = nullptr);

    bool isPlaying() const { return m_playing; }
    double time() const; // seconds
    // 0: no loop (the default).
    double loopSeconds() const { return m_loop; }

public slots:
    void setPlaying(bool playing);
    void togglePlaying() { setPlaying(!m_playing); }
    void setTime(double seconds);
    // Playing, time() runs from 0 to `seconds` and starts over; a value that is not positive and finite
    // turns the loop off. Paused, the time stays where it is.
    void setLoopSeconds(double seconds);

signals:
    void playingChanged(bool playing);
    void timeChanged(); // on jumps (setTime) and play/pause, not continuously

private:
    bool m_playing = false;
    double m_base = 0.0;   // time at the last start/jump
    double m_loop = 0.0;   // seconds; 0: no loop
    QElapsedTimer m_since; // wall time since then, while playing
};

} // namespace speculum::view
