#!/usr/bin/env python3
"""Writes the hand-made malformed glTF files used by tests/scene/bad_input_test.cpp.

Each file breaks one rule; the test expects a clear error naming the file and the
problem (or, where the spec allows it, a warning). Run from this directory:
    python3 make_malformed.py
"""
import base64, copy, json, math, struct

def buffer_bytes(positions, indices):
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    idx = b"".join(struct.pack("<H", i) for i in indices)
    pad = (4 - len(idx) % 4) % 4
    return data, idx + b"\0" * pad

def triangle(positions=((0, 0, 0), (1, 0, 0), (0, 1, 0)), indices=(0, 1, 2)):
    pos, idx = buffer_bytes(positions, indices)
    blob = pos + idx
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    return {
        "asset": {"version": "2.0", "generator": "sherpa tests/data/make_malformed.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"name": "m"}],
        "buffers": [{"uri": uri, "byteLength": len(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(indices) * 2},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [min(p[i] for p in positions) for i in range(3)],
             "max": [max(p[i] for p in positions) for i in range(3)]},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }

def write(name, doc):
    with open(name, "w") as f:
        # allow_nan: NaN/Inf are not JSON; tinygltf rejects them, so NaNs go in binary.
        json.dump(doc, f, indent=1)

cases = {}

g = triangle(); g["buffers"][0]["uri"] = "does_not_exist.bin"; cases["missing_buffer.gltf"] = g
g = triangle(); g["buffers"][0]["uri"] = "short_buffer.bin"; g["buffers"][0]["byteLength"] = 44
cases["short_buffer.gltf"] = g
with open("short_buffer.bin", "wb") as f: f.write(b"\0" * 10)
g = triangle(); g["buffers"][0]["byteLength"] = 20; cases["buffer_shorter_than_view.gltf"] = g
g = triangle(); g["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7; cases["accessor_out_of_range.gltf"] = g
g = triangle(); g["accessors"][0]["bufferView"] = 9; cases["bufferview_out_of_range.gltf"] = g
g = triangle(); g["accessors"][0]["count"] = 30; cases["accessor_past_view.gltf"] = g
g = triangle(indices=(0, 1, 5)); cases["index_beyond_vertices.gltf"] = g
g = triangle(positions=((0, 0, 0), (math.nan, 0, 0), (0, 1, 0)))
g["accessors"][0]["min"] = [0, 0, 0]; g["accessors"][0]["max"] = [1, 1, 0]; cases["nan_position.gltf"] = g
g = triangle(positions=((0, 0, 0), (1, 0, 0), (0, math.inf, 0)))
g["accessors"][0]["min"] = [0, 0, 0]; g["accessors"][0]["max"] = [1, 1, 0]; cases["inf_position.gltf"] = g
g = triangle(); g["accessors"][0]["count"] = 0; g["accessors"][1]["count"] = 0
del g["accessors"][0]["min"]; del g["accessors"][0]["max"]; cases["empty_primitive.gltf"] = g
g = triangle(); g["nodes"] = [{"mesh": 0}, {"children": [2]}, {"children": [1]}]  # 1 -> 2 -> 1
cases["node_cycle.gltf"] = g
g = triangle(); g["nodes"] = [{"mesh": 0, "children": [0]}]; cases["node_self_child.gltf"] = g
g = triangle(); g["nodes"] = [{"children": [2]}, {"children": [2]}, {"mesh": 0}]
g["scenes"] = [{"nodes": [0, 1]}]; cases["node_two_parents.gltf"] = g
g = triangle(); g["extensionsUsed"] = ["KHR_draco_mesh_compression"]
g["extensionsRequired"] = ["KHR_draco_mesh_compression"]; cases["unknown_required_extension.gltf"] = g
g = triangle(); del g["meshes"][0]["primitives"][0]["material"]; cases["no_material.gltf"] = g
g = triangle(); g["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 3}}
cases["texture_out_of_range.gltf"] = g
g = triangle(); g["bufferViews"][0]["byteStride"] = 4; cases["stride_too_small.gltf"] = g
g = triangle(); g["meshes"][0]["primitives"][0]["mode"] = 0; cases["points.gltf"] = g
g = triangle(); g["meshes"][0]["primitives"][0]["mode"] = 9; cases["bad_mode.gltf"] = g
g = triangle(positions=((0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)), indices=(0, 1, 2, 3))
g["meshes"][0]["primitives"][0]["mode"] = 5; cases["strip.gltf"] = g
g = triangle(positions=((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)), indices=(0, 1, 2, 3))
g["meshes"][0]["primitives"][0]["mode"] = 6; cases["fan.gltf"] = g
g = triangle(); g["nodes"][0]["mesh"] = 4; cases["node_mesh_out_of_range.gltf"] = g
g = triangle(); g["scene"] = 3; cases["default_scene_out_of_range.gltf"] = g
g = triangle(); g["accessors"][0]["componentType"] = 5130; cases["bad_component_type.gltf"] = g
g = triangle(); g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1; cases["normal_wrong_type.gltf"] = g

for name, doc in cases.items():
    write(name, doc)
with open("invalid_json.gltf", "w") as f: f.write('{"asset": {"version": "2.0"}, "nodes": [')
open("empty.gltf", "w").close()
with open("truncated.glb", "wb") as f:
    f.write(b"glTF" + struct.pack("<II", 2, 4096) + struct.pack("<I", 200) + b"JSON" + b'{"asset":')

# Valid files for features no sample model covers.
g = triangle()
g["nodes"] = [{"mesh": 0}, {"mesh": 0, "translation": [10, 0, 0]}]
g["scenes"] = [{"name": "first", "nodes": [0]}, {"name": "second", "nodes": [1]}]
write("two_scenes.gltf", g)
g = triangle()
g["extensionsUsed"] = ["KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_emissive_strength"]
g["extensions"] = {"KHR_lights_punctual": {"lights": [
    {"type": "directional", "color": [1, 0.9, 0.8], "intensity": 3},
    {"type": "spot", "intensity": 10, "range": 5, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}}]}}
# Rotation of -90 degrees about X: the light's -Z axis points down (-Y).
s = math.sqrt(0.5)
g["nodes"] = [{"mesh": 0, "children": [1, 2]},
              {"rotation": [-s, 0, 0, s], "extensions": {"KHR_lights_punctual": {"light": 0}}},
              {"translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 1}}}]
g["materials"][0]["emissiveFactor"] = [1, 0.5, 0]
g["materials"][0]["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}
g["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0, "extensions": {
    "KHR_texture_transform": {"offset": [0.5, 0.25], "scale": [2, 3], "rotation": 0.5, "texCoord": 1}}}}
g["textures"] = [{"source": 0}]
g["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg=="}]
write("lights_and_extensions.gltf", g)
