#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QSlider;

namespace speculum::view {
class AnimationClock;
}

namespace speculum::ui {

// The timeline: a slider over one loop of the scene's animation with the "t = … s" readout beside it.
// Playing moves it; dragging it, clicking along it or the arrow keys on it set the clock (a jump, which the
// viewport draws at once). It follows the clock only while the clock plays or jumps, so it costs nothing
// while paused.
class TimeSlider : public QWidget {
    Q_OBJECT

public:
    explicit TimeSlider(view::AnimationClock& clock, QWidget* parent = nullptr);

    // The slider runs from 0 to `seconds` (one loop of the animation). `animated`: whether anything in
    // the scene moves; the tooltip says so when nothing does.
    void setDuration(double seconds, bool animated);
    double duration() const { return m_duration; }
    // The time the slider shows, in seconds.
    double shownTime() const;
    QSlider* slider() const { return m_slider; }
    QString readout() const;

private:
    void follow(); // the slider and the readout to the clock's time
    void showTime(double seconds);
    void userMoved(int milliseconds);

    view::AnimationClock& m_clock;
    QSlider* m_slider = nullptr;
    QLabel* m_readout = nullptr;
    QTimer m_follow; // while the clock plays
    double m_duration = 0.0;
    bool m_showing = false; // setting the slider from the clock, not the user moving it
};

} // namespace speculum::ui
