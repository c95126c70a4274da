// The project reader and the inspector offer exactly the same range for every limited field, and both take
// it from render/frame/SceneLimits.hpp: each end loads and can be set in the inspector, one step beyond each
// end is refused by both. The choices (map types, fills, ...) are spelled once, in
// render/frame/SceneNames.hpp.
#include "editor/document/Properties.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/frame/Settings.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QDir>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace speculum::document {
namespace {

base::Result<scene::SceneData> parse(const std::string& json) {
    std::vector<std::string> warnings;
    return scene::parseProject(QByteArray::fromStdString(json), QDir("/tmp"), warnings);
}

std::string number(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

struct LimitedField {
    const char* key; // the inspector's property key
    double minimum;
    double maximum;
    // The nearest refused values on either side (integers step by one, or to the next allowed kind of value).
    double below;
    double above;
    // A whole project with this field set to the value.
    std::function<std::string(const std::string&)> project;
};

std::string withSettings(const char* field, const std::string& v) {
    return R"({ "format": "speculum-scene", "version": 1, "settings": { ")" + std::string(field) + R"(": )" +
           v + " } }";
}

std::string withNode(const std::string& node) {
    return R"({ "format": "speculum-scene", "version": 1, "nodes": [ )" + node + " ] }";
}

std::string inComponent(const char* component, const char* field, const std::string& v,
                        const std::string& more = {}) {
    return withNode(R"({ "mesh": { "builtin": "sphere" }, ")" + std::string(component) + R"(": { ")" + field +
                    R"(": )" + v + more + " } }");
}

// Just beyond a real-valued limit: a part in 10^12 (written exactly enough by number()).
double down(double v) {
    return v - std::max(std::abs(v), 1.0) * 1e-12;
}
double up(double v) {
    return v + std::max(std::abs(v), 1.0) * 1e-12;
}

std::vector<LimitedField> limitedFields() {
    using namespace render;
    const auto material = [](const char* field) {
        return [field](const std::string& v) { return inComponent("material", field, v); };
    };
    const auto mirror = [](const char* field) {
        return [field](const std::string& v) {
            return withNode(R"({ "mirror": { ")" + std::string(field) + R"(": )" + v + " } }");
        };
    };
    const auto reflector = [](const char* field) {
        return [field](const std::string& v) { return inComponent("reflector", field, v); };
    };
    const auto shadows = [](const char* field) {
        return [field](const std::string& v) {
            return withNode(R"({ "light": { "type": "spot", "shadows": { ")" + std::string(field) + R"(": )" +
                            v + " } } }");
        };
    };
    return {
        {"settings.mirrorDepth", 0, kMaxMirrorDepth, -1, kMaxMirrorDepth + 1,
         [](const std::string& v) { return withSettings("mirrorDepth", v); }},
        {"settings.ambient", 0.0, 1.0, down(0.0), up(1.0),
         [](const std::string& v) { return withSettings("ambient", v); }},
        {"mesh.tessellation", kMinTessellation, kMaxTessellation, kMinTessellation - 1, kMaxTessellation + 1,
         [](const std::string& v) {
             return withNode(R"({ "mesh": { "builtin": "teapot", "tessellation": )" + v + " } }");
         }},
        {"material.shininess", 0.0, kMaxShininess, down(0.0), up(kMaxShininess), material("shininess")},
        {"material.normalScale", -kMaxNormalScale, kMaxNormalScale, down(-kMaxNormalScale),
         up(kMaxNormalScale), material("normalScale")},
        {"material.opacity", 0.0, 1.0, down(0.0), up(1.0), material("opacity")},
        {"material.alphaCutoff", 0.0, 1.0, down(0.0), up(1.0), material("alphaCutoff")},
        {"light.spotBlend", 0.0, 1.0, down(0.0), up(1.0),
         [](const std::string& v) {
             return withNode(R"({ "light": { "type": "spot", "spotBlend": )" + v + " } }");
         }},
        // Powers of two: the nearest refused sizes that are powers of two, so only the range refuses them.
        {"light.shadows.mapSize", kMinShadowMapSize, kMaxShadowMapSize, kMinShadowMapSize / 2.0,
         kMaxShadowMapSize * 2.0, shadows("mapSize")},
        // Odd widths: likewise.
        {"light.shadows.pcf", kMinPcfWidth, kMaxPcfWidth, kMinPcfWidth - 2, kMaxPcfWidth + 2, shadows("pcf")},
        {"mirror.reflectivity", 0.0, 1.0, down(0.0), up(1.0), mirror("reflectivity")},
        {"mirror.roughness", 0.0, 1.0, down(0.0), up(1.0), mirror("roughness")},
        {"reflector.roughness", 0.0, 1.0, down(0.0), up(1.0), reflector("roughness")},
        {"settings.glossyTaps", kMinGlossyTaps, kMaxGlossyTaps, kMinGlossyTaps - 1, kMaxGlossyTaps + 1,
         [](const std::string& v) { return withSettings("glossyTaps", v); }},
        {"settings.prefilterSamples", kMinPrefilterSamples, kMaxPrefilterSamples, kMinPrefilterSamples - 1,
         kMaxPrefilterSamples + 1, [](const std::string& v) { return withSettings("prefilterSamples", v); }},
        {"reflector.resolution", kMinEnvironmentMapSize, kMaxEnvironmentMapSize, kMinEnvironmentMapSize - 1,
         kMaxEnvironmentMapSize + 1, reflector("resolution")},
        {"reflector.reflectivity", 0.0, 1.0, down(0.0), up(1.0), reflector("reflectivity")},
        {"reflector.mirrorDepth", 0, kMaxMirrorDepth, -1, kMaxMirrorDepth + 1, reflector("mirrorDepth")},
    };
}

// The inspector's description of a field and whether it accepts a value, on the data the reader made.
struct Inspected {
    const PropertyInfo* info = nullptr;
    std::function<base::Status(const QVariant&)> set;
};

Inspected inspect(const LimitedField& field, scene::SceneData& data) {
    const QString key = QString::fromLatin1(field.key);
    if (const auto* p = findSettingsProperty(key)) {
        return {&p->info, [p, &data](const QVariant& v) { return p->set(data.settings, v); }};
    }
    if (const auto* p = findNodeProperty(key)) {
        return {&p->info, [p, &data](const QVariant& v) { return p->set(data.nodes.at(0).data, v); }};
    }
    return {};
}

TEST(LimitsAgree, TheReaderAcceptsExactlyTheRangeTheInspectorOffers) {
    for (const LimitedField& field : limitedFields()) {
        SCOPED_TRACE(field.key);
        // The reader: both ends load, one step beyond each is refused and named by its path.
        auto atMinimum = parse(field.project(number(field.minimum)));
        ASSERT_TRUE(atMinimum) << atMinimum.error();
        auto atMaximum = parse(field.project(number(field.maximum)));
        ASSERT_TRUE(atMaximum) << atMaximum.error();
        for (double refused : {field.below, field.above}) {
            auto beyond = parse(field.project(number(refused)));
            ASSERT_FALSE(beyond) << number(refused) << " loads";
            const std::string leaf = std::string(field.key).substr(std::string(field.key).rfind('.') + 1);
            EXPECT_NE(beyond.error().find(leaf), std::string::npos) << beyond.error();
        }

        // The inspector: the same range (its spin box and slider are built from these), both ends set, one
        // step beyond refused, on the very data the reader made.
        scene::SceneData data = *atMinimum;
        const Inspected inspected = inspect(field, data);
        ASSERT_NE(inspected.info, nullptr) << "no inspector property";
        EXPECT_EQ(inspected.info->minimum, field.minimum);
        EXPECT_EQ(inspected.info->maximum, field.maximum);
        EXPECT_FALSE(inspected.info->minimumExclusive);
        EXPECT_FALSE(inspected.info->maximumExclusive);
        if (inspected.info->slider) {
            EXPECT_GE(inspected.info->softMinimum, field.minimum);
            EXPECT_LE(inspected.info->softMaximum, field.maximum);
        }
        EXPECT_TRUE(inspected.set(field.maximum)) << "maximum refused";
        EXPECT_TRUE(inspected.set(field.minimum)) << "minimum refused";
        EXPECT_FALSE(inspected.set(field.below)) << number(field.below) << " accepted";
        EXPECT_FALSE(inspected.set(field.above)) << number(field.above) << " accepted";
    }
}

TEST(LimitsAgree, EveryChoiceIsSpelledOnceForFileInspectorAndMessages) {
    struct Choice {
        const char* key;
        std::vector<render::names::Name> names;
        std::function<std::string(std::string_view)> project;
    };
    const auto reflector = [](const char* field) {
        return [field](std::string_view v) {
            return inComponent("reflector", field, "\"" + std::string(v) + "\"");
        };
    };
    const std::vector<Choice> choices{
        {"reflector.map",
         {render::names::kReflectorMaps.begin(), render::names::kReflectorMaps.end()},
         reflector("map")},
        {"reflector.fill",
         {render::names::kReflectorFills.begin(), render::names::kReflectorFills.end()},
         reflector("fill")},
        {"reflector.update",
         {render::names::kReflectorUpdates.begin(), render::names::kReflectorUpdates.end()},
         reflector("update")},
        {"mirror.technique",
         {render::names::kMirrorTechniques.begin(), render::names::kMirrorTechniques.end()},
         [](std::string_view v) {
             return withNode(R"({ "mirror": { "technique": ")" + std::string(v) + R"(" } })");
         }},
        {"light.type",
         {render::names::kLightTypes.begin(), render::names::kLightTypes.end()},
         [](std::string_view v) {
             return withNode(R"({ "light": { "type": ")" + std::string(v) + R"(" } })");
         }},
    };
    for (const Choice& c : choices) {
        SCOPED_TRACE(c.key);
        const auto* p = findNodeProperty(QString::fromLatin1(c.key));
        ASSERT_NE(p, nullptr);
        ASSERT_EQ(p->info.options.size(), qsizetype(c.names.size()));
        for (std::size_t i = 0; i < c.names.size(); ++i) {
            // Each file spelling loads as the option the inspector shows under the table's label, and is
            // written back the same way.
            auto loaded = parse(c.project(c.names[i].file));
            ASSERT_TRUE(loaded) << loaded.error();
            EXPECT_EQ(p->get(loaded->nodes.at(0).data).toInt(), int(i)) << c.names[i].file;
            EXPECT_EQ(p->info.options[qsizetype(i)].toStdString(), std::string(c.names[i].label));
            const QByteArray saved = scene::serializeProject(*loaded, QDir("/tmp"));
            EXPECT_TRUE(saved.contains(QByteArray("\"") +
                                       QByteArray(c.names[i].file.data(), qsizetype(c.names[i].file.size())) +
                                       "\""))
                << saved.toStdString();
        }
        // An unknown spelling is refused with the whole list.
        auto unknown = parse(c.project("nonsense"));
        ASSERT_FALSE(unknown);
        for (const auto& name : c.names) {
            EXPECT_NE(unknown.error().find(std::string(name.file)), std::string::npos) << unknown.error();
        }
    }
}

} // namespace
} // namespace speculum::document
