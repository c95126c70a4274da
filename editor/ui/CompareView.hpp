#pragma once

#include <QImage>
#include <QPointF>
#include <QWidget>

namespace speculum::ui {

// The exact and the raster image of a comparison, zoomable, either swiped (one image, the exact one left
// of a divider the user drags, the raster one right of it) or side by side (two panes that zoom and pan
// together). The wheel zooms about the pointer, dragging pans, a double-click fits the image again. Zoomed
// in, pixels are drawn as squares, so a single pixel's error can be looked at.
class CompareView : public QWidget {
    Q_OBJECT

public:
    enum class Layout { Swipe, SideBySide };

    explicit CompareView(QWidget* parent = nullptr);

    void setImages(const QImage& exact, const QImage& raster); // null images empty it
    void setLayoutMode(Layout layout);
    Layout layoutMode() const { return m_layout; }

    double zoom() const { return m_zoom; } // 1: the image fits its pane
    // Zooms to `zoom` (clamped to 1 … 64) keeping the image point under `anchor` (widget pixels) there.
    void setZoom(double zoom, const QPointF& anchor);
    void resetView();
    double divider() const { return m_divider; } // where the swipe splits, 0 … 1 of the image's width
    void setDivider(double divider);
    // The image pixel (fractional) shown at a widget point, in the pane under it; for tests and the cursor.
    QPointF imagePointAt(const QPointF& widgetPoint) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;

private:
    QRectF paneAt(const QPointF& widgetPoint) const; // the pane a point falls in
    QRectF pane(int index) const;                    // 0: the only or the left pane, 1: the right one
    double scale(const QRectF& pane) const;          // widget pixels per image pixel
    QPointF toWidget(const QRectF& pane, const QPointF& imagePoint) const;
    void paintPane(class QPainter& painter, const QRectF& pane, const QImage& image, double fromX,
                   double toX) const;
    double dividerX() const; // in widget pixels (swipe)
    void keepInView();       // the centre stays on the image, so it can never be dragged out of sight

    QImage m_exact;
    QImage m_raster;
    Layout m_layout = Layout::Swipe;
    double m_zoom = 1.0;
    QPointF m_centre; // the image point at the centre of each pane
    double m_divider = 0.5;
    enum class Drag { None, Pan, Divider } m_drag = Drag::None;
    QPointF m_lastMouse;
};

} // namespace speculum::ui
