#!/usr/bin/env python3
"""Writes resources/models/toyset.glb: the demo model of resources/scenes/models.speculum.json.

A small glTF 2.0 binary made only from this script (no third-party content), built to exercise what
model import has to keep: a node tree with transforms, five parts with a material each, an embedded
base-colour texture whose orientation is obvious (an arrow pointing to the image's top, a red corner at
its top left), vertex colours, a metal (metallic 1, roughness 0.25), an emissive lamp and an alpha cut-out
(alphaMode MASK). Lengths in metres. Run it from anywhere: python3 tools/make_toy_model.py
"""
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "models", "toyset.glb")


def png(width, height, pixel):
    """RGBA8 PNG bytes; pixel(x, y) -> (r, g, b, a) with y = 0 the TOP row, as PNG stores it."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        for x in range(width):
            raw.extend(pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) +
            chunk(b"IEND", b""))


def crate_pixel(x, y, n=128):
    """Warm wood with planks, a dark blue arrow pointing to the top and a red square at the top left."""
    u, v = (x + 0.5) / n, (y + 0.5) / n  # v = 0 at the top of the image
    plank = int(v * 4)
    shade = 0.85 + 0.1 * math.sin(37.0 * u + plank * 1.7) + (0.08 if plank % 2 else 0.0)
    r, g, b = 0.78 * shade, 0.52 * shade, 0.28 * shade
    if min(x, y, n - 1 - x, n - 1 - y) < 6:  # frame
        r, g, b = 0.35, 0.22, 0.1
    if u < 0.22 and v < 0.22 and min(x, y) >= 6:  # the orientation mark: top left
        r, g, b = 0.85, 0.08, 0.06
    # Arrow: a shaft from v = 0.8 up to 0.45, a head from 0.45 up to 0.15.
    in_shaft = abs(u - 0.5) < 0.08 and 0.45 <= v <= 0.82
    in_head = 0.15 <= v < 0.45 and abs(u - 0.5) < (v - 0.15) * 0.9
    if in_shaft or in_head:
        r, g, b = 0.08, 0.16, 0.55
    return (int(r * 255 + 0.5), int(g * 255 + 0.5), int(b * 255 + 0.5), 255)


def sign_pixel(x, y, n=64):
    """A white sign with round holes (alpha 0) in a 3x3 grid and a green rim."""
    u, v = (x + 0.5) / n, (y + 0.5) / n
    cu, cv = (int(u * 3) + 0.5) / 3, (int(v * 3) + 0.5) / 3
    hole = (u - cu) ** 2 + (v - cv) ** 2 < 0.11 ** 2
    rim = min(u, v, 1 - u, 1 - v) < 0.06
    if rim:
        return (40, 170, 60, 255)
    return (235, 235, 225, 0 if hole else 255)


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors, self.meshes = [], [], []

    def _view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin.extend(data)
        self.views.append(view)
        return len(self.views) - 1

    def _accessor(self, values, kind, comp_count):
        flat = [c for v in values for c in v] if comp_count > 1 else list(values)
        view = self._view(struct.pack("<%df" % len(flat), *flat), 34962)
        acc = {"bufferView": view, "componentType": 5126, "count": len(values), "type": kind}
        if kind == "VEC3":
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, name, positions, normals, uvs, indices, material, colors=None):
        attributes = {"POSITION": self._accessor(positions, "VEC3", 3),
                      "NORMAL": self._accessor(normals, "VEC3", 3)}
        if uvs:
            attributes["TEXCOORD_0"] = self._accessor(uvs, "VEC2", 2)
        if colors:
            attributes["COLOR_0"] = self._accessor(colors, "VEC4", 4)
        view = self._view(struct.pack("<%dH" % len(indices), *indices), 34963)
        self.accessors.append({"bufferView": view, "componentType": 5123, "count": len(indices),
                               "type": "SCALAR"})
        self.meshes.append({"name": name, "primitives": [{"attributes": attributes,
                                                          "indices": len(self.accessors) - 1,
                                                          "material": material}]})
        return len(self.meshes) - 1

    def image(self, data):
        return self._view(data)


def box(hx, hy, hz, colors_for=None):
    """A box with a whole-image quad on each face, upright seen from outside (+Y up on the sides; the top's
    image top towards -Z). glTF uvs: (0, 0) is the image's top left."""
    faces = [  # normal, right, up (the image's right and top directions on the face)
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
        ((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1))]
    h = (hx, hy, hz)
    positions, normals, uvs, indices, colors = [], [], [], [], []
    for n, r, up in faces:
        base = len(positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):  # bottom left, bottom right, top right, top left
            p = [h[i] * (n[i] + su * r[i] + sv * up[i]) for i in range(3)]
            positions.append(p)
            normals.append(list(n))
            uvs.append([(su + 1) / 2, 1 - (sv + 1) / 2])
            if colors_for:
                colors.append(colors_for(p))
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, uvs, indices, colors


def sphere(radius, rings=16, segments=32):
    positions, normals, uvs, indices = [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append([radius * c for c in n])
            normals.append(n)
            uvs.append([j / segments, i / rings])
    for i in range(rings):
        for j in range(segments):
            a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            indices += [a, b, a + 1, a + 1, b, b + 1]
    return positions, normals, uvs, indices


def rainbow(p):
    hue = (math.atan2(p[2], p[0]) / (2 * math.pi)) % 1.0
    k = [(5 + hue * 6) % 6, (3 + hue * 6) % 6, (1 + hue * 6) % 6]
    rgb = [1 - max(0.0, min(1.0, min(x, 4 - x))) for x in k]
    return [0.15 + 0.85 * c for c in rgb] + [1.0]


def main():
    b = Builder()
    crate_png = png(128, 128, crate_pixel)
    sign_png = png(64, 64, sign_pixel)
    materials = [
        {"name": "Crate wood", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.6}},
        {"name": "Gold", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.71, 0.29, 1.0],
                                                  "metallicFactor": 1.0, "roughnessFactor": 0.25}},
        {"name": "Lamp glow", "emissiveFactor": [1.0, 0.6, 0.2],
         "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.08, 0.05, 1.0], "metallicFactor": 0.0,
                                  "roughnessFactor": 0.9}},
        {"name": "Painted plinth", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1],
                                                            "metallicFactor": 0.0, "roughnessFactor": 0.5}},
        {"name": "Perforated sign", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicFactor": 0.0,
                                  "roughnessFactor": 0.8}},
    ]
    crate = b.mesh("Crate", *box(0.3, 0.3, 0.3)[:4], material=0)
    orb = b.mesh("Gold orb", *sphere(0.22), material=1)
    lamp = b.mesh("Lamp", *sphere(0.07, 8, 16), material=2)
    p, n, uv, idx, col = box(0.6, 0.06, 0.6, colors_for=rainbow)
    plinth = b.mesh("Plinth", p, n, None, idx, material=3, colors=col)
    sign = b.mesh("Sign", [[-0.3, -0.3, 0], [0.3, -0.3, 0], [0.3, 0.3, 0], [-0.3, 0.3, 0]],
                  [[0, 0, 1]] * 4, [[0, 1], [1, 1], [1, 0], [0, 0]], [0, 1, 2, 0, 2, 3], material=4)
    images = [{"bufferView": b.image(crate_png), "mimeType": "image/png", "name": "crate"},
              {"bufferView": b.image(sign_png), "mimeType": "image/png", "name": "sign"}]
    turned = [0.0, math.sin(math.radians(-15)), 0.0, math.cos(math.radians(-15))]  # 30 degrees about +Y
    nodes = [
        {"name": "Toy set", "children": [1, 2, 4, 5]},
        {"name": "Plinth", "mesh": plinth, "translation": [0, 0.06, 0]},
        {"name": "Crate", "mesh": crate, "translation": [-0.2, 0.42, 0.1], "rotation": turned,
         "children": [3]},
        {"name": "Orb", "mesh": orb, "translation": [0, 0.52, 0]},
        {"name": "Lamp", "mesh": lamp, "translation": [0.38, 0.2, 0.38]},
        {"name": "Sign", "mesh": sign, "translation": [0.35, 0.42, -0.3], "rotation": [0.0, math.sin(math.radians(15)), 0.0, math.cos(math.radians(15))]},
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "speculum tools/make_toy_model.py"},
        "scene": 0, "scenes": [{"name": "Toy set", "nodes": [0]}], "nodes": nodes, "meshes": b.meshes,
        "materials": materials, "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 1}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}, {"wrapS": 33071, "wrapT": 33071}],
        "images": images, "accessors": b.accessors, "bufferViews": b.views,
        "buffers": [{"byteLength": 0}],
    }
    while len(b.bin) % 4:
        b.bin.append(0)
    gltf["buffers"][0]["byteLength"] = len(b.bin)
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = (struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(b.bin), b"BIN\0") +
            bytes(b.bin))
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)
    print(os.path.normpath(OUT))


if __name__ == "__main__":
    main()
