#pragma once

#include "accuracy/Results.hpp"

#include <optional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// The error a family is judged by: the pixels its settings change. Map and parallax settings change only
// the reflector's pixels, mirror settings the mirrors' pixels; shadows and tessellation the whole frame.
enum class Metric { Psnr, PsnrMirrors, PsnrReflector };
Metric focusMetric(Family family);
std::string metricField(Metric metric); // "psnr", "psnrMirrors", "psnrReflector"
std::string metricAxisLabel(Metric metric);

// The family's metric for a record, falling back to the whole frame's PSNR when the frame has no pixels
// of that kind (a mirror scene whose mirrors are out of view).
double focusValue(const Record& record, Metric metric);
Metric effectiveMetric(const std::vector<const Record*>& records, Metric wanted);

// The metric a family's rows are judged by: focusMetric, falling back as effectiveMetric does; the
// screen-space family of a scene without mirrors sweeps the reflector, so it is judged on its pixels.
Metric judgedMetric(Family family, const std::vector<const Record*>& rows);

// FLIP's counterpart of focusValue: the mean LDR-FLIP on the family's pixels (falling back to the whole
// frame's as focusValue does); none for a record without perceptual figures.
std::optional<double> focusFlip(const Record& record, Metric metric);
std::string flipAxisLabel(Metric metric);

// One just-noticeable difference in mean FLIP (render::metrics::flipJnd: a ΔE*ab of 2.3).
double flipJnd();

// The cost compared: GPU time when every record has it, else CPU time.
bool allGpuTimed(const std::vector<const Record*>& records);
double costOf(const Record& record, bool gpu);

struct Point {
    double cost = 0.0; // ms, lower is better
    double psnr = 0.0; // dB, higher is better; for FLIP's points (flipPoint) minus the FLIP
};

// A point judged by FLIP: its value negated, so that higher is better as for PSNR and the front and
// cheapestWithin apply unchanged.
inline Point flipPoint(double cost, double flip) {
    return {cost, -flip};
}

// Indices of the points no other point beats in both cost and PSNR (ties in cost keep the better PSNR),
// ordered by cost.
std::vector<std::size_t> paretoFront(const std::vector<Point>& points);

// The front of a whole run as one chart draws it: every record's frame time (frameMs) against the whole
// frame's PSNR, across families. Indices into `records`, ordered by time.
std::vector<std::size_t> paretoFront(const std::vector<Record>& records);

// The cheapest point whose PSNR is within `dB` of the best one.
std::optional<std::size_t> cheapestWithin(const std::vector<Point>& points, double dB);

// The cost of one series (points in the order of rising accuracy, e.g. resolution) at a target PSNR:
// linear interpolation between the first point that reaches the target and the point before it; the
// nearest point reaching it, for the setting to pick; nothing if no point reaches it.
struct CostAtError {
    std::optional<double> interpolatedCost;
    std::optional<std::size_t> firstReaching;
};
CostAtError costAtError(const std::vector<Point>& series, double targetPsnr);

// The PSNR every series reaches: the smallest of the series' best values.
double commonTarget(const std::vector<std::vector<Point>>& series);

} // namespace speculum::accuracy
