#pragma once

#include <QWidget>

namespace speculum::ui {

class Viewport;

// A transparent child widget over the viewport that paints its handles and outlines with QPainter after
// each GL frame. Mouse events pass through to the viewport. Painting on a raster widget keeps QPainter
// away from the renderer's GL state.
class ViewportOverlay : public QWidget {
public:
    explicit ViewportOverlay(Viewport& viewport);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    Viewport& m_viewport;
};

} // namespace speculum::ui
