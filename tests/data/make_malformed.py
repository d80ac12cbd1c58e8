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
g = triangle(); g["extensionsUsed"] = ["EXT_made_up_required"]
g["extensionsRequired"] = ["EXT_made_up_required"]; cases["unknown_required_extension.gltf"] = g
# As compressors write it: the accessors have no bufferView (the data is in the
# extension's stream), which tinygltf alone reports as "accessor[1] invalid bufferView".
g = triangle(); g["extensionsUsed"] = ["EXT_made_up_compression", "KHR_texture_transform"]
g["extensionsRequired"] = ["EXT_made_up_compression"]
for a in g["accessors"]: del a["bufferView"]
g["meshes"][0]["primitives"][0]["extensions"] = {"EXT_made_up_compression": {"bufferView": 0}}
cases["unknown_required_extension_no_views.gltf"] = g
# Used but not required: the file opens; info --json reports it unsupported.
g = triangle(); g["extensionsUsed"] = ["EXT_made_up_extras", "KHR_texture_transform"]
g["extensionsRequired"] = ["KHR_texture_transform"]
cases["unsupported_used_extension.gltf"] = g
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

# --- issue #12: hostile input (see docs/robustness.md) ------------------------------
def with_blob(doc, blob):
    doc["buffers"][0] = {"uri": "data:application/octet-stream;base64," +
                         base64.b64encode(blob).decode(), "byteLength": len(blob)}
    return doc

g = triangle(); g["bufferViews"][0]["byteOffset"] = 2**64 - 16; cases["view_offset_wraps.gltf"] = g
g = triangle(); g["accessors"][0]["byteOffset"] = -12; cases["negative_byte_offset.gltf"] = g
g = triangle(); g["accessors"][0]["byteOffset"] = "12"; cases["string_byte_offset.gltf"] = g
g = triangle(); g["bufferViews"][0]["byteLength"] = 36.5; cases["fractional_byte_length.gltf"] = g
for name, uri in [("dot", "."), ("parent", "%2e%2e/"), ("root", "/"), ("nul", "a%00"),
                  ("bad_escape", "%zz%")]:
    g = triangle(); g["buffers"][0]["uri"] = uri; cases["buffer_uri_" + name + ".gltf"] = g
g = triangle(); g["textures"] = [{"source": 0}]; g["images"] = [{"uri": "."}]
g["materials"][0]["pbrMetallicRoughness"] = {"baseColorTexture": {"index": 0}}
cases["image_uri_directory.gltf"] = g
# 67M positions backed by 36 bytes: refused before anything is allocated for them.
g = triangle(); g["accessors"][0]["count"] = 67_000_000; cases["huge_count.gltf"] = g
g = triangle(); del g["accessors"][0]["bufferView"]; g["accessors"][0]["count"] = 60_000_000
g["meshes"][0]["primitives"][0].pop("indices"); cases["zero_fill_count.gltf"] = g
g = triangle(); g["asset"]["minVersion"] = "2.1"; cases["min_version_2_1.gltf"] = g
g = triangle(); g["asset"]["version"] = "3.0"; cases["version_3.gltf"] = g
g = triangle(); g["nodes"][0]["scale"] = [1e38, 1e38, 1e38]
g = with_blob(g, buffer_bytes([(0, 0, 0), (10, 0, 0), (0, 10, 0)], (0, 1, 2))[0] +
              buffer_bytes([], (0, 1, 2))[1])
g["accessors"][0]["max"] = [10, 10, 0]; cases["world_bounds_overflow.gltf"] = g

# Index accessors (uint32) whose element 2 a sparse substitution sets to `value`.
for name, value in [("sparse_index_max.gltf", 0xFFFFFFFF), ("sparse_index_2p24.gltf", 2**24 + 1)]:
    g = triangle(); pos, _ = buffer_bytes([(0, 0, 0), (1, 0, 0), (0, 1, 0)], ())
    idx = struct.pack("<3I", 0, 1, 2); sp = struct.pack("<I", 2) + struct.pack("<I", value)
    g = with_blob(g, pos + idx + sp)
    g["bufferViews"] = [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": 12},
                        {"buffer": 0, "byteOffset": len(pos) + 12, "byteLength": 4},
                        {"buffer": 0, "byteOffset": len(pos) + 16, "byteLength": 4}]
    g["accessors"][1] = {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR",
                         "sparse": {"count": 1, "indices": {"bufferView": 2, "componentType": 5125},
                                    "values": {"bufferView": 3}}}
    cases[name] = g
g = copy.deepcopy(cases["sparse_index_max.gltf"])
g["accessors"][1]["componentType"] = 5123; g["accessors"][1]["normalized"] = True
g["bufferViews"][1]["byteLength"] = 6; cases["sparse_indices_normalized.gltf"] = g
# Data leaving the declared min/max: a flipped byte in a .bin looks like this.
g = triangle(positions=((0, 0, 0), (1, 0, 0), (0, 1, 1.7e38)))
g["accessors"][0]["max"] = [1, 1, 0.5]; cases["position_outside_minmax.gltf"] = g

# Odd objects in otherwise valid files: skipped with a warning, the file kept.
def with_camera(cam):
    g = triangle(); g["cameras"] = [cam]; g["nodes"].append({"camera": 0, "translation": [0, 0, 3]})
    g["scenes"][0]["nodes"] = [0, 1]; return g
cases["camera_zfar_below_znear.gltf"] = with_camera(
    {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 10, "zfar": 1}})
cases["camera_negative_xmag.gltf"] = with_camera(
    {"type": "orthographic", "orthographic": {"xmag": -1, "ymag": 1, "znear": 0, "zfar": 10}})
cases["camera_yfov_pi.gltf"] = with_camera(
    {"type": "perspective", "perspective": {"yfov": 3.2, "znear": 0.1}})
def with_light(light):
    g = triangle(); g["extensionsUsed"] = ["KHR_lights_punctual"]
    g["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
    g["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
    g["scenes"][0]["nodes"] = [0, 1]; return g
cases["light_negative_intensity.gltf"] = with_light({"type": "point", "intensity": -5})
cases["light_cone_inverted.gltf"] = with_light(
    {"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.5}})
cases["light_unknown_type.gltf"] = with_light({"type": "area"})
g = triangle(); g["materials"][0]["normalTexture"] = {"index": 0, "scale": 1e30}
g["textures"] = [{"source": 0}]
g["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg=="}]
cases["normal_scale_huge.gltf"] = g
g = triangle(); pos, idx = buffer_bytes([(0, 0, 0), (1, 0, 0), (0, 1, 0)], (0, 1, 2))
nrm = struct.pack("<3f", math.nan, 0, 1) + struct.pack("<3f", 0, 0, 0) + struct.pack("<3f", 0, 0, 1)
g = with_blob(g, pos + idx + nrm)
g["bufferViews"].append({"buffer": 0, "byteOffset": len(pos) + len(idx), "byteLength": 36})
g["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3"})
g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2; cases["nan_normals.gltf"] = g
g = triangle(); g["scenes"][0]["nodes"] = [0, 0, 0]; cases["duplicate_scene_roots.gltf"] = g

for name, doc in cases.items():
    write(name, doc)
# ~20,000 levels of nesting in extras (40 KB): tinygltf's recursive parser overflowed
# the stack on this. Also as the JSON chunk of a .glb.
deep = json.dumps(triangle())[:-1] + ', "extras": ' + "[" * 20000 + "]" * 20000 + "}"
with open("deep_nesting.gltf", "w") as f: f.write(deep)
def glb(json_text, bin_chunk=b""):
    j = json_text.encode(); j += b" " * ((4 - len(j) % 4) % 4)
    chunks = struct.pack("<I", len(j)) + b"JSON" + j
    if bin_chunk:
        bin_chunk += b"\0" * ((4 - len(bin_chunk) % 4) % 4)
        chunks += struct.pack("<I", len(bin_chunk)) + b"BIN\0" + bin_chunk
    return b"glTF" + struct.pack("<II", 2, 12 + len(chunks)) + chunks
with open("deep_nesting.glb", "wb") as f: f.write(glb(deep))
# An image bufferView 4 KB long in a 68-byte BIN chunk: once copied past the end.
g = triangle(); pos, idx = buffer_bytes([(0, 0, 0), (1, 0, 0), (0, 1, 0)], (0, 1, 2))
g["buffers"] = [{"byteLength": len(pos) + len(idx) + 24}]
g["bufferViews"].append({"buffer": 0, "byteOffset": len(pos) + len(idx), "byteLength": 4096})
g["images"] = [{"bufferView": 2, "mimeType": "image/png"}]; g["textures"] = [{"source": 0}]
with open("image_view_past_buffer.glb", "wb") as f:
    f.write(glb(json.dumps(g), pos + idx + b"\x89PNG" + b"\0" * 20))
# A valid .glb whose image lives in the BIN chunk (bytes taken, range-checked, by Sherpa).
png = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg==")
g["buffers"] = [{"byteLength": len(pos) + len(idx) + len(png)}]
g["bufferViews"][2]["byteLength"] = len(png)
with open("image_in_glb.glb", "wb") as f: f.write(glb(json.dumps(g), pos + idx + png))
# A PNG renamed .gltf: the JSON library's exception once reached the user raw.
with open("png_renamed.gltf", "wb") as f:
    f.write(base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGP4z8DwHwAFAAH/iZk9HQAAAABJRU5ErkJggg=="))
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
