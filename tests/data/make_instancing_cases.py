#!/usr/bin/env python3
"""Writes the EXT_mesh_gpu_instancing files of tests/scene/gpu_instancing_test.cpp.

One triangle mesh on a node whose extension is valid, or breaks one rule: counts
that differ, a non-finite row, a zero rotation, a count its bytes do not back, a
component type the extension does not allow, an id past 2^32, no mesh, a skin.
Run from this directory:
    python3 make_instancing_cases.py
"""
import base64, copy, json, math, struct

def f32(values):
    return b"".join(struct.pack("<f", v) for v in values)

def instanced(translations, rotations=None, scales=None, primitives=1):
    """A triangle mesh (`primitives` copies) on node 0, instanced by the given rows."""
    pos = f32([0, 0, 0, 1, 0, 0, 0, 1, 0])
    blob = bytearray(pos)
    views, accessors = [], []
    def add(data, count, type_, component=5126, normalized=False):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        blob.extend(data)
        a = {"bufferView": len(views) - 1, "componentType": component, "count": count,
             "type": type_}
        if normalized:
            a["normalized"] = True
        accessors.append(a)
        return len(accessors) - 1
    position = add(pos, 3, "VEC3")
    accessors[position]["min"] = [0, 0, 0]
    accessors[position]["max"] = [1, 1, 0]
    attributes = {"TRANSLATION": add(f32([c for t in translations for c in t]),
                                     len(translations), "VEC3")}
    if rotations is not None:
        attributes["ROTATION"] = add(f32([c for r in rotations for c in r]), len(rotations),
                                     "VEC4")
    if scales is not None:
        attributes["SCALE"] = add(f32([c for s in scales for c in s]), len(scales), "VEC3")
    uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()
    return {
        "asset": {"version": "2.0", "generator": "sherpa tests/data/make_instancing_cases.py"},
        "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "extensionsRequired": ["EXT_mesh_gpu_instancing"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "forest", "translation": [0, 0, -1],
                   "extensions": {"EXT_mesh_gpu_instancing": {"attributes": attributes}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": position}}] * primitives}],
        "buffers": [{"uri": uri, "byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": accessors,
    }

def attributes(doc):
    return doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]

half = math.sqrt(0.5)
rows_t = [(0, 0, 0), (2, 0, 0), (4, 0, 0)]
rows_r = [(0, 0, 0, 1), (0, 0, half, half), (0, 0, 1, 0)]  # identity, 90 and 180 deg about Z
rows_s = [(1, 1, 1), (2, 2, 2), (1, 3, 1)]
cases = {}
cases["instancing_basic.gltf"] = instanced(rows_t, rows_r, rows_s)
# ROTATION counts 2 rows, TRANSLATION and SCALE 3: the first 2 are drawn.
cases["instancing_count_mismatch.gltf"] = instanced(rows_t, rows_r[:2], rows_s)
# Row 1 has a NaN translation, row 2 a zero quaternion: only row 0 is drawn.
cases["instancing_bad_rows.gltf"] = instanced([(0, 0, 0), (math.nan, 0, 0), (4, 0, 0)],
                                              [(0, 0, 0, 1), (0, 0, 0, 1), (0, 0, 0, 0)])
# 100 million translations backed by 36 bytes: the node is drawn once.
g = instanced(rows_t); g["accessors"][attributes(g)["TRANSLATION"]]["count"] = 100000000
cases["instancing_huge_count.gltf"] = g
# Translations as unsigned shorts (not an allowed type): read as glTF decodes them.
g = instanced(rows_t)
g["buffers"].append({"uri": "data:application/octet-stream;base64," +
                     base64.b64encode(struct.pack("<9H", 0, 0, 0, 2, 0, 0, 4, 0, 0) +
                                      b"\0\0").decode(), "byteLength": 20})
g["bufferViews"].append({"buffer": 1, "byteOffset": 0, "byteLength": 18})
g["accessors"].append({"bufferView": len(g["bufferViews"]) - 1, "componentType": 5123,
                       "count": 3, "type": "VEC3"})
attributes(g)["TRANSLATION"] = len(g["accessors"]) - 1
cases["instancing_ushort_translation.gltf"] = g
# An accessor id of 2^32, which an int reads as 0.
g = instanced(rows_t); attributes(g)["TRANSLATION"] = 2**32
cases["instancing_id_2p32.gltf"] = g
# The extension on a node without a mesh.
g = instanced(rows_t); g["nodes"].append(copy.deepcopy(g["nodes"][0])); del g["nodes"][1]["mesh"]
g["scenes"][0]["nodes"] = [0, 1]; cases["instancing_no_mesh.gltf"] = g
# 2^20 zero translations (no bufferView: they cost the file nothing) on a mesh of two
# primitives: 2^21 instances, twice the limit.
g = instanced(rows_t, primitives=2)
g["accessors"].append({"componentType": 5126, "count": 2**20, "type": "VEC3"})
attributes(g)["TRANSLATION"] = len(g["accessors"]) - 1
cases["instancing_over_limit.gltf"] = g

for name, doc in cases.items():
    with open(name, "w") as f:
        json.dump(doc, f, indent=1)
