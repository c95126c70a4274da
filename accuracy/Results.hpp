#pragma once

#include "accuracy/Sweep.hpp"
#include "base/Result.hpp"
#include "base/Shard.hpp"
#include "render/plan/FrameReport.hpp"

#include <QJsonArray>
#include <QJsonObject>
#include <optional>
#include <string>
#include <vector>

namespace speculum::accuracy {

// A share of a run measured on one machine (bench --shard): "1/4", and that machine's host name.
struct RanOn {
    std::string shard;
    std::string host;
};

// One measured configuration: a row of results.csv and a record of results.json.
struct Record {
    Configuration config;
    Settings settings;         // every setting the scene has, as this configuration renders it
    bool sceneSetting = false; // the settings are the scene's own
    double gpuMs = -1.0;       // median frame time on the GPU (timer queries); -1: not measured
    double cpuMs = 0.0;        // median frame time on the CPU (the renderer's own measure)
    render::TargetMemory memory;
    double rmse = 0.0;                   // sRGB values 0..1, all pixels
    double psnr = 0.0;                   // dB, all pixels
    std::optional<double> psnrMirrors;   // dB on the pixels showing a planar mirror; none if no such pixel
    std::optional<double> psnrReflector; // dB on the pixels showing the curved reflector
    std::string errorMap;                // path of its error map, relative to the output folder
    // The figures beside PSNR (render::metrics), all on the whole frame unless named otherwise. False in
    // a results.json written before they existed: the figures below are then unknown, not zero.
    bool perceptual = false;
    double mae = 0.0;                    // mean absolute error of the sRGB values
    double relativeMse = 0.0;            // on linear values (pbrt's relative MSE)
    double ssim = 1.0;                   // mean SSIM, 1 for identical images
    double flip = 0.0;                   // mean LDR-FLIP, 0 (identical) to 1
    double hdrFlip = 0.0;                // mean HDR-FLIP on the linear images
    std::optional<double> flipMirrors;   // mean LDR-FLIP on the mirrors' pixels
    std::optional<double> flipReflector; // on the reflector's pixels
    // The reference's own noise: its sRGB RMS over the frame, and the 95 % interval it leaves on the PSNR
    // (both equal to psnr for an exact reference).
    double referenceNoise = 0.0;
    double psnrLow = 0.0;
    double psnrHigh = 0.0;
    // The same family's records whose error differs from this one's by less than the reference's noise
    // can tell apart (on the pixels the family is judged by): ties, not a ranking.
    std::vector<std::string> tiedWith;
    std::string flipMap; // path of its FLIP map (magma), relative to the output folder
    // How far a viewer could tell this configuration's image from its family's best one (by mean FLIP on
    // the family's pixels): the 99th percentile over those pixels of the FLIP between the two images, 0 for
    // the best itself. Below one JND (render::metrics::flipJnd) the two look the same. None for the glossy
    // family (a best per roughness, its lines say) and in older files.
    std::optional<double> flipToBest;
    // The relative MSE on the pixels that see a rough surface (where the reference has noise); none where
    // there are none.
    std::optional<double> relativeMseRough;
    // Where it was measured, in a run joined from shards (bench --merge); none in a one-machine run.
    std::optional<RanOn> ranOn;
};

// The time a chart plots for a record: the GPU's where measured (what the settings cost the frame), else
// the CPU's.
double frameMs(const Record& record);

// One row of the white-furnace test (run/Furnace.hpp): a raster glossy path's value under a uniform white
// sky against the energy the GGX lobe keeps.
struct FurnaceRow {
    std::string surface; // "planar mirror" or "reflector"
    std::string path;    // the raster glossy filter: "mip", "footprint", "chain"
    double roughness = 0.0;
    double viewDegrees = 0.0;
    double albedo = 1.0;      // E(μ_v, α) by quadrature of the lobe's formulas
    double traced = 1.0;      // the tracer's value (it integrates the lobe by sampling)
    double tracedError = 0.0; // its standard error
    double raster = 1.0;      // the raster path's value

    // The share of the lobe's energy the raster path keeps: raster / E. E is the exact value of the integral
    // the tracer estimates by sampling (its value agrees within its noise), so the ratio carries no noise.
    double energy() const { return albedo > 0.0 ? raster / albedo : 1.0; }
};

// The furnace rows' object in results.json ("furnace": [...]) and back.
QJsonArray furnaceJson(const std::vector<FurnaceRow>& rows);
std::vector<FurnaceRow> furnaceFromJson(const QJsonArray& array);

// The reference's own convergence (bench --convergence): the scene's exact image traced with rising
// paths per rough pixel, its noise and its error against the image with the most paths.
struct ConvergencePoint {
    int samples = 0; // paths per pixel through rough surfaces
    double traceMs = 0.0;
    double noise = 0.0; // the tracer's own noise estimate in sRGB, RMS over the frame
    double rmse = 0.0;  // sRGB, against the image with the most paths (0 for that one)
};

inline constexpr int kMaxExtrapolated = 1 << 30;

struct ConvergenceStudy {
    std::vector<ConvergencePoint> points;
    bool exact = false;         // no rough pixel: one path is exact, nothing to converge
    double smallestError = 0.0; // the smallest whole-frame RMSE the run's configurations scored
    double slope = 0.0;         // of log noise against log samples (−½ expected)
    std::optional<int> enough;  // the fewest samples traced whose noise is below a tenth of it
    int extrapolated = 0;       // otherwise: the samples the slope says it needs (at most kMaxExtrapolated)
};

struct ReferenceInfo {
    ReferenceKind kind = ReferenceKind::Scene;
    double traceMs = 0.0;
    int threads = 1;
    std::string image; // relative to the output folder
};

// What a shard run (bench --shard K/N) was, for the merge to check its folders against each other and join
// them. A shard's records lack the figures that compare a configuration with others of its family
// (tiedWith, flipToBest): the merge computes them from the frames the shard keeps.
struct ShardInfo {
    base::Shard shard;
    // Every configuration of the whole sweep in its order (ids): the share is base::shardItems of it, and
    // two shards of one sweep have the same list.
    std::vector<std::string> configurations;
    std::string projectDigest; // SHA-256 of the project file, hex: the shards measured the same file
    bool convergence = false;  // bench --convergence: shard 0 studies the reference's convergence
    std::string host;
};

// A shard a merged run joined: where its configurations were measured.
struct ShardOrigin {
    std::string shard; // "1/4"
    std::string host;
    std::string renderer;
    std::size_t configurations = 0; // measured there
};

// What the whole run was: for the JSON header and the report.
struct RunInfo {
    std::string scene;     // the project file as given
    std::string sceneName; // its file name
    int width = 0;
    int height = 0;
    bool quick = false;
    int warmUpFrames = 0;
    int timedFrames = 0;
    std::string renderer; // the GL renderer's description
    std::vector<ReferenceInfo> references;
    std::vector<FurnaceRow> furnace;             // the white-furnace test, where the scene has rough surfaces
    std::optional<ConvergenceStudy> convergence; // bench --convergence
    std::optional<ShardInfo> shard;              // a shard run: its records are its share only
    std::vector<ShardOrigin> shards;             // a merged run: the shards it joined, in shard order

    // The shards ran on more than one machine or GPU: their times are not one machine's.
    bool timesFromSeveralMachines() const;
};

// The convergence study's object in results.json ("convergence": {...}) and back.
QJsonObject convergenceJson(const ConvergenceStudy& study);
ConvergenceStudy convergenceFromJson(const QJsonObject& object);

// The run's description in the root object of a results.json (everything but its records).
RunInfo runInfoFromJson(const QJsonObject& root);

// A results.json read back.
struct ResultsFile {
    RunInfo run; // width and height 0 where the size does not read as "WxH"
    std::vector<Record> records;
    std::size_t unknownFamilies = 0; // records of families this version does not know, left out

    bool gpuTimes() const;    // some record has a GPU time
    std::string size() const; // "480x270"
};

// Reads the root object of a results.json that `name` names in errors ("results.json: results[3].psnr:
// expected a number"). Reading it whole (the file, the JSON syntax, repeated keys) is the caller's.
base::Result<ResultsFile> readJson(const QJsonObject& root, const std::string& name);

// Columns: id, family, label, series, reference, sceneSetting, the settings (kSettingNames; empty where
// the scene has no such setting), gpuMs, cpuMs, memoryBytes, rmse, psnr, psnrMirrors, psnrReflector
// (empty where there are no such pixels), errorMap, then mae, relativeMse, ssim, flip, hdrFlip,
// flipMirrors, flipReflector, referenceNoise, psnrLow, psnrHigh, tiedWith (ids separated by spaces),
// flipMap, flipToBest, relativeMseRough (all empty for a record without perceptual figures).
base::Status writeCsv(const std::string& path, const std::vector<Record>& records);

// {"format": "speculum-bench", "version": 1, "scene", "size", "quick", ..., "references": [...],
//  "results": [{"id", "family", "label", "series", "reference", "sceneSetting", "settings": {...},
//               "gpuMs", "cpuMs", "memoryBytes", "memory": {"main", "mirrors", "shadows", "envmap"},
//               "rmse", "psnr", "psnrMirrors", "psnrReflector", "errorMap", "mae", "relativeMse",
//               "ssim", "flip", "hdrFlip", "flipMirrors", "flipReflector", "referenceNoise",
//               "psnrInterval": [low, high], "tiedWith": [ids], "flipMap", "flipToBest",
//               "relativeMseRough", "ranOn": {"shard", "host"}}],
//  "shard": {"index", "count", "contiguous", "configurations": [ids], "projectSha256", "convergence",
//            "host"},
//  "shards": [{"shard", "host", "renderer", "configurations"}], "timesFromSeveralMachines"}
// Missing values (no GPU timer, no mirror pixels) are null; "ranOn" and "shards" only in a merged run,
// "shard" only in a shard run's.
base::Status writeJson(const std::string& path, const RunInfo& run, const std::vector<Record>& records);

} // namespace speculum::accuracy
