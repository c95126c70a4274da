#include "editor/ui/ViewportOverlay.hpp"

#include "editor/ui/AxisGizmo.hpp"
#include "editor/ui/ViewGrid.hpp"
#include "editor/ui/Viewport.hpp"

#include <QFontMetricsF>
#include <QPainter>
#include <QSettings>
#include <algorithm>
#include <utility>

namespace speculum::ui {

namespace {

const QString kGuidesKey = QStringLiteral("view/showGuides");

} // namespace

ViewportOverlay::ViewportOverlay(Viewport& viewport)
    : QWidget(&viewport)
    , m_viewport(viewport) {
    setObjectName(QStringLiteral("viewportOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setAutoFillBackground(false);
    setFocusPolicy(Qt::NoFocus);
    m_guides = QSettings().value(kGuidesKey, true).toBool();
}

void ViewportOverlay::setGuidesVisible(bool on) {
    if (on == m_guides) {
        return;
    }
    m_guides = on;
    QSettings().setValue(kGuidesKey, on);
    update();
    m_viewport.update(); // the grid and the camera are in the frame
}

// The grid and the scene camera are drawn by the renderer, in the frame, behind what stands in front of them
// (Viewport::guideLines); the pivot is a mark of the view, not of the scene: it stays on top.
void ViewportOverlay::paintGuidesUnder(QPainter& painter) {
    const render::Camera& view = m_viewport.viewCamera();
    const QSizeF size(width(), height());
    if (auto pivot = ClipProjection(view, size).point(view.target)) {
        paintPivot(painter, *pivot);
    }
}

void ViewportOverlay::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const bool guides = m_guides && m_viewport.renderer() != nullptr;
    if (guides) {
        paintGuidesUnder(painter);
    }
    m_viewport.paintOverlay(painter);
    if (guides) {
        paintAxisGizmo(painter, m_viewport.viewCamera(), QSizeF(width(), height()));
    }
    if (m_viewport.renderer() != nullptr && m_viewport.lastFrameReduced()) {
        paintPreviewLabel(painter);
    }
    if (m_viewport.renderer() != nullptr && m_viewport.screenSpaceSourcesVisible()) {
        paintSourcesLegend(painter);
    }
}

void ViewportOverlay::paintSourcesLegend(QPainter& painter) {
    // Top left: what the screen-space debug view's colours mean (the trace's own colours, blended where
    // its confidence fades one source into the next).
    const std::pair<QColor, QString> entries[] = {
        {QColor(0, 255, 0), tr("met in the image")},
        {QColor(0, 0, 255), tr("the reflector's map")},
        {QColor(255, 0, 0), tr("the background")},
    };
    QFont font = painter.font();
    font.setPixelSize(12);
    painter.save();
    painter.setFont(font);
    const QFontMetricsF metrics(font);
    const double line = metrics.height() + 4.0;
    double widest = metrics.horizontalAdvance(tr("Screen-space reflections:"));
    for (const auto& entry : entries)
        widest = std::max(widest, 18.0 + metrics.horizontalAdvance(entry.second));
    const QRectF box(10.0, 10.0, widest + 16.0, line * 4 + 8.0);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 150));
    painter.drawRoundedRect(box, 4.0, 4.0);
    painter.setPen(QColor(255, 255, 255, 230));
    painter.drawText(QPointF(box.left() + 8.0, box.top() + 4.0 + metrics.ascent()),
                     tr("Screen-space reflections:"));
    for (int i = 0; i < 3; ++i) {
        const double top = box.top() + 4.0 + line * (i + 1);
        painter.fillRect(QRectF(box.left() + 8.0, top + 2.0, 12.0, metrics.height() - 4.0), entries[i].first);
        painter.drawText(QPointF(box.left() + 26.0, top + metrics.ascent()), entries[i].second);
    }
    painter.restore();
}

void ViewportOverlay::paintPreviewLabel(QPainter& painter) {
    // Bottom left, out of the axis gizmo's corner: the frame on screen is a reduced-resolution preview
    // (adaptive resolution while navigating); the full frame follows when the view rests.
    const QString text = tr("preview");
    QFont font = painter.font();
    font.setPixelSize(12);
    painter.save();
    painter.setFont(font);
    const QRectF box = QFontMetricsF(font).boundingRect(text).adjusted(-6, -3, 6, 3);
    const QRectF at(QPointF(10.0, height() - 10.0 - box.height()), box.size());
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 130));
    painter.drawRoundedRect(at, 4.0, 4.0);
    painter.setPen(QColor(255, 255, 255, 220));
    painter.drawText(at, Qt::AlignCenter, text);
    painter.restore();
}

} // namespace speculum::ui
