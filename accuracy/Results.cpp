#include "accuracy/Results.hpp"

#include "base/AtomicFile.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace speculum::accuracy {

namespace {

// Enough digits that a value read back from the CSV equals the JSON's to 1e-9.
std::string number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string settingOf(const Record& r, const std::string& name) {
    for (const auto& [key, value] : r.settings)
        if (key == name)
            return value;
    return {};
}

QJsonValue orNull(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
}

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

// Staged and checked (base::AtomicFile): a full disk is an error, never a truncated file.
base::Status writeText(const std::string& path, const std::string& text) {
    return base::writeFileAtomically(path, text);
}

std::optional<double> finite(const QJsonValue& v) {
    if (v.isDouble() && std::isfinite(v.toDouble()))
        return v.toDouble();
    return std::nullopt;
}

std::size_t bytes(const QJsonValue& v) {
    const std::optional<double> n = finite(v);
    return n && *n > 0.0 ? static_cast<std::size_t>(*n) : 0;
}

// The settings in the order effectiveSettings gives them (the file's object is unordered), then any this
// version does not know, which applying the record names as such.
Settings settingsOf(const QJsonObject& object) {
    Settings settings;
    auto text = [](const QJsonValue& v) {
        return (v.isDouble() ? QString::number(v.toDouble()) : v.toString()).toStdString();
    };
    for (const std::string& name : kSettingNames)
        if (object.contains(q(name)))
            settings.emplace_back(name, text(object.value(q(name))));
    for (auto it = object.begin(); it != object.end(); ++it)
        if (std::find(kSettingNames.begin(), kSettingNames.end(), it.key().toStdString()) ==
            kSettingNames.end())
            settings.emplace_back(it.key().toStdString(), text(*it));
    return settings;
}

std::string optionalNumber(const std::optional<double>& value) {
    return value ? number(*value) : std::string();
}

// The perceptual figures, present from the version that measures them on.
void readPerceptual(const QJsonObject& r, Record& record) {
    const auto flip = finite(r.value("flip"));
    if (!flip)
        return;
    record.perceptual = true;
    record.flip = *flip;
    record.mae = finite(r.value("mae")).value_or(0.0);
    record.relativeMse = finite(r.value("relativeMse")).value_or(0.0);
    record.ssim = finite(r.value("ssim")).value_or(1.0);
    record.hdrFlip = finite(r.value("hdrFlip")).value_or(0.0);
    record.flipMirrors = finite(r.value("flipMirrors"));
    record.flipReflector = finite(r.value("flipReflector"));
    record.referenceNoise = finite(r.value("referenceNoise")).value_or(0.0);
    const QJsonArray interval = r.value("psnrInterval").toArray();
    record.psnrLow = finite(interval.at(0)).value_or(record.psnr);
    record.psnrHigh = finite(interval.at(1)).value_or(record.psnr);
    for (const QJsonValue& id : r.value("tiedWith").toArray())
        record.tiedWith.push_back(id.toString().toStdString());
    record.flipMap = r.value("flipMap").toString().toStdString();
    record.flipToBest = finite(r.value("flipToBest"));
    record.relativeMseRough = finite(r.value("relativeMseRough"));
}

void addPerceptual(QJsonObject& object, const Record& r) {
    if (!r.perceptual)
        return;
    QJsonArray tied;
    for (const std::string& id : r.tiedWith)
        tied.append(q(id));
    object.insert("mae", r.mae);
    object.insert("relativeMse", r.relativeMse);
    object.insert("ssim", r.ssim);
    object.insert("flip", r.flip);
    object.insert("hdrFlip", r.hdrFlip);
    object.insert("flipMirrors", orNull(r.flipMirrors));
    object.insert("flipReflector", orNull(r.flipReflector));
    object.insert("referenceNoise", r.referenceNoise);
    object.insert("psnrInterval", QJsonArray{r.psnrLow, r.psnrHigh});
    object.insert("tiedWith", tied);
    object.insert("flipMap", q(r.flipMap));
    object.insert("flipToBest", orNull(r.flipToBest));
    object.insert("relativeMseRough", orNull(r.relativeMseRough));
}

void writePerceptualCsv(std::ostream& csv, const Record& r) {
    if (!r.perceptual) {
        csv << std::string(14, ',');
        return;
    }
    std::string tied;
    for (const std::string& id : r.tiedWith)
        tied += (tied.empty() ? "" : " ") + id;
    csv << "," << number(r.mae) << "," << number(r.relativeMse) << "," << number(r.ssim) << ","
        << number(r.flip) << "," << number(r.hdrFlip) << "," << optionalNumber(r.flipMirrors) << ","
        << optionalNumber(r.flipReflector) << "," << number(r.referenceNoise) << "," << number(r.psnrLow)
        << "," << number(r.psnrHigh) << "," << csvField(tied) << "," << csvField(r.flipMap) << ","
        << optionalNumber(r.flipToBest) << "," << optionalNumber(r.relativeMseRough);
}

QJsonObject shardJson(const ShardInfo& info) {
    QJsonArray configurations;
    for (const std::string& id : info.configurations)
        configurations.append(q(id));
    return QJsonObject{{"index", info.shard.index},
                       {"count", info.shard.count},
                       {"contiguous", info.shard.contiguous},
                       {"configurations", configurations},
                       {"projectSha256", q(info.projectDigest)},
                       {"convergence", info.convergence},
                       {"host", q(info.host)}};
}

ShardInfo shardFromJson(const QJsonObject& object) {
    ShardInfo info;
    info.shard.index = object.value("index").toInt(-1);
    info.shard.count = object.value("count").toInt(0);
    info.shard.contiguous = object.value("contiguous").toBool();
    for (const QJsonValue& id : object.value("configurations").toArray())
        info.configurations.push_back(id.toString().toStdString());
    info.projectDigest = object.value("projectSha256").toString().toStdString();
    info.convergence = object.value("convergence").toBool();
    info.host = object.value("host").toString().toStdString();
    return info;
}

} // namespace

bool RunInfo::timesFromSeveralMachines() const {
    for (const ShardOrigin& o : shards)
        if (o.host != shards.front().host || o.renderer != shards.front().renderer)
            return true;
    return false;
}

QJsonArray furnaceJson(const std::vector<FurnaceRow>& rows) {
    QJsonArray array;
    for (const FurnaceRow& row : rows)
        array.append(QJsonObject{{"surface", q(row.surface)},
                                 {"path", q(row.path)},
                                 {"roughness", row.roughness},
                                 {"viewDegrees", row.viewDegrees},
                                 {"albedo", row.albedo},
                                 {"traced", row.traced},
                                 {"tracedError", row.tracedError},
                                 {"raster", row.raster},
                                 {"energy", row.energy()}});
    return array;
}

std::vector<FurnaceRow> furnaceFromJson(const QJsonArray& array) {
    std::vector<FurnaceRow> rows;
    for (const QJsonValue& value : array) {
        const QJsonObject o = value.toObject();
        FurnaceRow row;
        row.surface = o.value("surface").toString().toStdString();
        row.path = o.value("path").toString().toStdString();
        row.roughness = finite(o.value("roughness")).value_or(0.0);
        row.viewDegrees = finite(o.value("viewDegrees")).value_or(0.0);
        row.albedo = finite(o.value("albedo")).value_or(1.0);
        row.traced = finite(o.value("traced")).value_or(1.0);
        row.tracedError = finite(o.value("tracedError")).value_or(0.0);
        row.raster = finite(o.value("raster")).value_or(1.0);
        rows.push_back(row);
    }
    return rows;
}

QJsonObject convergenceJson(const ConvergenceStudy& study) {
    QJsonArray points;
    for (const ConvergencePoint& p : study.points)
        points.append(QJsonObject{
            {"samples", p.samples}, {"traceMs", p.traceMs}, {"noise", p.noise}, {"rmse", p.rmse}});
    return QJsonObject{{"exact", study.exact},
                       {"smallestError", study.smallestError},
                       {"slope", study.slope},
                       {"enough", study.enough ? QJsonValue(*study.enough) : QJsonValue(QJsonValue::Null)},
                       {"extrapolated", study.extrapolated},
                       {"points", points}};
}

ConvergenceStudy convergenceFromJson(const QJsonObject& object) {
    ConvergenceStudy study;
    study.exact = object.value("exact").toBool();
    study.smallestError = finite(object.value("smallestError")).value_or(0.0);
    study.slope = finite(object.value("slope")).value_or(0.0);
    if (const auto enough = finite(object.value("enough")))
        study.enough = static_cast<int>(*enough);
    study.extrapolated = object.value("extrapolated").toInt();
    for (const QJsonValue& value : object.value("points").toArray()) {
        const QJsonObject p = value.toObject();
        study.points.push_back({p.value("samples").toInt(), finite(p.value("traceMs")).value_or(0.0),
                                finite(p.value("noise")).value_or(0.0),
                                finite(p.value("rmse")).value_or(0.0)});
    }
    return study;
}

double frameMs(const Record& record) {
    return record.gpuMs >= 0.0 ? record.gpuMs : record.cpuMs;
}

bool ResultsFile::gpuTimes() const {
    return std::any_of(records.begin(), records.end(), [](const Record& r) { return r.gpuMs >= 0.0; });
}

std::string ResultsFile::size() const {
    return run.width > 0 && run.height > 0 ? std::to_string(run.width) + "x" + std::to_string(run.height)
                                           : "?";
}

RunInfo runInfoFromJson(const QJsonObject& root) {
    RunInfo run;
    run.scene = root.value("scene").toString().toStdString();
    run.sceneName = QString::fromStdString(run.scene).section(QLatin1Char('/'), -1).toStdString();
    const QJsonValue size = root.value("size");
    if (size.isArray()) {
        run.width = size.toArray().at(0).toInt();
        run.height = size.toArray().at(1).toInt();
    } else {
        const QStringList parts = size.toString().split(QLatin1Char('x'));
        if (parts.size() == 2) {
            run.width = parts[0].toInt();
            run.height = parts[1].toInt();
        }
    }
    run.quick = root.value("quick").toBool();
    run.warmUpFrames = root.value("warmUpFrames").toInt();
    run.timedFrames = root.value("timedFrames").toInt();
    run.renderer = root.value("renderer").toString().toStdString();
    run.furnace = furnaceFromJson(root.value("furnace").toArray());
    if (root.value("convergence").isObject())
        run.convergence = convergenceFromJson(root.value("convergence").toObject());
    for (const QJsonValue& value : root.value("references").toArray()) {
        const QJsonObject ref = value.toObject();
        const auto kind = referenceFromName(ref.value("name").toString().toStdString());
        if (!kind)
            continue; // a reference of a newer version: nothing here refers to it
        run.references.push_back({*kind, finite(ref.value("traceMs")).value_or(0.0),
                                  ref.value("threads").toInt(1),
                                  ref.value("image").toString().toStdString()});
    }
    if (root.value("shard").isObject())
        run.shard = shardFromJson(root.value("shard").toObject());
    for (const QJsonValue& value : root.value("shards").toArray()) {
        const QJsonObject o = value.toObject();
        run.shards.push_back({o.value("shard").toString().toStdString(),
                              o.value("host").toString().toStdString(),
                              o.value("renderer").toString().toStdString(),
                              static_cast<std::size_t>(o.value("configurations").toInt())});
    }
    return run;
}

base::Result<ResultsFile> readJson(const QJsonObject& root, const std::string& name) {
    if (root.value("format").toString() != QStringLiteral("speculum-bench"))
        return base::Error{name + ": not a speculum bench result (format is not \"speculum-bench\")"};
    ResultsFile out;
    out.run = runInfoFromJson(root);
    const QJsonArray results = root.value("results").toArray();
    for (qsizetype i = 0; i < results.size(); ++i) {
        const QJsonObject r = results.at(i).toObject();
        const std::string where = name + ": results[" + std::to_string(i) + "].";
        const std::string family = r.value("family").toString().toStdString();
        if (family.empty())
            return base::Error{where + "family: expected a name"};
        const auto cpu = finite(r.value("cpuMs"));
        const auto psnr = finite(r.value("psnr"));
        const auto rmse = finite(r.value("rmse"));
        if (!cpu || !psnr || !rmse)
            return base::Error{where + (!cpu ? "cpuMs" : !psnr ? "psnr" : "rmse") + ": expected a number"};
        const std::optional<Family> known = familyFromName(family);
        if (!known) {
            ++out.unknownFamilies;
            continue;
        }
        Record record;
        record.config.family = *known;
        record.config.id = r.value("id").toString().toStdString();
        record.config.label = r.value("label").toString().toStdString();
        record.config.series = r.value("series").toString().toStdString();
        record.config.reference =
            referenceFromName(r.value("reference").toString().toStdString()).value_or(ReferenceKind::Scene);
        record.sceneSetting = r.value("sceneSetting").toBool();
        record.settings = settingsOf(r.value("settings").toObject());
        record.gpuMs = finite(r.value("gpuMs")).value_or(-1.0);
        record.cpuMs = *cpu;
        record.psnr = *psnr;
        record.rmse = *rmse;
        if (r.value("memory").isObject()) {
            const QJsonObject memory = r.value("memory").toObject();
            record.memory = {bytes(memory.value("main")), bytes(memory.value("mirrors")),
                             bytes(memory.value("shadows")), bytes(memory.value("envmap"))};
        } else {
            record.memory.main = bytes(r.value("memoryBytes"));
        }
        record.psnrMirrors = finite(r.value("psnrMirrors"));
        record.psnrReflector = finite(r.value("psnrReflector"));
        record.errorMap = r.value("errorMap").toString().toStdString();
        readPerceptual(r, record);
        if (r.value("ranOn").isObject()) {
            const QJsonObject on = r.value("ranOn").toObject();
            record.ranOn =
                RanOn{on.value("shard").toString().toStdString(), on.value("host").toString().toStdString()};
        }
        out.records.push_back(std::move(record));
    }
    if (out.records.empty())
        return base::Error{name + (out.unknownFamilies > 0 ? ": no results of a family this version knows"
                                                           : ": no results")};
    return out;
}

base::Status writeCsv(const std::string& path, const std::vector<Record>& records) {
    std::ostringstream csv;
    csv << "id,family,label,series,reference,sceneSetting";
    for (const std::string& name : kSettingNames)
        csv << "," << name;
    csv << ",gpuMs,cpuMs,memoryBytes,rmse,psnr,psnrMirrors,psnrReflector,errorMap,mae,relativeMse,ssim,flip,"
           "hdrFlip,flipMirrors,flipReflector,referenceNoise,psnrLow,psnrHigh,tiedWith,flipMap,flipToBest,"
           "relativeMseRough\n";
    for (const Record& r : records) {
        csv << csvField(r.config.id) << "," << familyName(r.config.family) << "," << csvField(r.config.label)
            << "," << csvField(r.config.series) << "," << referenceName(r.config.reference) << ","
            << (r.sceneSetting ? "true" : "false");
        for (const std::string& name : kSettingNames)
            csv << "," << csvField(settingOf(r, name));
        csv << "," << (r.gpuMs >= 0.0 ? number(r.gpuMs) : "") << "," << number(r.cpuMs) << ","
            << r.memory.total() << "," << number(r.rmse) << "," << number(r.psnr) << ","
            << (r.psnrMirrors ? number(*r.psnrMirrors) : "") << ","
            << (r.psnrReflector ? number(*r.psnrReflector) : "") << "," << csvField(r.errorMap);
        writePerceptualCsv(csv, r);
        csv << "\n";
    }
    return writeText(path, csv.str());
}

namespace {

// One record of results.json's "results".
QJsonObject recordJson(const Record& r) {
    QJsonObject settings;
    for (const auto& [key, value] : r.settings) {
        bool isNumber = false;
        const int n = QString::fromStdString(value).toInt(&isNumber);
        settings[q(key)] = isNumber ? QJsonValue(n) : QJsonValue(q(value));
    }
    QJsonObject object{
        {"id", q(r.config.id)},
        {"family", q(familyName(r.config.family))},
        {"label", q(r.config.label)},
        {"series", q(r.config.series)},
        {"reference", q(referenceName(r.config.reference))},
        {"sceneSetting", r.sceneSetting},
        {"settings", settings},
        {"gpuMs", r.gpuMs >= 0.0 ? QJsonValue(r.gpuMs) : QJsonValue(QJsonValue::Null)},
        {"cpuMs", r.cpuMs},
        {"memoryBytes", static_cast<double>(r.memory.total())},
        {"memory", QJsonObject{{"main", static_cast<double>(r.memory.main)},
                               {"mirrors", static_cast<double>(r.memory.mirrors)},
                               {"shadows", static_cast<double>(r.memory.shadows)},
                               {"envmap", static_cast<double>(r.memory.envmap)}}},
        {"rmse", r.rmse},
        {"psnr", r.psnr},
        {"psnrMirrors", orNull(r.psnrMirrors)},
        {"psnrReflector", orNull(r.psnrReflector)},
        {"errorMap", q(r.errorMap)},
    };
    addPerceptual(object, r);
    if (r.ranOn)
        object.insert("ranOn", QJsonObject{{"shard", q(r.ranOn->shard)}, {"host", q(r.ranOn->host)}});
    return object;
}

} // namespace

base::Status writeJson(const std::string& path, const RunInfo& run, const std::vector<Record>& records) {
    QJsonArray references;
    for (const ReferenceInfo& ref : run.references)
        references.append(QJsonObject{{"name", q(referenceName(ref.kind))},
                                      {"description", q(referenceDescription(ref.kind))},
                                      {"traceMs", ref.traceMs},
                                      {"threads", ref.threads},
                                      {"image", q(ref.image)}});
    QJsonArray results;
    for (const Record& r : records)
        results.append(recordJson(r));
    QJsonObject root{
        {"format", "speculum-bench"},
        {"version", 1},
        {"scene", q(run.scene)},
        {"size", q(std::to_string(run.width) + "x" + std::to_string(run.height))},
        {"quick", run.quick},
        {"warmUpFrames", run.warmUpFrames},
        {"timedFrames", run.timedFrames},
        {"renderer", q(run.renderer)},
        {"references", references},
        {"results", results},
    };
    if (!run.furnace.empty())
        root.insert("furnace", furnaceJson(run.furnace));
    if (run.convergence)
        root.insert("convergence", convergenceJson(*run.convergence));
    if (run.shard)
        root.insert("shard", shardJson(*run.shard));
    if (!run.shards.empty()) {
        QJsonArray shards;
        for (const ShardOrigin& o : run.shards)
            shards.append(QJsonObject{{"shard", q(o.shard)},
                                      {"host", q(o.host)},
                                      {"renderer", q(o.renderer)},
                                      {"configurations", static_cast<double>(o.configurations)}});
        root.insert("shards", shards);
        root.insert("timesFromSeveralMachines", run.timesFromSeveralMachines());
    }
    return writeText(path, QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString());
}

} // namespace speculum::accuracy
