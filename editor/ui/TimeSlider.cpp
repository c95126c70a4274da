#include "editor/ui/TimeSlider.hpp"

#include "editor/view/AnimationClock.hpp"

#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

constexpr int kFollowIntervalMs = 40; // 25 updates a second: smooth enough for a slider, cheap

} // namespace

TimeSlider::TimeSlider(view::AnimationClock& clock, QWidget* parent)
    : QWidget(parent)
    , m_clock(clock) {
    setObjectName(QStringLiteral("timeSlider"));
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("timeSliderBar"));
    m_slider->setMinimumWidth(160);
    m_slider->setSingleStep(40); // ms: about one frame at 25 fps
    m_slider->setPageStep(1000);
    // Arrow keys scrub when the slider has focus; it never takes focus from the viewport on its own.
    m_slider->setFocusPolicy(Qt::ClickFocus);
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("timeReadout"));
    m_readout->setMinimumWidth(
        QFontMetrics(m_readout->font()).horizontalAdvance(QStringLiteral("t = 000.00 s")));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_readout);

    m_follow.setInterval(kFollowIntervalMs);
    connect(&m_follow, &QTimer::timeout, this, &TimeSlider::follow);
    connect(&m_clock, &view::AnimationClock::playingChanged, this, [this](bool playing) {
        if (playing) {
            m_follow.start();
        } else {
            m_follow.stop();
        }
    });
    connect(&m_clock, &view::AnimationClock::timeChanged, this, &TimeSlider::follow);
    connect(m_slider, &QSlider::valueChanged, this, &TimeSlider::userMoved);
    setDuration(10.0, false);
    if (m_clock.isPlaying()) {
        m_follow.start();
    }
}

void TimeSlider::setDuration(double seconds, bool animated) {
    m_duration = seconds > 0.0 && std::isfinite(seconds) ? seconds : 10.0;
    m_showing = true;
    m_slider->setRange(0, int(std::lround(m_duration * 1000.0)));
    m_showing = false;
    m_slider->setToolTip(
        animated ? tr("Animation time: drag to scrub; playback loops every %1 s").arg(m_duration, 0, 'g', 4)
                 : tr("Animation time (nothing in this scene is animated)"));
    follow();
}

double TimeSlider::shownTime() const {
    return m_slider->value() / 1000.0;
}

QString TimeSlider::readout() const {
    return m_readout->text();
}

void TimeSlider::follow() {
    if (m_slider->isSliderDown()) {
        return; // the user holds it: the clock follows the slider, not the other way round
    }
    showTime(m_clock.time());
}

void TimeSlider::showTime(double seconds) {
    m_showing = true;
    m_slider->setValue(int(std::lround(std::clamp(seconds, 0.0, m_duration) * 1000.0)));
    m_showing = false;
    m_readout->setText(tr("t = %1 s").arg(seconds, 0, 'f', 2));
}

void TimeSlider::userMoved(int milliseconds) {
    if (m_showing) {
        return;
    }
    const double seconds = milliseconds / 1000.0;
    m_readout->setText(tr("t = %1 s").arg(seconds, 0, 'f', 2));
    m_clock.setTime(seconds); // emits timeChanged: follow() shows the same value again
}

} // namespace speculum::ui
