#include "app/bench/Results.hpp"

#include "render/io/AtomicFile.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace speculum::app::bench {

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

// Staged and checked (render::AtomicFile): a full disk is an error, never a truncated file.
render::Status writeText(const std::string& path, const std::string& text) {
    return render::writeFileAtomically(path, text);
}

} // namespace

render::Status writeCsv(const std::string& path, const std::vector<Record>& records) {
    std::ostringstream csv;
    csv << "id,family,label,series,reference,sceneSetting";
    for (const std::string& name : kSettingNames)
        csv << "," << name;
    csv << ",gpuMs,cpuMs,memoryBytes,rmse,psnr,psnrMirrors,psnrReflector,errorMap\n";
    for (const Record& r : records) {
        csv << csvField(r.config.id) << "," << familyName(r.config.family) << "," << csvField(r.config.label)
            << "," << csvField(r.config.series) << "," << referenceName(r.config.reference) << ","
            << (r.sceneSetting ? "true" : "false");
        for (const std::string& name : kSettingNames)
            csv << "," << csvField(settingOf(r, name));
        csv << "," << (r.gpuMs >= 0.0 ? number(r.gpuMs) : "") << "," << number(r.cpuMs) << ","
            << r.memory.total() << "," << number(r.rmse) << "," << number(r.psnr) << ","
            << (r.psnrMirrors ? number(*r.psnrMirrors) : "") << ","
            << (r.psnrReflector ? number(*r.psnrReflector) : "") << "," << csvField(r.errorMap) << "\n";
    }
    return writeText(path, csv.str());
}

render::Status writeJson(const std::string& path, const RunInfo& run, const std::vector<Record>& records) {
    QJsonArray references;
    for (const ReferenceInfo& ref : run.references)
        references.append(QJsonObject{{"name", q(referenceName(ref.kind))},
                                      {"description", q(referenceDescription(ref.kind))},
                                      {"traceMs", ref.traceMs},
                                      {"threads", ref.threads},
                                      {"image", q(ref.image)}});
    QJsonArray results;
    for (const Record& r : records) {
        QJsonObject settings;
        for (const auto& [key, value] : r.settings) {
            bool isNumber = false;
            const int n = QString::fromStdString(value).toInt(&isNumber);
            settings[q(key)] = isNumber ? QJsonValue(n) : QJsonValue(q(value));
        }
        results.append(QJsonObject{
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
        });
    }
    const QJsonObject root{
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
    return writeText(path, QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString());
}

} // namespace speculum::app::bench
