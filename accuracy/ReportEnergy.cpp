#include "accuracy/ReportEnergy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace speculum::accuracy {

namespace {

std::string percent(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", 100.0 * value);
    return text;
}

std::string number(const char* pattern, double value) {
    char text[32];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

std::string glossyPath(const Record& record) {
    if (record.config.label == "mip")
        return "mip";
    const std::string& series = record.config.series;
    return series.substr(series.rfind(' ') + 1);
}

std::optional<std::string> energyNote(const Record& record, double roughness,
                                      const std::vector<FurnaceRow>& furnace) {
    const std::string path = glossyPath(record);
    // Only the surfaces the configuration's frame shows.
    auto inView = [&](const FurnaceRow& row) {
        return row.surface == "reflector" ? record.psnrReflector.has_value() : record.psnrMirrors.has_value();
    };
    std::optional<double> worst;
    for (const FurnaceRow& row : furnace)
        if (row.path == path && std::abs(row.roughness - roughness) < 1e-6 && inView(row))
            if (!worst || std::abs(row.energy() - 1.0) > std::abs(*worst - 1.0))
                worst = row.energy();
    if (!worst)
        return std::nullopt;
    const double energyError = std::abs(*worst - 1.0);
    std::string note =
        "in the white furnace its " + path + " path keeps " + percent(*worst) + " of the lobe's energy";
    // On the rough pixels a loss of e is a relative error of e: where that is as large as the
    // configuration's whole relative error there, energy, not the blur's shape, is what it gets wrong.
    if (record.relativeMseRough && energyError >= std::sqrt(*record.relativeMseRough) && energyError > 0.01)
        note += ", an energy error as large as its whole relative error on the rough pixels (" +
                percent(std::sqrt(*record.relativeMseRough)) +
                "): energy, not the blur's shape, dominates it";
    return note;
}

void furnaceSection(std::ostringstream& md, const std::vector<FurnaceRow>& furnace) {
    if (furnace.empty())
        return;
    md << "## Energy: the white furnace\n\n"
          "A rough planar mirror (seen from above and at 60°) and the curved reflector (at its centre) alone "
          "under a uniform white sky: what they show is the energy the GGX lobe keeps after masking and "
          "shadowing, its directional albedo E (1 for a perfect mirror), computed here by quadrature of the "
          "lobe the tracer samples. The traced value estimates the same integral by sampling; \"traced "
          "agrees\" "
          "says whether it lies within three of its standard errors of E. Each raster glossy path should "
          "show E. "
          "Energy is the raster value over E: below 100 % the path loses light, above it creates light.\n\n";
    md << "| surface | view | roughness | E (quadrature) | traced | traced agrees | path | raster | energy "
          "|\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    for (const FurnaceRow& row : furnace) {
        const double deviation = std::abs(row.traced - row.albedo);
        const bool agrees = deviation <= 3.0 * row.tracedError + 1e-3;
        md << "| " << row.surface << " | " << number("%.0f°", row.viewDegrees) << " | "
           << number("%.2f", row.roughness) << " | " << number("%.4f", row.albedo) << " | "
           << number("%.4f", row.traced) << " ± " << number("%.4f", row.tracedError) << " | "
           << (agrees ? std::string("yes")
                      : "no (" + number("%.1f", deviation / std::max(row.tracedError, 1e-9)) + " σ)")
           << " | " << row.path << " | " << number("%.4f", row.raster) << " | " << percent(row.energy())
           << " |\n";
    }
    double worst = 0.0;
    const FurnaceRow* worstRow = nullptr;
    for (const FurnaceRow& row : furnace)
        if (std::abs(row.energy() - 1.0) >= worst) {
            worst = std::abs(row.energy() - 1.0);
            worstRow = &row;
        }
    if (worstRow)
        md << "\nThe largest energy error: the " << worstRow->surface << "'s " << worstRow->path
           << " path at roughness " << number("%.2f", worstRow->roughness) << " keeps "
           << percent(worstRow->energy()) << " (the tracer's value has a standard error of "
           << number("%.4f", worstRow->tracedError) << ").\n";
    md << "\n";
}

} // namespace speculum::accuracy
