#!/usr/bin/env python3
"""Writes the texture-failure files used by tests/cli/cli_missing_textures_test.cpp.

missing_texture.gltf: a unit quad facing +Z whose material 'Quad' reads an image file
that does not exist as baseColorTexture and occlusionTexture.
corrupt_texture.gltf: the same quad reading corrupt_texture.png, a PNG signature
followed by bytes no decoder accepts. Run from this directory:
    python3 make_missing_textures.py
"""
import base64, json, struct

def quad(image_uri):
    positions = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    normals = [(0, 0, 1)] * 4
    uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    indices = [0, 1, 2, 0, 2, 3]
    pos = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm = b"".join(struct.pack("<3f", *n) for n in normals)
    uv = b"".join(struct.pack("<2f", *t) for t in uvs)
    idx = b"".join(struct.pack("<H", i) for i in indices)
    blob = pos + nrm + uv + idx
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    views, offset = [], 0
    for part in (pos, nrm, uv, idx):
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part)
    return {
        "asset": {"version": "2.0", "generator": "sherpa tests/data/make_missing_textures.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [{"name": "Quad",
                       "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                "metallicFactor": 0.0},
                       "occlusionTexture": {"index": 0}}],
        "textures": [{"source": 0}],
        "images": [{"uri": image_uri}],
        "buffers": [{"uri": uri, "byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-1, -1, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }

for name, image in (("missing_texture.gltf", "does_not_exist.png"),
                    ("corrupt_texture.gltf", "corrupt_texture.png")):
    with open(name, "w") as f:
        json.dump(quad(image), f, indent=1)
with open("corrupt_texture.png", "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + bytes(range(7, 200, 3)))
