#include "accuracy/Plot.hpp"

#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"

#include <QBuffer>
#include <QFont>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cassert>
#include <cmath>

namespace speculum::accuracy {

namespace {

// Tableau's ten categorical colours: distinct for the colour-blind and in greyscale print.
const QColor kPalette[] = {QColor(31, 119, 180),  QColor(255, 127, 14),  QColor(44, 160, 44),
                           QColor(214, 39, 40),   QColor(148, 103, 189), QColor(140, 86, 75),
                           QColor(227, 119, 194), QColor(127, 127, 127), QColor(188, 189, 34),
                           QColor(23, 190, 207)};

QColor seriesColour(int series) {
    return kPalette[static_cast<std::size_t>(series) % std::size(kPalette)];
}

struct Range {
    double lo = 0.0;
    double hi = 1.0;
};

// The data's range with a margin (a fraction of it on each side), so no point or label sits on the frame;
// a single value gets a range around it.
Range paddedRange(double lo, double hi, double margin) {
    if (!(hi > lo)) {
        const double half = std::max(std::abs(lo) * 0.05, 0.5);
        return {lo - half, hi + half};
    }
    const double pad = (hi - lo) * margin;
    return {lo - pad, hi + pad};
}

QString tickText(double value, double step) {
    const int decimals = step >= 1.0 ? 0 : std::min(6, static_cast<int>(std::ceil(-std::log10(step))));
    return QString::number(value, 'f', decimals);
}

} // namespace

std::vector<double> niceTicks(double lo, double hi, int count) {
    std::vector<double> ticks;
    if (!(hi > lo) || count < 1)
        return ticks;
    const double raw = (hi - lo) / count;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step)
        ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
    return ticks;
}

base::Status writePlot(const std::string& path, const PlotSpec& spec, int width, int height) {
    assert(QGuiApplication::instance() && "writePlot(): needs a QGuiApplication for fonts");
    QImage image(width, height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);

    QFont titleFont("DejaVu Sans");
    titleFont.setPixelSize(22);
    titleFont.setBold(true);
    QFont textFont("DejaVu Sans");
    textFont.setPixelSize(14);
    QFont smallFont("DejaVu Sans");
    smallFont.setPixelSize(12);

    const int legendWidth = 250;
    const QRect area(100, 90, width - 100 - legendWidth - 30, height - 90 - 90);

    double xMin = 1e300, xMax = -1e300, yMin = 1e300, yMax = -1e300;
    for (const PlotPoint& pt : spec.points) {
        xMin = std::min(xMin, pt.x);
        xMax = std::max(xMax, pt.x);
        yMin = std::min(yMin, pt.y);
        yMax = std::max(yMax, pt.y);
    }
    if (spec.points.empty())
        xMin = xMax = yMin = yMax = 0.0;
    // Time starts at zero when that costs little room, so bar-like ratios read true.
    Range xr = paddedRange(xMin, xMax, 0.12); // labels sit beside points
    if (xMin >= 0.0 && xMin < 0.5 * xMax)
        xr.lo = 0.0;
    const Range yr = paddedRange(yMin, yMax, 0.08);
    auto toScreen = [&](double x, double y) {
        return QPointF(area.left() + (x - xr.lo) / (xr.hi - xr.lo) * area.width(),
                       area.bottom() - (y - yr.lo) / (yr.hi - yr.lo) * area.height());
    };

    // Title and subtitle.
    p.setPen(Qt::black);
    p.setFont(titleFont);
    p.drawText(QRect(0, 12, width, 30), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.title));
    p.setFont(textFont);
    p.setPen(QColor(80, 80, 80));
    p.drawText(QRect(0, 44, width, 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.subtitle));

    // Grid, ticks and tick labels.
    p.setFont(smallFont);
    const std::vector<double> xTicks = niceTicks(xr.lo, xr.hi, 8);
    const std::vector<double> yTicks = niceTicks(yr.lo, yr.hi, 8);
    const double xStep = xTicks.size() > 1 ? xTicks[1] - xTicks[0] : 1.0;
    const double yStep = yTicks.size() > 1 ? yTicks[1] - yTicks[0] : 1.0;
    for (double x : xTicks) {
        const double sx = toScreen(x, yr.lo).x();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(sx, area.top()), QPointF(sx, area.bottom()));
        p.setPen(QColor(60, 60, 60));
        p.drawText(QRectF(sx - 40, area.bottom() + 6, 80, 18), Qt::AlignHCenter | Qt::AlignTop,
                   tickText(x, xStep));
    }
    for (double y : yTicks) {
        const double sy = toScreen(xr.lo, y).y();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(area.left(), sy), QPointF(area.right(), sy));
        p.setPen(QColor(60, 60, 60));
        p.drawText(QRectF(area.left() - 70, sy - 9, 62, 18), Qt::AlignRight | Qt::AlignVCenter,
                   tickText(y, yStep));
    }
    p.setPen(QPen(QColor(40, 40, 40), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawRect(area);

    // Axis titles.
    p.setFont(textFont);
    p.setPen(Qt::black);
    p.drawText(QRect(area.left(), area.bottom() + 34, area.width(), 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.xLabel));
    p.save();
    p.translate(24, area.center().y());
    p.rotate(-90);
    p.drawText(QRect(-area.height() / 2, -12, area.height(), 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.yLabel));
    p.restore();

    p.setClipRect(area.adjusted(-8, -8, 8, 8));
    std::vector<QRectF> taken; // marker, label and staircase boxes already drawn, for placing labels
    // The Pareto front as a staircase: from each front point right to the next one's cost, then up to its
    // PSNR. Everything above and left of it is out of reach with these settings.
    if (!spec.front.empty()) {
        QPainterPath stairs;
        const PlotPoint& first = spec.points[spec.front.front()];
        stairs.moveTo(toScreen(first.x, yr.lo));
        stairs.lineTo(toScreen(first.x, first.y));
        for (std::size_t k = 1; k < spec.front.size(); ++k) {
            const PlotPoint& a = spec.points[spec.front[k - 1]];
            const PlotPoint& b = spec.points[spec.front[k]];
            stairs.lineTo(toScreen(b.x, a.y));
            stairs.lineTo(toScreen(b.x, b.y));
        }
        const PlotPoint& last = spec.points[spec.front.back()];
        stairs.lineTo(toScreen(xr.hi, last.y));
        p.setPen(QPen(QColor(30, 30, 30, 170), 2.0, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawPath(stairs);
        // Its straight pieces, as thin boxes labels keep clear of.
        for (int e = 1; e < stairs.elementCount(); ++e) {
            const QPointF a = stairs.elementAt(e - 1), b = stairs.elementAt(e);
            taken.push_back(QRectF(a, b).normalized().adjusted(-2, -2, 2, 2));
        }
    }

    // Series lines, in the order the points were given.
    for (std::size_t s = 0; s < spec.series.size(); ++s) {
        QPainterPath line;
        bool started = false;
        for (const PlotPoint& pt : spec.points) {
            if (pt.series != static_cast<int>(s))
                continue;
            if (started)
                line.lineTo(toScreen(pt.x, pt.y));
            else
                line.moveTo(toScreen(pt.x, pt.y));
            started = true;
        }
        QColor c = seriesColour(static_cast<int>(s));
        c.setAlpha(150);
        p.setPen(QPen(c, 1.5));
        p.drawPath(line);
    }

    // Markers: front points get a black ring, the scene's own setting is a diamond.
    std::vector<bool> onFront(spec.points.size(), false);
    for (std::size_t i : spec.front)
        onFront[i] = true;
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const PlotPoint& pt = spec.points[i];
        const QPointF c = toScreen(pt.x, pt.y);
        p.setPen(QPen(Qt::white, 1.0));
        p.setBrush(seriesColour(pt.series));
        if (pt.sceneSetting) {
            const double r = 9.0;
            const QPointF diamond[] = {c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r),
                                       c + QPointF(-r, 0)};
            p.setPen(QPen(Qt::black, 1.5));
            p.drawPolygon(diamond, 4);
        } else {
            p.drawEllipse(c, 5.5, 5.5);
        }
        if (onFront[i]) {
            p.setPen(QPen(Qt::black, 1.8));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(c, 10.0, 10.0);
        }
        taken.push_back(QRectF(c.x() - 10, c.y() - 10, 20, 20));
    }

    // Labels: the first of eight places around the point that overlaps nothing drawn yet.
    p.setFont(smallFont);
    const QFontMetricsF metrics(smallFont);
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const PlotPoint& pt = spec.points[i];
        const QString text = QString::fromStdString(pt.label);
        const QPointF c = toScreen(pt.x, pt.y);
        const double w = metrics.horizontalAdvance(text) + 4, h = metrics.height();
        // Past the front's ring (radius 10), so a label never sits on it.
        const QPointF offsets[] = {{14, -h / 2},  {-14 - w, -h / 2},  {-w / 2, -13 - h}, {-w / 2, 13},
                                   {11, -11 - h}, {-11 - w, -11 - h}, {11, 11},          {-11 - w, 11}};
        QRectF chosen(c + offsets[0], QSizeF(w, h));
        for (const QPointF& o : offsets) {
            const QRectF box(c + o, QSizeF(w, h));
            const bool inside = QRectF(area).contains(box);
            const bool clear =
                std::none_of(taken.begin(), taken.end(), [&](const QRectF& t) { return t.intersects(box); });
            if (inside && clear) {
                chosen = box;
                break;
            }
        }
        taken.push_back(chosen);
        p.setPen(seriesColour(pt.series).darker(140));
        p.drawText(chosen, Qt::AlignLeft | Qt::AlignVCenter, text);
    }
    p.setClipping(false);

    // Legend.
    const int lx = area.right() + 24;
    int ly = area.top();
    p.setFont(textFont);
    p.setPen(Qt::black);
    auto legendRow = [&](const QString& text) {
        p.setPen(Qt::black);
        p.drawText(QRect(lx + 30, ly - 10, legendWidth - 30, 20), Qt::AlignLeft | Qt::AlignVCenter, text);
        ly += 26;
    };
    for (std::size_t s = 0; s < spec.series.size(); ++s) {
        p.setPen(QPen(Qt::white, 1.0));
        p.setBrush(seriesColour(static_cast<int>(s)));
        p.drawEllipse(QPointF(lx + 12, ly), 5.5, 5.5);
        legendRow(QString::fromStdString(spec.series[s]));
    }
    ly += 8;
    p.setPen(QPen(QColor(30, 30, 30, 170), 2.0, Qt::DashLine));
    p.drawLine(QPointF(lx, ly), QPointF(lx + 24, ly));
    legendRow("Pareto front");
    p.setPen(QPen(Qt::black, 1.8));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(QPointF(lx + 12, ly), 10.0, 10.0);
    legendRow("on the front");
    {
        const QPointF c(lx + 12, ly);
        const QPointF diamond[] = {c + QPointF(0, -9), c + QPointF(9, 0), c + QPointF(0, 9),
                                   c + QPointF(-9, 0)};
        p.setPen(QPen(Qt::black, 1.5));
        p.setBrush(QColor(200, 200, 200));
        p.drawPolygon(diamond, 4);
    }
    legendRow("the scene's own setting");
    p.end();

    // Encoded in memory, then staged and checked like every other file (base::AtomicFile): QSaveFile
    // would commit a plot whose buffered write failed on a full disk.
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG") || png.isEmpty())
        return base::Error{base::printable(path, 200) + ": cannot encode the plot as PNG"};
    return base::writeFileAtomically(path,
                                     std::string_view(png.constData(), static_cast<std::size_t>(png.size())));
}

} // namespace speculum::accuracy
