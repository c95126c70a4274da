#include "editor/ui/ViewportOverlay.hpp"

#include "editor/ui/AxisGizmo.hpp"
#include "editor/ui/ViewGrid.hpp"
#include "editor/ui/Viewport.hpp"

#include <QFontMetricsF>
#include <QPainter>
#include <QSettings>

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
