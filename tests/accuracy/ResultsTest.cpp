// results.json written by the sweep reads back into the same records (the one record type the bench
// writes and the editor's chart reads), and the findings the panel shows are the report's.
#include "accuracy/Results.hpp"

#include "accuracy/Report.hpp"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace speculum::accuracy {
namespace {

Record record(Family family, const std::string& id, double gpuMs, double psnr, bool scene = false) {
    Record r;
    r.config.family = family;
    r.config.id = id;
    r.config.label = (family == Family::Shadows ? "pcf " : "") + id.substr(id.rfind('-') + 1);
    r.config.series = family == Family::Envmap ? "cube" : "PCF kernel";
    r.config.reference = family == Family::Shadows ? ReferenceKind::HardShadows : ReferenceKind::Scene;
    r.settings = {{"map", "cube"}, {"resolution", "128"}, {"parallax", "off"}, {"pcf", "3"}};
    r.sceneSetting = scene;
    r.gpuMs = gpuMs;
    r.cpuMs = gpuMs + 1.25;
    r.memory = {1000, 0, 2048, 4096};
    r.rmse = 0.015625;
    r.psnr = psnr;
    r.psnrReflector = psnr - 3.5;
    r.errorMap = "errors/" + id + ".png";
    return r;
}

QJsonObject readBack(const std::string& path) {
    QFile file(QString::fromStdString(path));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    return QJsonDocument::fromJson(file.readAll()).object();
}

TEST(Results, JsonRoundTripGivesTheSameRecords) {
    QTemporaryDir dir;
    const std::string path = dir.filePath("results.json").toStdString();
    RunInfo run;
    run.scene = "/scenes/chrome.speculum.json";
    run.sceneName = "chrome.speculum.json";
    run.width = 480;
    run.height = 270;
    run.quick = true;
    run.warmUpFrames = 2;
    run.timedFrames = 7;
    run.renderer = "llvmpipe";
    run.references = {{ReferenceKind::Scene, 812.5, 16, "reference.png"},
                      {ReferenceKind::HardShadows, 700.0, 16, "reference-hard-shadows.png"}};
    std::vector<Record> records = {record(Family::Scene, "scene", 4.0, 34.0, true),
                                   record(Family::Envmap, "envmap-cube-64", 2.5, 30.0),
                                   record(Family::Shadows, "pcf-5", -1.0, 28.0)};
    records[1].psnrMirrors = 22.0;
    records[2].psnrReflector.reset();
    ASSERT_TRUE(writeJson(path, run, records).ok());

    auto read = readJson(readBack(path), "results.json");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->size(), "480x270");
    EXPECT_EQ(read->run.scene, run.scene);
    EXPECT_EQ(read->run.sceneName, run.sceneName);
    EXPECT_EQ(read->run.timedFrames, 7);
    ASSERT_EQ(read->run.references.size(), 2u);
    EXPECT_EQ(read->run.references[1].kind, ReferenceKind::HardShadows);
    EXPECT_DOUBLE_EQ(read->run.references[0].traceMs, 812.5);
    EXPECT_TRUE(read->gpuTimes());
    ASSERT_EQ(read->records.size(), records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
        const Record& a = records[i];
        const Record& b = read->records[i];
        EXPECT_EQ(b.config.family, a.config.family);
        EXPECT_EQ(b.config.id, a.config.id);
        EXPECT_EQ(b.config.label, a.config.label);
        EXPECT_EQ(b.config.series, a.config.series);
        EXPECT_EQ(b.config.reference, a.config.reference);
        EXPECT_EQ(b.settings, a.settings) << a.config.id;
        EXPECT_EQ(b.sceneSetting, a.sceneSetting);
        EXPECT_DOUBLE_EQ(b.gpuMs, a.gpuMs);
        EXPECT_DOUBLE_EQ(b.cpuMs, a.cpuMs);
        EXPECT_EQ(b.memory.total(), a.memory.total());
        EXPECT_EQ(b.memory.shadows, a.memory.shadows);
        EXPECT_DOUBLE_EQ(b.rmse, a.rmse);
        EXPECT_DOUBLE_EQ(b.psnr, a.psnr);
        EXPECT_EQ(b.psnrMirrors, a.psnrMirrors);
        EXPECT_EQ(b.psnrReflector, a.psnrReflector);
        EXPECT_EQ(b.errorMap, a.errorMap);
        EXPECT_DOUBLE_EQ(frameMs(b), a.gpuMs >= 0.0 ? a.gpuMs : a.cpuMs);
    }
}

Record withPerceptual(Record r, double flip, double ssim) {
    r.perceptual = true;
    r.mae = 0.0125;
    r.relativeMse = 0.03125;
    r.ssim = ssim;
    r.flip = flip;
    r.hdrFlip = flip * 0.75;
    r.flipReflector = flip * 2.0;
    r.referenceNoise = 0.004;
    r.psnrLow = r.psnr - 0.25;
    r.psnrHigh = r.psnr + 0.25;
    r.flipMap = "flip/" + r.config.id + ".png";
    return r;
}

TEST(Results, PerceptualFiguresAndTiesRoundTripAndOlderFilesLackThem) {
    QTemporaryDir dir;
    const std::string json = dir.filePath("results.json").toStdString();
    const std::string csv = dir.filePath("results.csv").toStdString();
    RunInfo run;
    run.width = 64;
    run.height = 32;
    std::vector<Record> records = {withPerceptual(record(Family::Shadows, "pcf-1", 2.0, 27.0), 0.0625, 0.875),
                                   withPerceptual(record(Family::Shadows, "pcf-3", 3.0, 27.1), 0.05, 0.9),
                                   record(Family::Shadows, "pcf-5", 4.0, 27.2)};
    records[0].tiedWith = {"pcf-3"};
    records[1].tiedWith = {"pcf-1"};
    records[0].flipToBest = 0.125;
    ASSERT_TRUE(writeJson(json, run, records).ok());
    ASSERT_TRUE(writeCsv(csv, records).ok());
    auto read = readJson(readBack(json), "results.json");
    ASSERT_TRUE(read.ok()) << read.error();
    ASSERT_EQ(read->records.size(), 3u);
    for (std::size_t i = 0; i < 2; ++i) {
        const Record &a = records[i], &b = read->records[i];
        EXPECT_TRUE(b.perceptual);
        EXPECT_DOUBLE_EQ(b.mae, a.mae);
        EXPECT_DOUBLE_EQ(b.relativeMse, a.relativeMse);
        EXPECT_DOUBLE_EQ(b.ssim, a.ssim);
        EXPECT_DOUBLE_EQ(b.flip, a.flip);
        EXPECT_DOUBLE_EQ(b.hdrFlip, a.hdrFlip);
        EXPECT_EQ(b.flipReflector, a.flipReflector);
        EXPECT_EQ(b.flipMirrors, a.flipMirrors);
        EXPECT_DOUBLE_EQ(b.referenceNoise, a.referenceNoise);
        EXPECT_DOUBLE_EQ(b.psnrLow, a.psnrLow);
        EXPECT_DOUBLE_EQ(b.psnrHigh, a.psnrHigh);
        EXPECT_EQ(b.tiedWith, a.tiedWith);
        EXPECT_EQ(b.flipMap, a.flipMap);
        EXPECT_EQ(b.flipToBest, a.flipToBest);
    }
    EXPECT_FALSE(read->records[2].perceptual) << "a record without the figures does not read as FLIP 0";
    EXPECT_TRUE(read->run.furnace.empty()) << "no rough surface, no furnace";
    EXPECT_FALSE(readBack(json).value("results").toArray().at(2).toObject().contains("flip"));

    QFile file(QString::fromStdString(csv));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4);
    const QStringList header = lines[0].split(',');
    EXPECT_TRUE(
        lines[0].endsWith("errorMap,mae,relativeMse,ssim,flip,hdrFlip,flipMirrors,flipReflector,"
                          "referenceNoise,psnrLow,psnrHigh,tiedWith,flipMap,flipToBest,relativeMseRough"))
        << lines[0].toStdString();
    for (int i = 1; i < 4; ++i)
        EXPECT_EQ(lines[i].split(',').size(), header.size()) << lines[i].toStdString();
    EXPECT_TRUE(lines[1].endsWith(",pcf-3,flip/pcf-1.png,0.125,")) << lines[1].toStdString();
}

// FLIP judges beside PSNR: its best, its cheap pick within one JND, and where the two disagree; a best
// whose difference from another lies within the reference's noise is called a tie, not a ranking.
TEST(Results, FlipFindingsAndTiesAreSaidInWords) {
    std::vector<Record> records = {withPerceptual(record(Family::Shadows, "pcf-1", 2.0, 27.0), 0.30, 0.8),
                                   withPerceptual(record(Family::Shadows, "pcf-3", 3.0, 30.0), 0.10, 0.9),
                                   withPerceptual(record(Family::Shadows, "pcf-5", 6.0, 30.5), 0.12, 0.9)};
    records[2].tiedWith = {"pcf-3"};
    records[1].tiedWith = {"pcf-5"};
    records[0].flipToBest = 0.2;  // a viewer tells it from the best's image
    records[1].flipToBest = 0.0;  // the best by FLIP
    records[2].flipToBest = 0.05; // within one JND of it, but dearer
    const std::vector<FamilyFindings> found = findings(records);
    ASSERT_EQ(found.size(), 1u);
    auto line = [&](const std::string& start) {
        for (const std::string& l : found[0].lines)
            if (l.rfind(start, 0) == 0)
                return l;
        return std::string();
    };
    EXPECT_NE(line("Best: **pcf 5**").find("tied within the reference's noise with **pcf 3**"),
              std::string::npos)
        << line("Best:");
    EXPECT_EQ(line("Best by FLIP:").rfind("Best by FLIP: **pcf 3**: FLIP 0.1000 at 3.00 ms GPU", 0), 0u)
        << line("Best by FLIP:");
    EXPECT_NE(line("Best by FLIP:").find("tied within the reference's noise with **pcf 5**"),
              std::string::npos);
    // pcf 5 looks the same as the best but costs more; pcf 1 does not look the same.
    EXPECT_FALSE(
        line("Cheapest that looks the same as the best by FLIP (on 99 % of the judged pixels less than "
             "one just-noticeable difference, FLIP 0.1031, from the best's image): **pcf 3**")
            .empty());
    EXPECT_FALSE(
        line("FLIP and PSNR disagree on the best: PSNR ranks **pcf 5** first, FLIP **pcf 3**").empty());
}

// The glossy family cites the white furnace: the energy its pick's path keeps, and whether that energy
// error is what dominates the pick's error.
TEST(Results, GlossyLinesNameTheFurnacesEnergyError) {
    auto row = [](const std::string& id, const std::string& series, const std::string& label, double ms,
                  double psnr) {
        Record r = withPerceptual(record(Family::Glossy, id, ms, psnr), 0.05, 0.95);
        r.config.series = series;
        r.config.label = label;
        r.relativeMseRough = 0.0016; // a typical relative error of 4 % on the rough pixels
        r.psnrMirrors = psnr;        // the frame shows a mirror, and no reflector
        r.psnrReflector.reset();
        return r;
    };
    const std::vector<Record> records = {
        row("glossy-r0.3-mip", "r 0.3 mip", "mip", 1.0, 30.0),
        row("glossy-r0.3-footprint", "r 0.3 footprint", "4 taps", 2.0, 30.5)};
    FurnaceRow lossy;
    lossy.surface = "planar mirror";
    lossy.path = "mip";
    lossy.roughness = 0.3;
    lossy.albedo = 0.99;
    lossy.traced = 0.99;
    lossy.raster = 0.891; // keeps 90 %
    FurnaceRow fine = lossy;
    fine.path = "footprint";
    fine.raster = 0.99;
    FurnaceRow unseen = lossy; // the reflector is not in these frames: its rows are not theirs
    unseen.surface = "reflector";
    unseen.raster = 0.5;
    const std::vector<FamilyFindings> found = findings(records, {lossy, fine, unseen});
    ASSERT_EQ(found.size(), 1u);
    const std::string& line = found[0].lines.at(0);
    EXPECT_EQ(line.rfind("At roughness 0.3: pick **r 0.3 mip**", 0), 0u) << line;
    EXPECT_NE(line.find("its mip path keeps 90.0 % of the lobe's energy"), std::string::npos) << line;
    EXPECT_NE(line.find("energy, not the blur's shape, dominates it"), std::string::npos) << line;
    // Without the furnace's rows the line says nothing about energy.
    EXPECT_EQ(findings(records)[0].lines.at(0).find("energy"), std::string::npos);
}

TEST(Results, UnknownFamiliesAreLeftOutAndCounted) {
    const QJsonObject root = QJsonDocument::fromJson(R"({"format": "speculum-bench", "size": [64, 32],
        "results": [{"family": "future", "cpuMs": 1, "psnr": 20, "rmse": 0.1},
                    {"family": "scene", "cpuMs": 2, "psnr": 30, "rmse": 0.01, "gpuMs": null}]})")
                                 .object();
    auto read = readJson(root, "results.json");
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read->unknownFamilies, 1u);
    ASSERT_EQ(read->records.size(), 1u);
    EXPECT_EQ(read->size(), "64x32");
    EXPECT_FALSE(read->gpuTimes());
    EXPECT_DOUBLE_EQ(frameMs(read->records[0]), 2.0);
}

TEST(Results, FindingsAreTheReportsLines) {
    const std::vector<Record> records = {
        record(Family::Scene, "scene", 4.0, 34.0, true), record(Family::Shadows, "pcf-1", 2.0, 27.0),
        record(Family::Shadows, "pcf-3", 3.0, 30.0, true), record(Family::Shadows, "pcf-5", 6.0, 30.5)};
    const std::vector<FamilyFindings> found = findings(records);
    ASSERT_EQ(found.size(), 1u); // the scene row is no family of its own
    EXPECT_EQ(found[0].family, Family::Shadows);
    EXPECT_EQ(found[0].judgedBy, "PSNR of the whole frame");
    ASSERT_GE(found[0].lines.size(), 3u);
    EXPECT_EQ(found[0].lines[0].rfind("Best: **pcf 5**: 30.50 dB", 0), 0u) << found[0].lines[0];
    EXPECT_EQ(found[0].lines[1].rfind("Cheapest within 1 dB of the best: **pcf 3**", 0), 0u)
        << found[0].lines[1];

    QTemporaryDir dir;
    RunInfo run;
    run.sceneName = "scene";
    run.width = 64;
    run.height = 32;
    // No plots without a QGuiApplication: one shadow row would plot, so give the report a single row.
    const std::vector<Record> one = {records[0], records[2]};
    ASSERT_TRUE(writeReport(dir.path().toStdString(), run, one).ok());
    QFile report(dir.filePath("report.md"));
    ASSERT_TRUE(report.open(QIODevice::ReadOnly));
    const std::string md = report.readAll().toStdString();
    for (const FamilyFindings& f : findings(one))
        for (const std::string& line : f.lines)
            EXPECT_NE(md.find("- " + line + "\n"), std::string::npos) << line;
}

// The screen-space family says in words whether the trace at its best comes within 1 dB of the best planar
// technique, judged on the mirrors' pixels.
TEST(Results, TheScreenSpaceFamilySaysWhetherTracingIsGoodEnough) {
    auto row = [](const std::string& id, const std::string& series, double ms, double psnrMirrors) {
        Record r = record(Family::ScreenSpace, id, ms, 30.0);
        r.config.series = series;
        r.config.label = id;
        r.psnrMirrors = psnrMirrors;
        return r;
    };
    const auto said = [](const std::vector<Record>& records) {
        const std::vector<FamilyFindings> found = findings(records);
        EXPECT_EQ(found.size(), 1u);
        EXPECT_EQ(found[0].judgedBy, "PSNR on mirror pixels");
        return found[0].lines.at(0);
    };
    const std::string close =
        said({row("planar stencil", "planar", 9.0, 40.0), row("traced 16 steps", "steps", 4.0, 38.0),
              row("traced 64 steps", "steps", 6.0, 39.5)});
    EXPECT_EQ(close.rfind("Screen space is good enough here", 0), 0u) << close;
    EXPECT_NE(close.find("traced 64 steps scores 39.50 dB at 6.00 ms, planar stencil 40.00 dB"),
              std::string::npos)
        << close;
    const std::string far =
        said({row("planar texture", "planar", 9.0, 40.0), row("traced 64 steps", "steps", 6.0, 31.0)});
    EXPECT_EQ(far.rfind("Screen space is not good enough here: at its best it stays 9.00 dB below", 0), 0u)
        << far;
}

// The bounces family says what each bounce gains on the reflectors and costs; the update family what
// slicing the maps loses while the scene moves, and saves.
TEST(Results, BouncesAndUpdatesAreSaidInWords) {
    auto row = [](Family family, const std::string& label, double ms, double psnrReflector) {
        Record r = record(family, label, ms, 30.0);
        r.config.label = label;
        r.config.series = family == Family::Bounces ? "bounces" : "update";
        r.psnrReflector = psnrReflector;
        return r;
    };
    const std::vector<FamilyFindings> bounces = findings({row(Family::Bounces, "0 bounces", 100.0, 15.0),
                                                          row(Family::Bounces, "1 bounce", 180.0, 18.5),
                                                          row(Family::Bounces, "2 bounces", 260.0, 18.75)});
    ASSERT_EQ(bounces.size(), 1u);
    EXPECT_EQ(bounces[0].judgedBy, "PSNR on reflector pixels");
    EXPECT_EQ(bounces[0].lines.at(0).rfind("A first bounce gains 3.50 dB on the reflectors for 80.0 ms", 0),
              0u)
        << bounces[0].lines.at(0);
    EXPECT_EQ(bounces[0].lines.at(1).rfind("A second bounce gains 0.25 dB on the reflectors for 80.0 ms", 0),
              0u)
        << bounces[0].lines.at(1);
    const std::vector<FamilyFindings> update = findings(
        {row(Family::Update, "every frame", 90.0, 24.0), row(Family::Update, "time-sliced", 30.0, 22.0)});
    ASSERT_EQ(update.size(), 1u);
    EXPECT_EQ(
        update[0].lines.at(0).rfind(
            "Time-sliced, the maps lose 2.00 dB on the reflectors while the scene moves and save 60.0 ms", 0),
        0u)
        << update[0].lines.at(0);
}

} // namespace
} // namespace speculum::accuracy
