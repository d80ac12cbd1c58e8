#!/usr/bin/env python3
"""Writes the emitters the path tracer cannot sample as lights, used by
tests/cli/cli_emissive_warnings_test.cpp and editor/tests/rt_tests.cpp. Each is
textured_emitter.gltf (a 1 x 1 quad emitting through an 8 x 8 texture 1 above a floor)
with one change:

emitter_animated.gltf: an animation moves the emitter's node (no light list: its
triangles move).
emitter_variants.gltf: KHR_materials_variants variant 'Dark' gives the emitter a
material that does not emit (no light list: it would bias the other variant).
emitter_bad_image.gltf: the emissive image is corrupt_texture.png, a PNG signature
followed by bytes no decoder accepts (the emitter is weighted as if white).
Run from this directory:
    python3 make_emitter_warnings.py
"""
import base64, copy, json, struct

with open("textured_emitter.gltf") as f:
    BASE = json.load(f)


def write(name, doc):
    doc["asset"]["generator"] = "sherpa tests/data/make_emitter_warnings.py"
    with open(name, "w") as f:
        json.dump(doc, f)
        f.write("\n")


def animated():
    doc = copy.deepcopy(BASE)
    times = struct.pack("<2f", 0.0, 1.0)
    moves = struct.pack("<6f", 0.0, 0.0, 0.0, 0.5, 0.0, 0.0)
    blob = times + moves
    doc["buffers"].append({"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                           + base64.b64encode(blob).decode()})
    buffer = len(doc["buffers"]) - 1
    view = len(doc["bufferViews"])
    doc["bufferViews"] += [{"buffer": buffer, "byteOffset": 0, "byteLength": len(times)},
                           {"buffer": buffer, "byteOffset": len(times), "byteLength": len(moves)}]
    acc = len(doc["accessors"])
    doc["accessors"] += [{"bufferView": view, "componentType": 5126, "count": 2, "type": "SCALAR",
                          "min": [0.0], "max": [1.0]},
                         {"bufferView": view + 1, "componentType": 5126, "count": 2, "type": "VEC3"}]
    doc["animations"] = [{"name": "Slide", "samplers": [{"input": acc, "output": acc + 1}],
                          "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}]
    write("emitter_animated.gltf", doc)


def variants():
    doc = copy.deepcopy(BASE)
    dark = copy.deepcopy(doc["materials"][1])
    dark["name"] = "Dark"
    dark["emissiveFactor"] = [0, 0, 0]
    doc["materials"][1]["name"] = "Glow"
    doc["materials"].append(dark)
    doc["extensionsUsed"].append("KHR_materials_variants")
    doc["extensions"] = {"KHR_materials_variants": {"variants": [{"name": "Dark"}]}}
    doc["meshes"][1]["primitives"][0]["extensions"] = {
        "KHR_materials_variants": {"mappings": [{"material": 2, "variants": [0]}]}}
    write("emitter_variants.gltf", doc)


def bad_image():
    doc = copy.deepcopy(BASE)
    doc["images"] = [{"uri": "corrupt_texture.png"}]
    write("emitter_bad_image.gltf", doc)


animated()
variants()
bad_image()
