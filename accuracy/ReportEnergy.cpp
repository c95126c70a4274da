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
    std::optional<double> worst;
    for (const FurnaceRow& row : furnace)
        if (row.path == path && std::abs(row.roughness - roughness) < 1e-6)
            if (!worst || std::abs(row.energy() - 1.0) > std::abs(*worst - 1.0))
                worst = row.energy();
    if (!worst)
        return std::nullopt;
    const double energyError = std::abs(*worst - 1.0);
    std::string note =
        "in the white furnace its " + path + " path keeps " + percent(*worst) + " of the lobe's energy";
    if (record.perceptual && energyError >= std::sqrt(record.relativeMse) && energyError > 0.01)
        note += ", an energy error as large as its whole relative error (" +
                percent(std::sqrt(record.relativeMse)) + "): energy, not the blur's shape, dominates it";
    return note;
}

void furnaceSection(std::ostringstream& md, const std::vector<FurnaceRow>& furnace) {
    if (furnace.empty())
        return;
    md << "## Energy: the white furnace\n\n"
          "A rough planar mirror (seen from above and at 60°) and the curved reflector (at its centre) alone "
          "under a uniform white sky: what they show is the energy the GGX lobe keeps after masking and "
          "shadowing, its directional albedo E (1 for a perfect mirror), computed here by quadrature of the "
          "lobe the tracer samples; the traced value confirms it within the tracer's noise. Each raster "
          "glossy "
          "path should show E. Energy is the raster value over E: below 100 % the path loses light, above it "
          "creates light.\n\n";
    md << "| surface | view | roughness | E (quadrature) | traced | path | raster | energy |\n"
          "|---|---|---|---|---|---|---|---|\n";
    for (const FurnaceRow& row : furnace)
        md << "| " << row.surface << " | " << number("%.0f°", row.viewDegrees) << " | "
           << number("%.2f", row.roughness) << " | " << number("%.4f", row.albedo) << " | "
           << number("%.4f", row.traced) << " ± " << number("%.4f", row.tracedError) << " | " << row.path
           << " | " << number("%.4f", row.raster) << " | " << percent(row.energy()) << " |\n";
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
