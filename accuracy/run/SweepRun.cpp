#include "accuracy/run/SweepRun.hpp"

#include "accuracy/Analysis.hpp"
#include "accuracy/Report.hpp"
#include "accuracy/run/FamilyComparison.hpp"
#include "accuracy/run/Furnace.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <thread>

namespace speculum::accuracy {

namespace {

std::string key(const Settings& settings) {
    std::string k;
    for (const auto& [name, value] : settings)
        k += name + "=" + value + ";";
    return k;
}

std::string referenceFile(ReferenceKind kind) {
    return kind == ReferenceKind::Scene ? "reference.png" : "reference-" + referenceName(kind) + ".png";
}

// The scene's traits, and whether what its reflectors' maps see moves in the frames the caller played.
SceneTraits traitsOf(const SweepInput& input) {
    SceneTraits traits = sceneTraits(input.scene, input.teapotTessellation);
    const std::vector<render::FrameInput>& played = input.playedFrames;
    for (std::size_t i = 0; played.size() >= 2 && i < played.front().reflectors.size(); ++i)
        traits.moves = traits.moves || render::envmapSignature(played.front(), static_cast<int>(i)) !=
                                           render::envmapSignature(played.back(), static_cast<int>(i));
    return traits;
}

class Run {
public:
    Run(render::Renderer& renderer, const SweepInput& input, const SweepObserver& observer)
        : m_renderer(renderer)
        , m_input(input)
        , m_observer(observer)
        , m_traits(traitsOf(input)) {
        const SweepSize size = defaultSweepSize(input.quick);
        m_width = input.width > 0 ? input.width : size.width;
        m_height = input.height > 0 ? input.height : size.height;
    }

    base::Result<SweepOutcome> operator()() {
        const SweepTiming timing = sweepTiming(m_input.quick);
        const std::vector<Configuration> plan = planSweep(m_input.scene, m_traits, {m_input.quick});
        const std::vector<Configuration> configs = share(plan);
        SweepOutcome out;
        if (m_input.shard) {
            out.run.shard.emplace();
            out.run.shard->shard = *m_input.shard;
            for (const Configuration& c : plan)
                out.run.shard->configurations.push_back(c.id);
        }
        out.run.sceneName = m_input.sceneName;
        out.run.width = m_width;
        out.run.height = m_height;
        out.run.quick = m_input.quick;
        out.run.warmUpFrames = timing.warmUp;
        out.run.timedFrames = timing.rounds;
        progress(std::to_string(configs.size()) + " configurations of " + m_input.sceneName + " at " +
                 std::to_string(m_width) + "x" + std::to_string(m_height) +
                 (m_input.quick ? " (quick)" : "") +
                 (m_input.shard
                      ? ", shard " + base::shardText(*m_input.shard) + " of " + std::to_string(plan.size())
                      : std::string()));
        if (configs.empty())
            return out; // a shard with no share (more shards than configurations)

        auto references = traceReferences(configs, out.run);
        if (!references)
            return base::Error{references.error()};

        // Warm the whole pipeline up once (shader variants, textures, meshes), so that the first
        // configuration measured is not the one that pays for it.
        progress("warming up");
        if (auto warm = measureFrames(m_renderer, m_input.scene, m_width, m_height, 2, 0, m_observer.stop);
            !warm)
            return base::Error{warm.error()};

        DistinctFrames frames;
        if (base::Status measured = measureConfigurations(configs, *references, timing, out.records, frames);
            !measured)
            return base::Error{measured.error()};
        if (base::Status timed = timeRounds(timing, frames, out.records); !timed)
            return base::Error{timed.error()};
        if (runsFurnace(plan, configs)) {
            progress("white furnace: the raster glossy paths' energy against the GGX lobe's");
            auto furnace = runFurnace(m_renderer, m_observer.stop);
            if (!furnace)
                return base::Error{furnace.error() == "stopped" ? std::string(kSweepStopped)
                                                                : furnace.error()};
            out.run.furnace = std::move(*furnace);
        }
        return out;
    }

private:
    // The configurations this run measures: all, or its shard's share.
    std::vector<Configuration> share(const std::vector<Configuration>& plan) const {
        if (!m_input.shard)
            return plan;
        std::vector<Configuration> configs;
        for (int i : base::shardItems(*m_input.shard, static_cast<int>(plan.size())))
            configs.push_back(plan[static_cast<std::size_t>(i)]);
        return configs;
    }

    // The white furnace runs where the sweep has the glossy family: in a sharded sweep, once, in the
    // shard that measures the family's first configuration.
    bool runsFurnace(const std::vector<Configuration>& plan,
                     const std::vector<Configuration>& configs) const {
        auto glossy = [](const Configuration& c) { return c.family == Family::Glossy; };
        const auto first = std::find_if(plan.begin(), plan.end(), glossy);
        if (first == plan.end())
            return false;
        return std::any_of(configs.begin(), configs.end(),
                           [&](const Configuration& c) { return c.id == first->id; });
    }

    void progress(const std::string& line) const {
        if (m_observer.progress)
            m_observer.progress(line);
    }
    bool stopped() const { return m_observer.stop && m_observer.stop(); }

    // Configurations with the same settings (the scene's own recur in every family) are rendered once and
    // timed once: the frame of each distinct setting, and which one each record is.
    struct DistinctFrames {
        std::vector<std::string> keys;                      // per record
        std::map<std::string, render::FrameInput> distinct; // the frame of each distinct setting
        std::map<std::string, Variation> played;            // the update family's: played, not drawn once
    };

    // The played frames with a configuration's variation.
    std::vector<render::FrameInput> playedWith(const Variation& variation) const {
        std::vector<render::FrameInput> frames;
        for (const render::FrameInput& frame : m_input.playedFrames)
            frames.push_back(applyVariation(frame, variation, m_traits.proxy, m_input.tessellate));
        return frames;
    }

    // A configuration's first frame: drawn once, or, in the update family, played.
    base::Result<FrameCost> firstCost(const Configuration& config, const render::FrameInput& applied,
                                      const SweepTiming& timing) {
        if (config.family == Family::Update)
            return measurePlayed(m_renderer, playedWith(config.variation), m_width, m_height,
                                 m_observer.stop);
        return measureFrames(m_renderer, applied, m_width, m_height, timing.warmUp, 1, m_observer.stop);
    }

    // Images, memory and errors, one configuration at a time: a record per configuration, with the times
    // of its one frame (timeRounds replaces them).
    base::Status measureConfigurations(const std::vector<Configuration>& configs,
                                       const std::map<ReferenceKind, Reference>& references,
                                       const SweepTiming& timing, std::vector<Record>& records,
                                       DistinctFrames& frames) {
        // The images are compared and handed on as they come: they are freed before the timing rounds.
        std::map<std::string, FrameCost> costs;
        const std::string sceneKey = key(
            effectiveSettings(m_input.scene, m_input.teapotTessellation, m_traits.simplifiableMeshes > 0));
        for (std::size_t i = 0; i < configs.size(); ++i) {
            if (stopped())
                return base::Error{kSweepStopped};
            const Configuration& config = configs[i];
            const std::string step = "[" + std::to_string(i + 1) + "/" + std::to_string(configs.size()) +
                                     "] " + familyName(config.family) + ": " + displayName(config);
            render::FrameInput applied =
                applyVariation(m_input.scene, config.variation, m_traits.proxy, m_input.tessellate);
            Record record;
            record.config = config;
            record.settings = effectiveSettings(applied,
                                                config.variation.tessellation ? config.variation.tessellation
                                                                              : m_input.teapotTessellation,
                                                m_traits.simplifiableMeshes > 0);
            const bool played = config.family == Family::Update;
            if (played) // the maps' policy is what the family varies
                if (const render::FieldValue* update = config.variation.find(Part::Reflector, "update"))
                    record.settings.emplace_back(
                        "update", render::fieldValueText(*partField(Part::Reflector, "update"), *update));
            const std::string k = key(record.settings) + (played ? "played" : "");
            record.sceneSetting = k == sceneKey;
            if (!costs.count(k)) {
                progress(step + (played
                                     ? ": playing " + std::to_string(m_input.playedFrames.size()) + " frames"
                                     : std::string(": rendering")));
                auto cost = firstCost(config, applied, timing);
                if (!cost)
                    return base::Error{cost.error() == kSweepStopped
                                           ? cost.error()
                                           : displayName(config) + ": " + cost.error()};
                costs.emplace(k, std::move(*cost));
                if (played)
                    frames.played.emplace(k, config.variation);
                else
                    frames.distinct.emplace(k, std::move(applied));
            }
            const FrameCost& cost = costs.at(k);
            auto errors = compareWithReference(cost.image, references.at(config.reference));
            if (!errors)
                return base::Error{displayName(config) + ": " + errors.error()};
            setFigures(record, cost, *errors);
            if (m_observer.measured)
                if (base::Status s = m_observer.measured(i, configs.size(), record, cost, *errors); !s)
                    return base::Error{s.error()};
            progress(summaryLine(step, record));
            records.push_back(std::move(record));
            frames.keys.push_back(k);
        }
        if (m_input.shard)
            return base::Done{}; // the merge compares the shards' frames
        auto image = [&](std::size_t i) -> const render::Image& { return costs.at(frames.keys[i]).image; };
        for (const auto& [family, members] : familyMembers(records))
            if (base::Status compared = compareFamily(records, members, image, references); !compared)
                return compared;
        return base::Done{};
    }

    // The record's figures from its frame and its comparison with the reference.
    static void setFigures(Record& record, const FrameCost& cost, const ErrorFigures& errors) {
        record.gpuMs = cost.gpuMs;
        record.cpuMs = cost.cpuMs;
        record.memory = cost.memory;
        record.rmse = errors.overall.rmse;
        record.psnr = errors.overall.psnr;
        if (errors.mirrors)
            record.psnrMirrors = errors.mirrors->psnr;
        if (errors.reflector)
            record.psnrReflector = errors.reflector->psnr;
        record.errorMap = "errors/" + record.config.id + ".png";
        record.perceptual = true;
        record.mae = errors.overall.mae;
        record.relativeMse = errors.overall.relativeMse;
        record.ssim = errors.ssim;
        record.flip = errors.flip.mean;
        record.hdrFlip = errors.hdrFlip;
        record.flipMirrors = errors.flipMirrors;
        record.flipReflector = errors.flipReflector;
        record.referenceNoise = errors.interval.noiseRms;
        record.psnrLow = errors.interval.psnrLow;
        record.psnrHigh = errors.interval.psnrHigh;
        record.flipMap = "flip/" + record.config.id + ".png";
        record.relativeMseRough = errors.roughRelativeMse;
    }

    // Each round times every distinct configuration once; after each, every record's times are the
    // medians of the rounds so far (a GPU time only when every round measured one).
    base::Status timeRounds(const SweepTiming& timing, const DistinctFrames& frames,
                            std::vector<Record>& records) {
        std::map<std::string, std::vector<double>> gpu, cpu;
        for (int round = 1; round <= timing.rounds; ++round) {
            progress("timing round " + std::to_string(round) + "/" + std::to_string(timing.rounds) + ": " +
                     std::to_string(frames.distinct.size() + frames.played.size()) +
                     " distinct configurations");
            for (const auto& [k, frame] : frames.distinct) {
                auto cost = measureFrames(m_renderer, frame, m_width, m_height, 1, 1, m_observer.stop);
                if (!cost)
                    return base::Error{cost.error()};
                gpu[k].push_back(cost->gpuMs);
                cpu[k].push_back(cost->cpuMs);
            }
            for (const auto& [k, variation] : frames.played) {
                auto cost =
                    measurePlayed(m_renderer, playedWith(variation), m_width, m_height, m_observer.stop);
                if (!cost)
                    return base::Error{cost.error()};
                gpu[k].push_back(cost->gpuMs);
                cpu[k].push_back(cost->cpuMs);
            }
            for (std::size_t i = 0; i < records.size(); ++i) {
                const std::vector<double>& g = gpu[frames.keys[i]];
                records[i].gpuMs =
                    std::all_of(g.begin(), g.end(), [](double ms) { return ms >= 0.0; }) ? median(g) : -1.0;
                records[i].cpuMs = median(cpu[frames.keys[i]]);
            }
            if (m_observer.timed)
                m_observer.timed(round, timing.rounds, records);
        }
        return base::Done{};
    }

    // Traces each reference the configurations need.
    base::Result<std::map<ReferenceKind, Reference>>
    traceReferences(const std::vector<Configuration>& configs, RunInfo& run) {
        std::vector<ReferenceKind> kinds;
        for (const Configuration& c : configs)
            if (std::find(kinds.begin(), kinds.end(), c.reference) == kinds.end())
                kinds.push_back(c.reference);
        std::map<ReferenceKind, Reference> references;
        const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        for (ReferenceKind kind : kinds) {
            const std::string name = referenceName(kind);
            progress("tracing the " + name + " reference on " + std::to_string(threads) + " threads");
            int lastQuarter = 0;
            const render::FrameInput& base = kind == ReferenceKind::Played && !m_input.playedFrames.empty()
                                                 ? m_input.playedFrames.back()
                                                 : m_input.scene;
            auto traced = traceReference(
                referenceInput(base, kind, m_input.tessellate), kind, m_width, m_height,
                [&](double f) {
                    const int quarter = static_cast<int>(f * 4.0);
                    if (quarter > lastQuarter && quarter < 4)
                        progress("tracing the " + name + " reference: " + std::to_string(quarter * 25) + "%");
                    lastQuarter = std::max(lastQuarter, quarter);
                    return !stopped();
                },
                m_input.quick ? kQuickReferenceGlossySamples : kReferenceGlossySamples);
            if (stopped())
                return base::Error{kSweepStopped};
            if (!traced)
                return base::Error{traced.error()};
            std::string noise;
            if (traced->traced.glossyPixels > 0) {
                char text[96];
                std::snprintf(text, sizeof text, " (%d paths a pixel through rough surfaces, noise %.4f RMS)",
                              traced->traced.paths, traced->traced.noiseRms);
                noise = text;
            }
            progress("traced the " + name + " reference in " +
                     std::to_string(static_cast<int>(traced->traced.totalMs + 0.5)) + " ms" + noise);
            const ReferenceInfo info{kind, traced->traced.totalMs, threads, referenceFile(kind)};
            if (m_observer.referenceTraced)
                if (base::Status s = m_observer.referenceTraced(*traced, info); !s)
                    return base::Error{s.error()};
            run.references.push_back(info);
            references.emplace(kind, std::move(*traced));
        }
        return references;
    }

    render::Renderer& m_renderer;
    const SweepInput& m_input;
    const SweepObserver& m_observer;
    const SceneTraits m_traits;
    int m_width = 0;
    int m_height = 0;
};

} // namespace

SweepTiming sweepTiming(bool quick) {
    return quick ? SweepTiming{2, 7} : SweepTiming{2, 9};
}

SweepSize defaultSweepSize(bool quick) {
    return quick ? SweepSize{480, 270} : SweepSize{1280, 720};
}

std::string summaryLine(const std::string& step, const Record& r) {
    char text[200];
    std::snprintf(text, sizeof text, "%s: PSNR %.2f dB", step.c_str(), r.psnr);
    std::string line = text;
    if (r.psnrReflector) {
        std::snprintf(text, sizeof text, ", reflector %.2f dB", *r.psnrReflector);
        line += text;
    }
    if (r.psnrMirrors) {
        std::snprintf(text, sizeof text, ", mirrors %.2f dB", *r.psnrMirrors);
        line += text;
    }
    std::snprintf(text, sizeof text, ", %.1f MiB", static_cast<double>(r.memory.total()) / (1024.0 * 1024.0));
    return line + text;
}

std::vector<Configuration> sweepPlan(const SweepInput& input) {
    return planSweep(input.scene, traitsOf(input), {input.quick});
}

base::Result<SweepOutcome> runSweep(render::Renderer& renderer, const SweepInput& input,
                                    const SweepObserver& observer) {
    return Run(renderer, input, observer)();
}

} // namespace speculum::accuracy
