#include "editor/ui/CompareView.hpp"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

constexpr double kMaxZoom = 64.0;
constexpr double kDividerGrab = 8.0; // widget pixels either side of the divider that grab it

} // namespace

CompareView::CompareView(QWidget* parent)
    : QWidget(parent) {
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Wheel: zoom about the pointer · drag: pan · drag the line: move the swipe · "
                  "double-click: fit"));
}

QSize CompareView::sizeHint() const {
    return {480, 300};
}

QSize CompareView::minimumSizeHint() const {
    return {200, 160};
}

void CompareView::setImages(const QImage& exact, const QImage& raster) {
    const bool sameSize = exact.size() == m_exact.size();
    m_exact = exact;
    m_raster = raster;
    if (!sameSize)
        resetView();
    update();
}

void CompareView::setLayoutMode(Layout layout) {
    m_layout = layout;
    update();
}

void CompareView::resetView() {
    m_zoom = 1.0;
    m_centre = QPointF(m_exact.width() / 2.0, m_exact.height() / 2.0);
    update();
}

void CompareView::setDivider(double divider) {
    m_divider = std::clamp(divider, 0.0, 1.0);
    update();
}

QRectF CompareView::pane(int index) const {
    const QRectF all = QRectF(rect()).adjusted(2, 2, -2, -2);
    if (m_layout == Layout::Swipe)
        return all;
    const double half = (all.width() - 4.0) / 2.0;
    return index == 0 ? QRectF(all.left(), all.top(), half, all.height())
                      : QRectF(all.right() - half, all.top(), half, all.height());
}

QRectF CompareView::paneAt(const QPointF& widgetPoint) const {
    return m_layout == Layout::SideBySide && widgetPoint.x() >= pane(1).left() ? pane(1) : pane(0);
}

double CompareView::scale(const QRectF& p) const {
    if (m_exact.isNull())
        return 1.0;
    const double fit = std::min(p.width() / m_exact.width(), p.height() / m_exact.height());
    return fit * m_zoom;
}

QPointF CompareView::toWidget(const QRectF& p, const QPointF& imagePoint) const {
    return p.center() + (imagePoint - m_centre) * scale(p);
}

QPointF CompareView::imagePointAt(const QPointF& widgetPoint) const {
    const QRectF p = paneAt(widgetPoint);
    return m_centre + (widgetPoint - p.center()) / scale(p);
}

double CompareView::dividerX() const {
    return toWidget(pane(0), QPointF(m_divider * m_exact.width(), 0.0)).x();
}

void CompareView::setZoom(double zoom, const QPointF& anchor) {
    const QPointF before = imagePointAt(anchor);
    m_zoom = std::clamp(zoom, 1.0, kMaxZoom);
    if (m_zoom == 1.0) { // fitted: the whole image, centred
        resetView();
        return;
    }
    // Keep `before` under the anchor: the centre moves by what the anchor's offset now spans.
    const QRectF p = paneAt(anchor);
    m_centre = before - (anchor - p.center()) / scale(p);
    keepInView();
    update();
}

void CompareView::paintPane(QPainter& painter, const QRectF& p, const QImage& image, double fromX,
                            double toX) const {
    painter.save();
    painter.setClipRect(
        QRectF(QPointF(std::max(p.left(), fromX), p.top()), QPointF(std::min(p.right(), toX), p.bottom())));
    const QPointF topLeft = toWidget(p, QPointF(0.0, 0.0));
    const double s = scale(p);
    // Enlarged, pixels show as squares (the error of one pixel is what the zoom is for); reduced, smoothly.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, s < 1.0);
    painter.drawImage(QRectF(topLeft, QSizeF(image.width() * s, image.height() * s)), image);
    painter.restore();
}

void CompareView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    if (m_exact.isNull() || m_raster.isNull()) {
        painter.drawText(rect(), Qt::AlignCenter, tr("Compare with exact to see the images here."));
        return;
    }
    auto caption = [&](const QRectF& p, const QString& text, Qt::Alignment side) {
        const QRectF box = QRectF(p.left() + 6, p.top() + 6, p.width() - 12, 20);
        painter.setPen(Qt::white);
        painter.fillRect(
            painter.fontMetrics().boundingRect(box.toRect(), int(side), text).adjusted(-4, -1, 4, 1),
            QColor(0, 0, 0, 150));
        painter.drawText(box, int(side | Qt::AlignTop), text);
    };
    if (m_layout == Layout::SideBySide) {
        paintPane(painter, pane(0), m_exact, pane(0).left(), pane(0).right());
        paintPane(painter, pane(1), m_raster, pane(1).left(), pane(1).right());
        caption(pane(0), tr("Exact"), Qt::AlignLeft);
        caption(pane(1), tr("Raster"), Qt::AlignLeft);
        return;
    }
    const QRectF p = pane(0);
    const double split = dividerX();
    paintPane(painter, p, m_exact, p.left(), split);
    paintPane(painter, p, m_raster, split, p.right());
    painter.setPen(QPen(Qt::white, 2.0));
    painter.drawLine(QPointF(split, p.top()), QPointF(split, p.bottom()));
    painter.setBrush(Qt::white);
    painter.drawEllipse(QPointF(split, p.center().y()), 6.0, 6.0);
    caption(p, tr("Exact"), Qt::AlignLeft);
    caption(p, tr("Raster"), Qt::AlignRight);
}

void CompareView::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0.0 && !m_exact.isNull())
        setZoom(m_zoom * std::pow(1.25, steps), event->position());
    event->accept();
}

void CompareView::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || m_exact.isNull())
        return;
    m_lastMouse = event->position();
    const bool onDivider =
        m_layout == Layout::Swipe && std::abs(event->position().x() - dividerX()) <= kDividerGrab;
    m_drag = onDivider ? Drag::Divider : Drag::Pan;
}

void CompareView::mouseMoveEvent(QMouseEvent* event) {
    const bool near =
        m_layout == Layout::Swipe && std::abs(event->position().x() - dividerX()) <= kDividerGrab;
    setCursor(m_drag == Drag::Divider || near ? Qt::SplitHCursor
              : m_drag == Drag::Pan           ? Qt::ClosedHandCursor
                                              : Qt::OpenHandCursor);
    if (m_drag == Drag::Divider) {
        setDivider(imagePointAt(event->position()).x() / std::max(1, m_exact.width()));
    } else if (m_drag == Drag::Pan) {
        const QPointF moved = event->position() - m_lastMouse;
        m_centre -= moved / scale(paneAt(event->position()));
        keepInView();
        update();
    }
    m_lastMouse = event->position();
}

void CompareView::keepInView() {
    m_centre.setX(std::clamp(m_centre.x(), 0.0, double(m_exact.width())));
    m_centre.setY(std::clamp(m_centre.y(), 0.0, double(m_exact.height())));
}

void CompareView::mouseReleaseEvent(QMouseEvent*) {
    m_drag = Drag::None;
}

void CompareView::mouseDoubleClickEvent(QMouseEvent*) {
    resetView();
}

} // namespace speculum::ui
