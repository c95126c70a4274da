#include "editor/ui/Icons.hpp"

#include <QHash>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QRadialGradient>

namespace speculum::ui {

NodeKind nodeKind(const scene::NodeData& d) {
    if (d.reflector) {
        return NodeKind::Reflector;
    }
    if (d.mirror) {
        return NodeKind::Mirror;
    }
    if (d.light) {
        return NodeKind::Light;
    }
    if (d.mesh) {
        return NodeKind::Mesh;
    }
    return NodeKind::Empty;
}

QString kindName(NodeKind kind) {
    switch (kind) {
    case NodeKind::Empty:
        return QObject::tr("Empty (group)");
    case NodeKind::Mesh:
        return QObject::tr("Mesh");
    case NodeKind::Mirror:
        return QObject::tr("Planar mirror");
    case NodeKind::Reflector:
        return QObject::tr("Curved reflector");
    case NodeKind::Light:
        return QObject::tr("Light");
    case NodeKind::Camera:
        return QObject::tr("Camera");
    }
    return {};
}

namespace {

void paintIcon(QPainter& p, NodeKind kind) {
    p.setRenderHint(QPainter::Antialiasing);
    const QPen outline(QColor(40, 40, 48), 1.5);
    switch (kind) {
    case NodeKind::Empty:
        p.setPen(QPen(QColor(120, 120, 130), 2.0));
        p.drawLine(QPointF(16, 5), QPointF(16, 27));
        p.drawLine(QPointF(5, 16), QPointF(27, 16));
        p.drawEllipse(QPointF(16, 16), 4, 4);
        break;
    case NodeKind::Mesh: {
        // An isometric cube: top, left and right faces.
        const QPointF top[] = {{16, 4}, {27, 10}, {16, 16}, {5, 10}};
        const QPointF left[] = {{5, 10}, {16, 16}, {16, 28}, {5, 22}};
        const QPointF right[] = {{16, 16}, {27, 10}, {27, 22}, {16, 28}};
        p.setPen(outline);
        p.setBrush(QColor(140, 180, 235));
        p.drawPolygon(top, 4);
        p.setBrush(QColor(80, 125, 200));
        p.drawPolygon(left, 4);
        p.setBrush(QColor(55, 95, 165));
        p.drawPolygon(right, 4);
        break;
    }
    case NodeKind::Mirror: {
        QLinearGradient glass(4, 4, 28, 28);
        glass.setColorAt(0.0, QColor(215, 240, 250));
        glass.setColorAt(1.0, QColor(95, 160, 195));
        p.setPen(QPen(QColor(70, 60, 50), 2.0));
        p.setBrush(glass);
        p.drawRoundedRect(QRectF(6, 3, 20, 26), 2, 2);
        p.setPen(QPen(QColor(255, 255, 255, 220), 2.0));
        p.drawLine(QPointF(10, 13), QPointF(16, 7));
        p.drawLine(QPointF(10, 20), QPointF(21, 9));
        break;
    }
    case NodeKind::Reflector: {
        QRadialGradient chrome(QPointF(12, 11), 16);
        chrome.setColorAt(0.0, Qt::white);
        chrome.setColorAt(0.35, QColor(190, 195, 205));
        chrome.setColorAt(0.8, QColor(70, 75, 90));
        chrome.setColorAt(1.0, QColor(150, 155, 170));
        p.setPen(outline);
        p.setBrush(chrome);
        p.drawEllipse(QPointF(16, 16), 12, 12);
        break;
    }
    case NodeKind::Light: {
        p.setPen(QPen(QColor(200, 150, 20), 2.0));
        for (int i = 0; i < 8; ++i) {
            p.save();
            p.translate(16, 16);
            p.rotate(45.0 * i);
            p.drawLine(QPointF(0, 9), QPointF(0, 14));
            p.restore();
        }
        p.setPen(QPen(QColor(160, 110, 10), 1.5));
        p.setBrush(QColor(255, 215, 70));
        p.drawEllipse(QPointF(16, 16), 7, 7);
        break;
    }
    case NodeKind::Camera:
        p.setPen(outline);
        p.setBrush(QColor(90, 90, 100));
        p.drawRoundedRect(QRectF(3, 10, 19, 14), 2, 2);
        p.drawPolygon(QPolygonF({QPointF(22, 14), QPointF(29, 10), QPointF(29, 24), QPointF(22, 20)}));
        p.setBrush(QColor(150, 200, 240));
        p.drawEllipse(QPointF(12, 17), 4, 4);
        break;
    }
}

} // namespace

QIcon kindIcon(NodeKind kind) {
    static QHash<int, QIcon> cache;
    auto it = cache.find(int(kind));
    if (it != cache.end()) {
        return *it;
    }
    QIcon icon;
    for (int size : {16, 32, 64}) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.scale(size / 32.0, size / 32.0);
        paintIcon(p, kind);
        p.end();
        icon.addPixmap(pixmap);
    }
    cache.insert(int(kind), icon);
    return icon;
}

} // namespace speculum::ui
