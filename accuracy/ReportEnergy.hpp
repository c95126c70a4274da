#pragma once

#include "accuracy/Results.hpp"

#include <optional>
#include <sstream>
#include <string>
#include <vector>

// The white furnace in the report (accuracy internal, for Report.cpp): what energy each raster glossy
// path keeps, and where that, rather than the shape of the blur, is a configuration's error.
namespace speculum::accuracy {

// The raster path a glossy configuration uses: "mip", "footprint" or "chain".
std::string glossyPath(const Record& record);

// The furnace's word on a glossy configuration at `roughness`: the share of the lobe's energy its path
// keeps (the worst over the surfaces its frame shows), and whether that energy error dominates the
// configuration's own error (it is at least the configuration's typical relative error on the pixels that
// see a rough surface, √Record::relativeMseRough).
// None without furnace rows for that path and roughness.
std::optional<std::string> energyNote(const Record& record, double roughness,
                                      const std::vector<FurnaceRow>& furnace);

// "## Energy: the white furnace": what was measured and a table of every row.
void furnaceSection(std::ostringstream& md, const std::vector<FurnaceRow>& furnace);

} // namespace speculum::accuracy
