#pragma once

#include <QWidget>

namespace speculum::ui {

class Viewport;

// A transparent child widget over the viewport that paints its handles and outlines with QPainter after
// each GL frame. Mouse events pass through to the viewport. Painting on a raster widget keeps QPainter
// away from the renderer's GL state.
//
// Under the viewport's own marks it paints the guides that orient the view: the ground grid, the scene
// camera's wireframe and the pivot the view orbits about; over them, the axis gizmo in the corner. They are
// painted only when the viewport repaints (each GL frame updates the overlay), never on a timer. While the
// frame shown is a reduced-resolution preview (adaptive resolution), a "preview" label says so.
class ViewportOverlay : public QWidget {
public:
    explicit ViewportOverlay(Viewport& viewport);

    // The grid, the camera wireframe, the pivot and the axis gizmo (View ▸ Show Guides); remembered in
    // QSettings.
    bool guidesVisible() const { return m_guides; }
    void setGuidesVisible(bool on);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void paintGuidesUnder(QPainter& painter);
    void paintPreviewLabel(QPainter& painter);
    void paintSourcesLegend(QPainter& painter);

    Viewport& m_viewport;
    bool m_guides = true;
};

} // namespace speculum::ui
