#include "accuracy/Analysis.hpp"

#include "render/metrics/Flip.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace speculum::accuracy {

Metric focusMetric(Family family) {
    switch (family) {
    case Family::Envmap:
    case Family::Parallax:
    case Family::Bounces:
    case Family::Update:
        return Metric::PsnrReflector;
    case Family::MirrorTechnique:
    case Family::ScreenSpace:
    case Family::MirrorDepth:
    case Family::ReflectedDetail: // whole-frame PSNR where no mirror shows (a reflector's map only)
        return Metric::PsnrMirrors;
    default:
        return Metric::Psnr;
    }
}

std::string metricField(Metric metric) {
    switch (metric) {
    case Metric::PsnrMirrors:
        return "psnrMirrors";
    case Metric::PsnrReflector:
        return "psnrReflector";
    default:
        return "psnr";
    }
}

std::string metricAxisLabel(Metric metric) {
    switch (metric) {
    case Metric::PsnrMirrors:
        return "PSNR on mirror pixels (dB, higher is better)";
    case Metric::PsnrReflector:
        return "PSNR on reflector pixels (dB, higher is better)";
    default:
        return "PSNR of the whole frame (dB, higher is better)";
    }
}

double focusValue(const Record& record, Metric metric) {
    if (metric == Metric::PsnrMirrors && record.psnrMirrors)
        return *record.psnrMirrors;
    if (metric == Metric::PsnrReflector && record.psnrReflector)
        return *record.psnrReflector;
    return record.psnr;
}

Metric judgedMetric(Family family, const std::vector<const Record*>& rows) {
    const bool mirrors =
        std::any_of(rows.begin(), rows.end(), [](const Record* r) { return r->config.series == "planar"; });
    return effectiveMetric(rows, family == Family::ScreenSpace && !mirrors ? Metric::PsnrReflector
                                                                           : focusMetric(family));
}

std::optional<double> focusFlip(const Record& record, Metric metric) {
    if (!record.perceptual)
        return std::nullopt;
    if (metric == Metric::PsnrMirrors && record.flipMirrors)
        return record.flipMirrors;
    if (metric == Metric::PsnrReflector && record.flipReflector)
        return record.flipReflector;
    return record.flip;
}

std::string flipAxisLabel(Metric metric) {
    switch (metric) {
    case Metric::PsnrMirrors:
        return "mean FLIP on mirror pixels (lower is better)";
    case Metric::PsnrReflector:
        return "mean FLIP on reflector pixels (lower is better)";
    default:
        return "mean FLIP of the whole frame (lower is better)";
    }
}

double flipJnd() {
    return render::metrics::flipJnd();
}

Metric effectiveMetric(const std::vector<const Record*>& records, Metric wanted) {
    const bool all = std::all_of(records.begin(), records.end(), [&](const Record* r) {
        return wanted == Metric::Psnr ||
               (wanted == Metric::PsnrMirrors ? r->psnrMirrors.has_value() : r->psnrReflector.has_value());
    });
    return all ? wanted : Metric::Psnr;
}

bool allGpuTimed(const std::vector<const Record*>& records) {
    return std::all_of(records.begin(), records.end(), [](const Record* r) { return r->gpuMs >= 0.0; });
}

double costOf(const Record& record, bool gpu) {
    return gpu ? record.gpuMs : record.cpuMs;
}

std::vector<std::size_t> paretoFront(const std::vector<Point>& points) {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (points[a].cost != points[b].cost)
            return points[a].cost < points[b].cost;
        return points[a].psnr > points[b].psnr;
    });
    std::vector<std::size_t> front;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t i : order)
        if (points[i].psnr > best) {
            front.push_back(i);
            best = points[i].psnr;
        }
    return front;
}

std::vector<std::size_t> paretoFront(const std::vector<Record>& records) {
    std::vector<Point> points;
    points.reserve(records.size());
    for (const Record& r : records)
        points.push_back({frameMs(r), r.psnr});
    return paretoFront(points);
}

std::optional<std::size_t> cheapestWithin(const std::vector<Point>& points, double dB) {
    if (points.empty())
        return std::nullopt;
    double best = -std::numeric_limits<double>::infinity();
    for (const Point& p : points)
        best = std::max(best, p.psnr);
    std::optional<std::size_t> cheapest;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].psnr >= best - dB && (!cheapest || points[i].cost < points[*cheapest].cost))
            cheapest = i;
    return cheapest;
}

CostAtError costAtError(const std::vector<Point>& series, double targetPsnr) {
    CostAtError out;
    for (std::size_t i = 0; i < series.size(); ++i) {
        if (series[i].psnr < targetPsnr)
            continue;
        out.firstReaching = i;
        if (i == 0 || series[i - 1].psnr >= series[i].psnr) {
            out.interpolatedCost = series[i].cost;
        } else {
            const Point& a = series[i - 1];
            const Point& b = series[i];
            const double t = (targetPsnr - a.psnr) / (b.psnr - a.psnr);
            out.interpolatedCost = a.cost + t * (b.cost - a.cost);
        }
        break;
    }
    return out;
}

double commonTarget(const std::vector<std::vector<Point>>& series) {
    double target = std::numeric_limits<double>::infinity();
    for (const auto& s : series) {
        double best = -std::numeric_limits<double>::infinity();
        for (const Point& p : s)
            best = std::max(best, p.psnr);
        target = std::min(target, best);
    }
    return target;
}

} // namespace speculum::accuracy
