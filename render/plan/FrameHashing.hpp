#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/plan/Hasher.hpp"

namespace speculum::render {

// The parts of a FrameInput that more than one signature hashes, field by field, so a map's signature
// and a shadow's read a material or a texture the same way (tests/render/plan/test_signatures.cpp
// perturbs every field and checks which signatures see it).

// A texture by identity: its file path, or the decoded image's address (an embedded image replaced by
// another is a different texture), and how it wraps.
inline void addTexture(Hasher& h, const TextureSource& t) {
    h.add(std::string_view(t.path));
    h.add(static_cast<const void*>(t.image.get()));
    h.add(static_cast<int>(t.wrapS));
    h.add(static_cast<int>(t.wrapT));
}

// Everything the lit passes read of a material.
inline void addMaterial(Hasher& h, const Material& m) {
    h.add(m.color);
    h.add(m.ambient);
    h.add(m.diffuse);
    h.add(m.specular);
    h.add(m.shininess);
    h.add(m.emission);
    h.add(m.specularColor);
    addTexture(h, m.texture);
    addTexture(h, m.emissionTexture);
    addTexture(h, m.normalTexture);
    h.add(m.normalScale);
    h.add(m.opacity);
    h.add(static_cast<int>(m.alphaMode));
    h.add(m.alphaCutoff);
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
    addTexture(h, m.texture);
}

} // namespace speculum::render
