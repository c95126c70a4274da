#pragma once

#include "accuracy/Sweep.hpp"
#include "base/Result.hpp"
#include "render/plan/FrameReport.hpp"

#include <QJsonObject>
#include <optional>
#include <string>
#include <vector>

namespace speculum::accuracy {

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
};

// The time a chart plots for a record: the GPU's where measured (what the settings cost the frame), else
// the CPU's.
double frameMs(const Record& record);

struct ReferenceInfo {
    ReferenceKind kind = ReferenceKind::Scene;
    double traceMs = 0.0;
    int threads = 1;
    std::string image; // relative to the output folder
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
};

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
// (empty where there are no such pixels), errorMap.
base::Status writeCsv(const std::string& path, const std::vector<Record>& records);

// {"format": "speculum-bench", "version": 1, "scene", "size", "quick", ..., "references": [...],
//  "results": [{"id", "family", "label", "series", "reference", "sceneSetting", "settings": {...},
//               "gpuMs", "cpuMs", "memoryBytes", "memory": {"main", "mirrors", "shadows", "envmap"},
//               "rmse", "psnr", "psnrMirrors", "psnrReflector", "errorMap"}]}
// Missing values (no GPU timer, no mirror pixels) are null.
base::Status writeJson(const std::string& path, const RunInfo& run, const std::vector<Record>& records);

} // namespace speculum::accuracy
