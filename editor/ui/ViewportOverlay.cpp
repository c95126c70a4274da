#include "editor/ui/ViewportOverlay.hpp"

#include "editor/ui/Viewport.hpp"

#include <QPainter>

namespace speculum::ui {

ViewportOverlay::ViewportOverlay(Viewport& viewport)
    : QWidget(&viewport)
    , m_viewport(viewport) {
    setObjectName(QStringLiteral("viewportOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setAutoFillBackground(false);
    setFocusPolicy(Qt::NoFocus);
}

void ViewportOverlay::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    m_viewport.paintOverlay(painter);
}

} // namespace speculum::ui
