#include "editor/ui/AppIdentity.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QPainter>
#include <QPixmap>
#include <QRadialGradient>

namespace speculum::ui {

QString examplesFolder() {
    const QString installed = QDir(QCoreApplication::applicationDirPath())
                                  .absoluteFilePath(QStringLiteral("../share/speculum/scenes"));
    for (const QString& candidate : {installed, QStringLiteral(SPECULUM_SOURCE_DIR "/resources/scenes")}) {
        if (QFileInfo(candidate).isDir()) {
            return QDir(candidate).canonicalPath();
        }
    }
    return {};
}

namespace {

// resources/desktop/org.speculum.Speculum.svg, drawn: a red ball on a mirror, and its reflection.
QPixmap drawnIcon(int size) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 128.0, size / 128.0);
    QLinearGradient mirror(0, 64, 0, 120);
    mirror.setColorAt(0, QColor(0xb9, 0xd7, 0xef));
    mirror.setColorAt(1, QColor(0x3c, 0x6e, 0x99));
    p.setPen(Qt::NoPen);
    p.setBrush(mirror);
    p.drawRoundedRect(QRectF(8, 64, 112, 56), 10, 10);
    const auto ball = [](QPointF highlight) {
        QRadialGradient g(highlight, 26 * 1.4);
        g.setColorAt(0, QColor(0xff, 0xb3, 0xa7));
        g.setColorAt(0.35, QColor(0xe0, 0x30, 0x1e));
        g.setColorAt(1, QColor(0x6e, 0x0e, 0x06));
        return g;
    };
    p.setOpacity(0.75);
    p.setBrush(ball({58, 98}));
    p.drawEllipse(QPointF(64, 90), 26, 26);
    p.setOpacity(1.0);
    p.setBrush(QColor(0xdf, 0xee, 0xfa));
    p.drawRoundedRect(QRectF(8, 62, 112, 4), 2, 2);
    p.setBrush(ball({58, 30}));
    p.drawEllipse(QPointF(64, 38), 26, 26);
    return pixmap;
}

} // namespace

QIcon applicationIcon() {
    QIcon icon = QIcon::fromTheme(QString::fromLatin1(kApplicationId));
    if (!icon.isNull()) {
        return icon;
    }
    for (int size : {16, 24, 32, 48, 64, 128, 256}) {
        icon.addPixmap(drawnIcon(size));
    }
    return icon;
}

} // namespace speculum::ui
