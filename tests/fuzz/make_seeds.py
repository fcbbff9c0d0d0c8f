#!/usr/bin/env python3
"""Writes the hand-made seeds of tests/fuzz/corpus/ (valid small files of each format, so the
fuzzers start from inputs that load and mutate them; the bundled resources and tests/data/bad
are added to the seeds at configure time). The EXR seeds (corpus/fuzz_exr/rgba_<compression>.exr,
tiled_mip.exr, y_float_window.exr: 8x4 images, one per OpenEXR compression, a tiled mipmapped one
and a luminance-only one with an offset data window) were written once with OpenEXR's
RgbaOutputFile / TiledRgbaOutputFile / OutputFile, and multipart_scanline_tiled.exr (8x4, a ZIP
scanline part and a PIZ mipmapped tiled part, float RGB 0.25/0.5/1) with MultiPartOutputFile. Usage: python3 make_seeds.py"""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def put(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    import math
    mant, e = math.frexp(m)
    s = mant * 256.0 / m
    return bytes([int(r * s), int(g * s), int(b * s), e + 128])


def rle_channel(values):
    out = bytearray()
    i = 0
    while i < len(values):  # runs of equal bytes as (128+n, v), the rest as literal (n, v...)
        run = 1
        while i + run < len(values) and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 3:
            out += bytes([128 + run, values[i]])
            i += run
        else:
            n = min(2, len(values) - i)
            out += bytes([n]) + bytes(values[i:i + n])
            i += n
    return bytes(out)


def hdr_seeds():
    head = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y %d +X %d\n"
    flat = (head % (2, 4)).encode() + b"".join(rgbe(0.1 * x, 0.5, 2.0 * y + 0.1) for y in range(2) for x in range(4))
    put("fuzz_hdr", "flat_4x2.hdr", flat)
    w, h = 16, 3
    rle = bytearray((head % (h, w)).encode())
    for y in range(h):
        px = [rgbe(1.0 if x < 8 else 0.25 * x, 0.5, 100.0 * y + 1.0) for x in range(w)]
        rle += bytes([2, 2, w >> 8, w & 255])
        for c in range(4):
            rle += rle_channel([p[c] for p in px])
    put("fuzz_hdr", "rle_16x3.hdr", bytes(rle))


def ply_seeds():
    verts = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
    head = ("ply\nformat %s 1.0\ncomment seed\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n")
    body = "".join("%g %g %g 0 1 0\n" % v for v in verts) + "4 0 3 2 1\n"
    put("fuzz_ply", "quad_ascii.ply", head % "ascii" + body)
    binary = (head % "binary_little_endian").encode()
    binary += b"".join(struct.pack("<6f", *v, 0, 1, 0) for v in verts) + struct.pack("<B4i", 4, 0, 3, 2, 1)
    put("fuzz_ply", "quad_binary.ply", binary)


def gltf_seeds():
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    blob = positions + indices

    def doc(uri):
        buffer = {"byteLength": len(blob)}
        if uri:
            buffer["uri"] = uri
        return {
            "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"mesh": 0, "translation": [0, 1, 0]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
            "buffers": [buffer],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                            {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]},
                          {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        }
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    put("fuzz_gltf", "triangle_embedded.gltf", json.dumps(doc(uri), separators=(",", ":")))
    text = json.dumps(doc(None), separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    glb = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(blob), b"BIN\0") + blob
    put("fuzz_gltf", "triangle.glb", b"glTF" + struct.pack("<II", 2, 12 + len(glb)) + glb)


def obj_seeds():
    put("fuzz_obj", "features.obj", "\n".join([
        "# groups, quads, uvs, normals, negative indices, smoothing, a material library that is missing",
        "mtllib missing.mtl", "o box", "g top", "s 1", "usemtl gold",
        "v -1 1 -1", "v 1 1 -1", "v 1 1 1", "v -1 1 1",
        "vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 1 0",
        "f 1/1/1 4/4/1 3/3/1 2/2/1",
        "g side", "v -1 0 -1", "v 1 0 -1",
        "f -2 -1 2 1", "l 1 2", "p 3", ""]))


def json_seeds():
    v0_scene = {
        "format": "wavelit-scene", "version": 0, "name": "v0",
        "camera": {"position": [0, 1, 4], "target": [0, 0, 0], "fov": 40},
        "render": {"width": 64, "height": 64, "bounces": 2},
        "materials": [{"id": 1, "name": "gold", "brdf": "ggx", "roughness": 0.2, "baseColor": [1, 0.8, 0.3]},
                      {"id": 2, "name": "floor", "brdf": "lambert"}],
        "objects": [{"id": 1, "name": "a", "mesh": "../meshes/quad.obj", "material": "gold",
                     "translation": [0, 1, 0], "rotation": [0, 45, 0], "scale": [1, 1, 1]},
                    {"name": "b", "mesh": "../../../resources/meshes/quad.obj", "material": "floor"}],
        "lighting": {"name": "l", "environment": {"map": "../envmaps/night.exr", "exposure": 1.5, "rotation": 30},
                     "lights": [{"id": 1, "name": "p", "type": "point", "position": [0, 2, 0], "intensity": 5}]},
        "extras": {"tool": {"nested": [1, 2, {"x": None}]}},
    }
    put("fuzz_scene", "version0_migrated.wlscene", json.dumps(v0_scene, indent=1))
    lights = [
        {"id": 1, "name": "p", "type": "point", "position": [0, 2, 0], "intensity": 5, "color": [1, 1, 1]},
        {"id": 2, "name": "s", "type": "sphere", "position": [1, 2, 0], "radius": 0.2},
        {"id": 3, "name": "r", "type": "rect", "position": [0, 3, 0], "direction": [0, -1, 0], "size": [1, 2]},
        {"id": 4, "name": "c", "type": "spot", "coneInner": 10, "coneOuter": 30},
        {"name": "sun", "type": "sun", "direction": [0.3, -1, 0.2], "angularDiameter": 0.53},
    ]
    v0_light = {"format": "wavelit-lighting", "version": 0, "name": "v0",
                "environment": {"map": "../envmaps/city.exr", "exposure": -2, "tint": [1, 0.9, 0.8]},
                "lights": lights}
    put("fuzz_lighting", "version0_all_lights.wllight", json.dumps(v0_light, indent=1))


if __name__ == "__main__":
    hdr_seeds()
    ply_seeds()
    gltf_seeds()
    obj_seeds()
    json_seeds()
