#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/image/Image.hpp"

#include <array>
#include <glm/vec3.hpp>
#include <memory>
#include <string>

namespace speculum::render {

// How texture coordinates outside [0, 1] are read (glTF sampler wrapS / wrapT, Assimp's mapping modes).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// glTF's alphaMode: Opaque ignores alpha; Mask discards fragments whose alpha (opacity × texture alpha ×
// vertex alpha) is below alphaCutoff, in both renderers and in shadows; Blend is drawn as Mask at 0.5
// (a warned fallback: no sorted transparency yet).
enum class AlphaMode { Opaque, Mask, Blend };
static_assert(int(TextureWrap::MirroredRepeat) + 1 == names::kTextureWraps.size(), "one name per value");
static_assert(int(AlphaMode::Blend) + 1 == names::kAlphaModes.size(), "one name per value");

// One texture a material samples. Either a file (`path`, absolute) that the renderer loads itself, or an
// image already decoded (`image`: a model's embedded texture, set by the scene's evaluation), in which case
// `path` is only its name for messages and caches ("/abs/model.glb#*0").
struct TextureSource {
    std::string path;
    std::shared_ptr<const TextureImage> image;

    bool empty() const { return path.empty() && !image; }
    bool operator==(const TextureSource&) const = default;
};

// A texture field's value as the declarations see it: its path.
inline FieldValue toFieldValue(const TextureSource& texture) {
    return texture.path;
}
inline bool fromFieldValue(const FieldValue& value, TextureSource& out) {
    const std::string* path = std::get_if<std::string>(&value);
    return path && (out = TextureSource{*path, nullptr}, true);
}

// Blinn-Phong, with the additions model files need:
//   base     = color · baseTexture.rgb · vertexColor.rgb
//   emitted  = emission · emissionTexture.rgb
//   out      = emitted + base·(ambient·sceneAmbient + diffuse·Σ n·l·vis·L) + specular·specularColor·Σ
//   (n·h)^s·vis·L
// with n taken from the normal map (tangent space, scaled in xy by normalScale) when there is one and the
// mesh has tangents. Every texture wraps as `wrap` says (u, v).
struct Material {
    glm::dvec3 color{0.8, 0.8, 0.8};
    double ambient = 1.0;
    double diffuse = 1.0;
    double specular = 0.0;
    double shininess = 32.0;
    glm::dvec3 emission{0.0, 0.0, 0.0};
    TextureSource texture;                   // base colour (sRGB), alpha for Mask; empty for none
    glm::dvec3 specularColor{1.0, 1.0, 1.0}; // tints highlights: metals' highlights take their colour
    TextureSource emissionTexture;           // multiplies emission (sRGB)
    TextureSource normalTexture;             // tangent-space normal map (linear)
    double normalScale = 1.0;
    std::array<TextureWrap, 2> wrap{TextureWrap::Repeat, TextureWrap::Repeat};
    double opacity = 1.0; // base alpha factor
    AlphaMode alphaMode = AlphaMode::Opaque;
    double alphaCutoff = 0.5;

    bool operator==(const Material&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// The alpha below which a masked material is cut away, in the lit passes and in shadows: its cutoff, or
// one half for Blend (no sorted transparency yet: drawn as Mask at one half, the importer warns).
inline double effectiveAlphaCutoff(const Material& m) {
    return m.alphaMode == AlphaMode::Blend ? 0.5 : m.alphaCutoff;
}

template <typename Visit>
void Material::fields(Visit&& visit) {
    // Coefficients that multiply light: from 0 up to the intensity limit, the slider to 2.
    const auto coefficient = [](std::string_view name, std::string_view label, std::string_view meaning) {
        return FieldSpec{.name = name,
                         .label = label,
                         .meaning = meaning,
                         .min = 0,
                         .max = kMaxIntensity,
                         .slider = true,
                         .softMax = 2.0};
    };
    const auto texture = [](std::string_view name, std::string_view label, std::string_view meaning) {
        return FieldSpec{.name = name,
                         .label = label,
                         .meaning = meaning,
                         .type = FieldType::Path,
                         .write = FieldWrite::UnlessDefault};
    };
    const auto modelField =
        [](FieldSpec spec) { // what imported models bring; files without it stay as they were
            spec.write = FieldWrite::UnlessDefault;
            return spec;
        };
    visit(field(
        &Material::color,
        {.name = "color", .label = "Colour", .meaning = "The surface's colour", .type = FieldType::Color}));
    visit(field(&Material::ambient, coefficient("ambient", "Ambient", "How much ambient light it reflects")));
    visit(field(&Material::diffuse, coefficient("diffuse", "Diffuse", "How much light it scatters")));
    visit(field(&Material::specular, coefficient("specular", "Specular", "The strength of its highlights")));
    visit(field(&Material::shininess,
                {.name = "shininess",
                 .label = "Shininess",
                 .meaning = "The Blinn-Phong exponent: larger is a smaller, sharper highlight",
                 .min = 0,
                 .max = kMaxShininess,
                 .slider = true,
                 .softMin = 1,
                 .softMax = 256,
                 .decimals = 1,
                 .step = 1}));
    visit(field(&Material::emission, {.name = "emission",
                                      .label = "Emission",
                                      .meaning = "Light it gives off itself, lit or not",
                                      .type = FieldType::Color}));
    visit(field(&Material::texture, texture("texture", "Texture", "The base colour image; empty for none")));
    visit(field(&Material::specularColor,
                modelField({.name = "specularColor",
                            .label = "Highlight colour",
                            .meaning = "Tints the highlights (a metal's take its colour)",
                            .type = FieldType::Color})));
    visit(field(&Material::emissionTexture,
                texture("emissionTexture", "Emission texture", "Multiplies the emission; empty for none")));
    visit(field(&Material::normalTexture,
                texture("normalTexture", "Normal map", "Tangent-space normal map; empty for none")));
    visit(field(&Material::normalScale,
                modelField({.name = "normalScale",
                            .label = "Normal strength",
                            .meaning = "Scales the normal map's tilt (negative flips it)",
                            .min = -kMaxNormalScale,
                            .max = kMaxNormalScale,
                            .slider = true,
                            .softMax = 2.0})));
    visit(field(&Material::wrap,
                modelField({.name = "wrap",
                            .label = "Wrap",
                            .meaning = "How every texture repeats beyond its edges, along u and v: one mode "
                                       "for both, or [u, v]",
                            .type = FieldType::WrapPair,
                            .noun = "wrap mode",
                            .choices = names::kTextureWraps})));
    visit(field(&Material::opacity, modelField({.name = "opacity",
                                                .label = "Opacity",
                                                .meaning = "The base alpha",
                                                .min = 0,
                                                .max = 1,
                                                .slider = true})));
    visit(
        field(&Material::alphaMode,
              modelField({.name = "alphaMode",
                          .label = "Alpha",
                          .meaning = "Opaque ignores alpha; mask cuts away below the cutoff; blend is drawn "
                                     "as a mask at one half",
                          .type = FieldType::Choice,
                          .noun = "alpha mode",
                          .choices = names::kAlphaModes})));
    visit(field(&Material::alphaCutoff,
                modelField({.name = "alphaCutoff",
                            .label = "Alpha cutoff",
                            .meaning = "A masked material is cut away where its alpha is below this",
                            .min = 0,
                            .max = 1,
                            .slider = true})));
}

} // namespace speculum::render
