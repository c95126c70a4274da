// The main window's timeline: a toolbar along the bottom with Play, Rewind and the time slider,
// and the clock that starts over, paused, with every document.
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/TimeSlider.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneAnimation.hpp"

#include <QAction>
#include <QMenu>
#include <QToolBar>

namespace speculum::ui {

void MainWindow::createTimeline() {
    auto* bar = new QToolBar(tr("Timeline"), this);
    bar->setObjectName(QStringLiteral("timelineToolBar")); // saveState/restoreState key
    bar->setMovable(true);
    for (const char* name : {"actionRewind", "actionPlay"}) {
        if (QAction* a = action(QString::fromLatin1(name))) {
            bar->addAction(a);
        }
    }
    m_timeSlider = new TimeSlider(*m_clock, bar);
    bar->addWidget(m_timeSlider);
    addToolBar(Qt::BottomToolBarArea, bar);
    m_viewMenu->addAction(bar->toggleViewAction());

    connect(&scene(), &scene::Scene::changed, this, &MainWindow::updateTimelineRange);
    // A new document starts at t = 0, paused: the last one's clock means nothing for it (Blender opens a
    // file on its first frame and does not play it).
    connect(&scene(), &scene::Scene::sceneReset, this, [this] {
        updateTimelineRange();
        resetClock();
    });
    updateTimelineRange();
}

void MainWindow::updateTimelineRange() {
    const double loop = scene::animationLoopSeconds(scene());
    m_clock->setLoopSeconds(loop);
    m_timeSlider->setDuration(loop, scene::sceneHasAnimation(scene()));
}

void MainWindow::resetClock() {
    m_clock->setPlaying(false);
    m_clock->setTime(0.0);
}

} // namespace speculum::ui
