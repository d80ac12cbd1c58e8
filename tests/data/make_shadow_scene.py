#!/usr/bin/env python3
"""Writes double_sided_shadow.gltf for tests/gpu/shadow_facing_test.cpp.

A double-sided 2x2 plane at z = 0 whose normal is +Z, and a double-sided 0.6x0.4
caster quad at z = -0.5 spanning x [-0.3, 0.3], y [0.4, 0.8]. The test looks at the
plane's back (from -Z) with the sun on the same side, travelling along (0, -1, 1):
the caster's shadow falls on x [-0.3, 0.3], y [-0.1, 0.3], and nothing else may
darken the plane. Run from this directory:
    python3 make_shadow_scene.py
"""
import base64, json, struct

def quad(x0, x1, y0, y1, z):
    positions = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    normals = [(0.0, 0.0, 1.0)] * 4
    return positions, normals, [0, 1, 2, 0, 2, 3]

def main():
    quads = [quad(-1.0, 1.0, -1.0, 1.0, 0.0), quad(-0.3, 0.3, 0.4, 0.8, -0.5)]
    blob, views, accessors, meshes = b"", [], [], []
    for positions, normals, indices in quads:
        prims = {}
        for name, data, fmt, kind, ctype in (("POSITION", positions, "<3f", "VEC3", 5126),
                                             ("NORMAL", normals, "<3f", "VEC3", 5126),
                                             ("indices", indices, "<H", "SCALAR", 5123)):
            chunk = b"".join(struct.pack(fmt, *(v if isinstance(v, tuple) else (v,))) for v in data)
            chunk += b"\0" * ((4 - len(chunk) % 4) % 4)
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(chunk)})
            acc = {"bufferView": len(views) - 1, "componentType": ctype, "count": len(data),
                   "type": kind}
            if name == "POSITION":
                acc["min"] = [min(p[i] for p in data) for i in range(3)]
                acc["max"] = [max(p[i] for p in data) for i in range(3)]
            accessors.append(acc)
            blob += chunk
            if name == "indices":
                prims["indices"] = len(accessors) - 1
            else:
                prims.setdefault("attributes", {})[name] = len(accessors) - 1
        prims["material"] = 0
        meshes.append({"primitives": [prims]})
    doc = {
        "asset": {"version": "2.0", "generator": "sherpa tests/data/make_shadow_scene.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "name": "plane"}, {"mesh": 1, "name": "caster"}],
        "meshes": meshes,
        "materials": [{"name": "white double-sided", "doubleSided": True,
                       "pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 1.0}}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(blob).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open("double_sided_shadow.gltf", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")

main()
