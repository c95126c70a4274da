#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/plan/Hasher.hpp"

#include <type_traits>

namespace speculum::render {

// The parts of a FrameInput that more than one signature hashes, field by field, so a map's signature
// and a shadow's read a material or a texture the same way (tests/render/plan/test_signatures.cpp
// perturbs every field and checks which signatures see it).

// A declared field's value (Field.hpp): a texture by identity (its file path, or the decoded image's
// address: an embedded image replaced by another is a different texture), an optional group by presence
// and its own fields, anything else by its bytes (numbers, vectors, enumerations).
template <typename T>
void addFields(Hasher& h, const T& value, bool mapsOnly = false);

inline void addValue(Hasher& h, const TextureSource& t, bool) {
    h.add(std::string_view(t.path));
    h.add(static_cast<const void*>(t.image.get()));
}

template <typename T>
void addValue(Hasher& h, const T& value, bool mapsOnly) {
    if constexpr (IsOptional<T>::value) {
        h.add(value.has_value());
        if (value)
            addFields(h, *value, mapsOnly);
    } else {
        static_assert(!std::is_class_v<T> || std::is_standard_layout_v<T>,
                      "a declared field the hash cannot read as bytes");
        h.add(value);
    }
}

// Every declared field of `value` that applies to it (a point light's cone draws nothing); with
// `mapsOnly`, only those an environment map draws (FieldSpec::drawnInMaps). A field added to a
// declaration is in every signature that hashes its struct, with nothing else to change.
template <typename T>
void addFields(Hasher& h, const T& value, bool mapsOnly) {
    forEachField<T>([&](const auto& f) {
        using Owner = typename std::decay_t<decltype(f)>::OwnerType;
        const Owner& owner = value;
        if ((mapsOnly && !f.spec.drawnInMaps) || !f.appliesTo(owner))
            return;
        h.add(f.spec.name);
        addValue(h, owner.*f.member, mapsOnly);
    });
}

// Everything the lit passes read of a material.
inline void addMaterial(Hasher& h, const Material& m) {
    addFields(h, m);
}

// What a shadow map reads of a caster's material: nothing for an opaque one; for a masked one the alpha
// it cuts at (opacity · base texture alpha against the effective cutoff, passes/ShadowMaps.cpp).
inline void addShadowAlpha(Hasher& h, const Material& m) {
    const bool masked = m.alphaMode != AlphaMode::Opaque;
    h.add(masked);
    if (!masked)
        return;
    h.add(m.opacity);
    h.add(effectiveAlphaCutoff(m));
    addValue(h, m.texture, false);
    h.add(m.wrap);
}

} // namespace speculum::render
