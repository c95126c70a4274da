#pragma once

#include "render/frame/FrameInput.hpp"

#include <optional>
#include <string>

namespace speculum::render {

// What drawing the reflector's environment map costs, counted before any of it runs: the texels of every
// face the environment pass draws, and the GGX lobe samples the pre-filtered chain takes (its levels
// below the sharp one, a third of the map's texels, each `prefilterSamples` times). The figures the
// planner warns with before a frame that would take minutes, and caps an interactive view by; not a
// timing (`bench` and `time` measure those).
struct MapCost {
    double texels = 0.0;
    double prefilterSamples = 0.0;
    // Seconds on a software renderer (Mesa llvmpipe on two cores), at the rates measured there.
    double softwareSeconds() const;
};

// The map of `reflector` at `resolution` texels, pre-filtered with `samples` lobe samples a texel where
// its roughness and the glossy filter ask for the chain.
MapCost mapCost(const Reflector& reflector, int resolution, const Settings& settings, int samples);

// A map estimated over this on a software renderer is warned of: a frame taking minutes should be a
// choice. Half a minute, so that what merely takes seconds (a 2048² rough map) is not reported as if wrong.
inline constexpr double kMapCostWarningSeconds = 30.0;

// The longest the editor's viewport lets the map take (PlanOptions::maxMapSeconds), in software seconds:
// a project whose 8192² map would take many minutes comes up in about this, drawn smaller; the demos'
// maps, and a 1024² rough one, are never capped.
inline constexpr double kInteractiveMapSeconds = 3.0;

// "About 5.5e11 samples, roughly 9 min": the estimate in words.
std::string costText(const MapCost& cost);

} // namespace speculum::render
