#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/frame/Guides.hpp"
#include "render/inspect/PixelExplanation.hpp"

#include <QWidget>
#include <vector>

class QLabel;
class QTreeWidget;

namespace speculum::ui {

// The path of an explained pixel as 3D lines the viewport draws over the scene, coloured by kind: the
// camera ray white, each planar bounce cyan, each curved one magenta, the segment to the surface that
// ends the path yellow (grey to the background), shadow rays green where they reach the light and red
// where they are blocked. They are world-space lines, so they stay where they are while the view orbits.
// `highlighted`: the vertex whose arriving segment is drawn wider (the step selected in the panel; -1: none).
std::vector<render::GuideLine> pathGuides(const render::inspect::PixelExplanation& explanation,
                                          const render::FrameInput& input, int highlighted = -1);

// The Inspect Pixel panel: both recipes of the pixel last clicked with the inspect tool, and their
// difference. Selecting a step that touched a node asks for that node (nodeChosen).
class InspectPanel : public QWidget {
    Q_OBJECT

public:
    explicit InspectPanel(QWidget* parent = nullptr);

    void show(const render::inspect::PixelExplanation& explanation, const render::FrameInput& input);
    void showMessage(const QString& message);

signals:
    // The name of the node a selected step touched (a mirror, a reflector, an object, a light).
    void nodeChosen(const QString& name);
    // A step of the exact path was selected: its vertex (-1: something else was).
    void pathStepChosen(int vertex);

private:
    QLabel* m_summary = nullptr;
    QTreeWidget* m_tree = nullptr;
};

} // namespace speculum::ui
