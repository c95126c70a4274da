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

namespace {

constexpr int kLegendWidth = 250;

struct PlotFonts {
    QFont title;
    QFont text;
    QFont small;
};

PlotFonts plotFonts() {
    QFont titleFont("DejaVu Sans");
    titleFont.setPixelSize(22);
    titleFont.setBold(true);
    QFont textFont("DejaVu Sans");
    textFont.setPixelSize(14);
    QFont smallFont("DejaVu Sans");
    smallFont.setPixelSize(12);
    return {titleFont, textFont, smallFont};
}

// The plot's frame in the image and the data ranges it shows, and how a data point maps into it.
struct PlotArea {
    QRect rect;
    Range x;
    Range y;
    bool yDown = false;
    bool logX = false; // the ranges are then of log10 of the values
    bool logY = false;

    double axisX(double value) const { return logX ? std::log10(value) : value; }
    double axisY(double value) const { return logY ? std::log10(value) : value; }
    // A point in axis units (the ranges' units) on the screen.
    QPointF onAxes(double u, double v) const {
        const double up = (v - y.lo) / (y.hi - y.lo) * rect.height();
        return QPointF(rect.left() + (u - x.lo) / (x.hi - x.lo) * rect.width(),
                       yDown ? rect.top() + up : rect.bottom() - up);
    }
    QPointF toScreen(double px, double py) const { return onAxes(axisX(px), axisY(py)); }
    double worstY() const { return yDown ? y.hi : y.lo; } // the bottom edge's value, axis units
};

// Ticks on a log10 range: 1, 2 and 5 times each power of ten inside it (values, not logs).
std::vector<double> logTicks(double lo, double hi) {
    std::vector<double> ticks;
    for (int k = static_cast<int>(std::floor(lo)); k <= static_cast<int>(std::ceil(hi)); ++k)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, k);
            if (std::log10(v) >= lo && std::log10(v) <= hi)
                ticks.push_back(v);
        }
    if (ticks.empty()) // a range too narrow to hold a 1, 2 or 5: its ends
        ticks = {std::pow(10.0, lo), std::pow(10.0, hi)};
    return ticks;
}

// Room on the left and below for the ticks and axis titles, on the right for the legend; the ranges hold
// every point with a margin.
PlotArea plotArea(const PlotSpec& spec, int width, int height) {
    double xMin = 1e300, xMax = -1e300, yMin = 1e300, yMax = -1e300;
    for (const PlotPoint& pt : spec.points) {
        const double px = spec.logX ? std::log10(pt.x) : pt.x, py = spec.logY ? std::log10(pt.y) : pt.y;
        xMin = std::min(xMin, px);
        xMax = std::max(xMax, px);
        yMin = std::min(yMin, py);
        yMax = std::max(yMax, py);
    }
    if (spec.points.empty())
        xMin = xMax = yMin = yMax = 0.0;
    PlotArea area;
    area.rect = QRect(100, 90, width - 100 - kLegendWidth - 30, height - 90 - 90);
    // Time starts at zero when that costs little room, so bar-like ratios read true.
    area.x = paddedRange(xMin, xMax, 0.12); // labels sit beside points
    if (!spec.logX && xMin >= 0.0 && xMin < 0.5 * xMax)
        area.x.lo = 0.0;
    area.y = paddedRange(yMin, yMax, 0.08);
    area.yDown = spec.yDown;
    area.logX = spec.logX;
    area.logY = spec.logY;
    return area;
}

void drawTitles(QPainter& p, const PlotSpec& spec, const PlotFonts& fonts, int width) {
    p.setPen(Qt::black);
    p.setFont(fonts.title);
    p.drawText(QRect(0, 12, width, 30), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.title));
    p.setFont(fonts.text);
    p.setPen(QColor(80, 80, 80));
    p.drawText(QRect(0, 44, width, 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.subtitle));
}

// Grid lines at the ticks, the tick labels, and the frame around the area.
void drawGrid(QPainter& p, const PlotArea& plot, const PlotFonts& fonts) {
    const QRect& area = plot.rect;
    p.setFont(fonts.small);
    const std::vector<double> xTicks =
        plot.logX ? logTicks(plot.x.lo, plot.x.hi) : niceTicks(plot.x.lo, plot.x.hi, 8);
    const std::vector<double> yTicks =
        plot.logY ? logTicks(plot.y.lo, plot.y.hi) : niceTicks(plot.y.lo, plot.y.hi, 8);
    // Log ticks are labelled with as many digits as the smallest needs.
    const double xStep = plot.logX ? xTicks.front() : xTicks.size() > 1 ? xTicks[1] - xTicks[0] : 1.0;
    const double yStep = plot.logY ? yTicks.front() : yTicks.size() > 1 ? yTicks[1] - yTicks[0] : 1.0;
    for (double x : xTicks) {
        const double sx = plot.onAxes(plot.axisX(x), plot.y.lo).x();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(sx, area.top()), QPointF(sx, area.bottom()));
        p.setPen(QColor(60, 60, 60));
        p.drawText(QRectF(sx - 40, area.bottom() + 6, 80, 18), Qt::AlignHCenter | Qt::AlignTop,
                   tickText(x, xStep));
    }
    for (double y : yTicks) {
        const double sy = plot.onAxes(plot.x.lo, plot.axisY(y)).y();
        p.setPen(QPen(QColor(225, 225, 225), 1));
        p.drawLine(QPointF(area.left(), sy), QPointF(area.right(), sy));
        p.setPen(QColor(60, 60, 60));
        p.drawText(QRectF(area.left() - 70, sy - 9, 62, 18), Qt::AlignRight | Qt::AlignVCenter,
                   tickText(y, yStep));
    }
    p.setPen(QPen(QColor(40, 40, 40), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawRect(area);
}

void drawAxisTitles(QPainter& p, const PlotSpec& spec, const QRect& area, const PlotFonts& fonts) {
    p.setFont(fonts.text);
    p.setPen(Qt::black);
    p.drawText(QRect(area.left(), area.bottom() + 34, area.width(), 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.xLabel));
    p.save();
    p.translate(24, area.center().y());
    p.rotate(-90);
    p.drawText(QRect(-area.height() / 2, -12, area.height(), 24), Qt::AlignHCenter | Qt::AlignVCenter,
               QString::fromStdString(spec.yLabel));
    p.restore();
}

// The Pareto front as a staircase: from each front point right to the next one's cost, then up to its
// PSNR. Everything above and left of it is out of reach with these settings. Its straight pieces go into
// `taken`, as thin boxes labels keep clear of.
void drawFront(QPainter& p, const PlotSpec& spec, const PlotArea& plot, std::vector<QRectF>& taken) {
    if (spec.front.empty())
        return;
    QPainterPath stairs;
    const PlotPoint& first = spec.points[spec.front.front()];
    stairs.moveTo(plot.onAxes(plot.axisX(first.x), plot.worstY()));
    stairs.lineTo(plot.toScreen(first.x, first.y));
    for (std::size_t k = 1; k < spec.front.size(); ++k) {
        const PlotPoint& a = spec.points[spec.front[k - 1]];
        const PlotPoint& b = spec.points[spec.front[k]];
        stairs.lineTo(plot.toScreen(b.x, a.y));
        stairs.lineTo(plot.toScreen(b.x, b.y));
    }
    const PlotPoint& last = spec.points[spec.front.back()];
    stairs.lineTo(plot.onAxes(plot.x.hi, plot.axisY(last.y)));
    p.setPen(QPen(QColor(30, 30, 30, 170), 2.0, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawPath(stairs);
    for (int e = 1; e < stairs.elementCount(); ++e) {
        const QPointF a = stairs.elementAt(e - 1), b = stairs.elementAt(e);
        taken.push_back(QRectF(a, b).normalized().adjusted(-2, -2, 2, 2));
    }
}

// Series lines, in the order the points were given.
void drawSeriesLines(QPainter& p, const PlotSpec& spec, const PlotArea& plot) {
    for (std::size_t s = 0; s < spec.series.size(); ++s) {
        QPainterPath line;
        bool started = false;
        for (const PlotPoint& pt : spec.points) {
            if (pt.series != static_cast<int>(s))
                continue;
            if (started)
                line.lineTo(plot.toScreen(pt.x, pt.y));
            else
                line.moveTo(plot.toScreen(pt.x, pt.y));
            started = true;
        }
        QColor c = seriesColour(static_cast<int>(s));
        c.setAlpha(150);
        p.setPen(QPen(c, 1.5));
        p.drawPath(line);
    }
}

// A diamond of "radius" r around c, with the painter's pen and brush: the scene's own setting.
void drawDiamond(QPainter& p, QPointF c, double r) {
    const QPointF diamond[] = {c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0)};
    p.drawPolygon(diamond, 4);
}

// Markers: front points get a black ring, the scene's own setting is a diamond. Each marker's box goes
// into `taken`.
void drawMarkers(QPainter& p, const PlotSpec& spec, const PlotArea& plot, std::vector<QRectF>& taken) {
    std::vector<bool> onFront(spec.points.size(), false);
    for (std::size_t i : spec.front)
        onFront[i] = true;
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        const PlotPoint& pt = spec.points[i];
        const QPointF c = plot.toScreen(pt.x, pt.y);
        p.setPen(QPen(Qt::white, 1.0));
        p.setBrush(seriesColour(pt.series));
        if (pt.sceneSetting) {
            p.setPen(QPen(Qt::black, 1.5));
            drawDiamond(p, c, 9.0);
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
}

// Labels: the first of eight places around the point that overlaps nothing drawn yet (`taken`), inside
// the area; the first place when none is free.
void drawLabels(QPainter& p, const PlotSpec& spec, const PlotArea& plot, const PlotFonts& fonts,
                std::vector<QRectF>& taken) {
    p.setFont(fonts.small);
    const QFontMetricsF metrics(fonts.small);
    for (const PlotPoint& pt : spec.points) {
        const QString text = QString::fromStdString(pt.label);
        const QPointF c = plot.toScreen(pt.x, pt.y);
        const double w = metrics.horizontalAdvance(text) + 4, h = metrics.height();
        // Past the front's ring (radius 10), so a label never sits on it.
        const QPointF offsets[] = {{14, -h / 2},  {-14 - w, -h / 2},  {-w / 2, -13 - h}, {-w / 2, 13},
                                   {11, -11 - h}, {-11 - w, -11 - h}, {11, 11},          {-11 - w, 11}};
        QRectF chosen(c + offsets[0], QSizeF(w, h));
        for (const QPointF& o : offsets) {
            const QRectF box(c + o, QSizeF(w, h));
            const bool inside = QRectF(plot.rect).contains(box);
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
}

// Right of the area: a row per series, then the front's line, its ring and the scene's diamond.
void drawLegend(QPainter& p, const PlotSpec& spec, const QRect& area, const PlotFonts& fonts) {
    const int lx = area.right() + 24;
    int ly = area.top();
    p.setFont(fonts.text);
    p.setPen(Qt::black);
    auto legendRow = [&](const QString& text) {
        p.setPen(Qt::black);
        p.drawText(QRect(lx + 30, ly - 10, kLegendWidth - 30, 20), Qt::AlignLeft | Qt::AlignVCenter, text);
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
    p.setPen(QPen(Qt::black, 1.5));
    p.setBrush(QColor(200, 200, 200));
    drawDiamond(p, QPointF(lx + 12, ly), 9.0);
    legendRow("the scene's own setting");
}

} // namespace

base::Status writePlot(const std::string& path, const PlotSpec& spec, int width, int height) {
    assert(QGuiApplication::instance() && "writePlot(): needs a QGuiApplication for fonts");
    QImage image(width, height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    const PlotFonts fonts = plotFonts();
    const PlotArea plot = plotArea(spec, width, height);

    // Each step leaves the painter's pen and brush to the next, which sets what it needs.
    drawTitles(p, spec, fonts, width);
    drawGrid(p, plot, fonts);
    drawAxisTitles(p, spec, plot.rect, fonts);
    p.setClipRect(plot.rect.adjusted(-8, -8, 8, 8));
    std::vector<QRectF> taken; // marker, label and staircase boxes already drawn, for placing labels
    drawFront(p, spec, plot, taken);
    drawSeriesLines(p, spec, plot);
    drawMarkers(p, spec, plot, taken);
    drawLabels(p, spec, plot, fonts, taken);
    p.setClipping(false);
    drawLegend(p, spec, plot.rect, fonts);
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
