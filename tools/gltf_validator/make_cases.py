#!/usr/bin/env python3
"""Writes one small glTF per validation code Sherpa claims (plus a valid base) into
OUT_DIR: a triangle with normals, UVs, a texture, a camera, a skin and an animation,
each case breaking one thing. The Khronos validator (khronos_validate.js) is the
judge of what each file holds; the case name only says what it aims at.
Usage: make_cases.py OUT_DIR"""
import base64, copy, json, math, os, struct, sys, zlib


def png_1x1(width=1, height=1, extra=b""):
    raw = (b"\x00" + b"\xff\x00\x00\xff" * width) * height
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + (chunk(*extra) if extra else b"") + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def data_uri(mime, data):
    return "data:" + mime + ";base64," + base64.b64encode(data).decode()


class Data:
    """The base buffer's fields, so cases can rewrite values."""
    def __init__(self):
        self.pos = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
        self.nrm = [(0, 0, 1)] * 3
        self.uv = [(0, 0), (1, 0), (0, 1)]
        self.idx = [0, 1, 2]
        self.times = [0.0, 1.0]
        self.rot = [(0, 0, 0, 1), (0, 0.7071068, 0, 0.7071068)]
        self.ibm = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
        self.joints = [(0, 0, 0, 0)] * 3
        self.weights = [(1, 0, 0, 0)] * 3
        self.extra = b""  # appended after the base data (sparse cases), 4-byte aligned

    def pack(self):
        b = b"".join(struct.pack("<3f", *p) for p in self.pos)       # 0: 36
        b += b"".join(struct.pack("<3f", *n) for n in self.nrm)      # 36: 36
        b += b"".join(struct.pack("<2f", *t) for t in self.uv)       # 72: 24
        b += struct.pack("<3H", *self.idx) + b"\0\0"                 # 96: 8
        b += struct.pack("<2f", *self.times)                         # 104: 8
        b += b"".join(struct.pack("<4f", *q) for q in self.rot)      # 112: 32
        b += struct.pack("<16f", *self.ibm)                          # 144: 64
        b += b"".join(struct.pack("<4B", *j) for j in self.joints)   # 208: 12
        b += b"".join(struct.pack("<4f", *w) for w in self.weights)  # 220: 48
        return b + self.extra                                        # 268 + extra


def base():
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]},
                  {"mesh": 1, "skin": 0}, {"name": "joint", "translation": [0, 0, 0.5]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]},
                   {"primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 7, "WEIGHTS_0": 8},
                                    "indices": 3}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png_1x1()).decode()}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "skins": [{"joints": [3], "inverseBindMatrices": 6}],
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}],
                        "samplers": [{"input": 4, "output": 5}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"},
            {"bufferView": 4, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
            {"bufferView": 5, "componentType": 5126, "count": 2, "type": "VEC4"},
            {"bufferView": 6, "componentType": 5126, "count": 1, "type": "MAT4"},
            {"bufferView": 7, "componentType": 5121, "count": 3, "type": "VEC4"},
            {"bufferView": 8, "componentType": 5126, "count": 3, "type": "VEC4"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36, "target": 34962},
            {"buffer": 0, "byteOffset": 36, "byteLength": 36, "target": 34962},
            {"buffer": 0, "byteOffset": 72, "byteLength": 24, "target": 34962},
            {"buffer": 0, "byteOffset": 96, "byteLength": 6, "target": 34963},
            {"buffer": 0, "byteOffset": 104, "byteLength": 8},
            {"buffer": 0, "byteOffset": 112, "byteLength": 32},
            {"buffer": 0, "byteOffset": 144, "byteLength": 64},
            {"buffer": 0, "byteOffset": 208, "byteLength": 12, "target": 34962},
            {"buffer": 0, "byteOffset": 220, "byteLength": 48, "target": 34962},
        ],
        "buffers": [{"byteLength": 268}],
    }


def case(g, d):
    """Yields (name, gltf dict, Data) for every case."""
    def c(name, edit_json=None, edit_data=None):
        j, x = copy.deepcopy(g), copy.deepcopy(d)
        if edit_json: edit_json(j)
        if edit_data: edit_data(x)
        return name, j, x
    A = lambda j, i: j["accessors"][i]
    def setp(path, value):
        def f(j):
            o = j
            for k in path[:-1]: o = o[k]
            o[path[-1]] = value
        return f
    def delp(path):
        def f(j):
            o = j
            for k in path[:-1]: o = o[k]
            del o[path[-1]]
        return f
    yield c("valid")
    # Structure and schema
    yield c("unexpected_property", setp(["nodes", 0, "foo"], 1))
    yield c("type_mismatch", setp(["nodes", 1, "name"], 5))
    yield c("undefined_property", delp(["accessors", 0, "componentType"]))
    yield c("value_not_in_list", setp(["accessors", 1, "type"], "VEC7"))
    yield c("value_not_in_range", setp(["meshes", 0, "primitives", 0, "mode"], 9))
    yield c("invalid_index", setp(["nodes", 0, "mesh"], -1))
    yield c("empty_entity", setp(["materials", 0], {}))
    yield c("array_length", setp(["nodes", 1, "translation"], [0, 0]))
    yield c("duplicate_elements", setp(["scenes", 0, "nodes"], [0, 1, 2, 3, 3]))
    yield c("unknown_major_version", setp(["asset", "version"], "3.0"))
    yield c("unknown_minor_version", setp(["asset", "version"], "2.1"))
    yield c("min_version_greater", setp(["asset", "minVersion"], "2.1"))
    yield c("integer_as_float", setp(["accessors", 0, "count"], 3.0))
    yield c("fractional_count", setp(["accessors", 0, "count"], 2.5))
    yield c("pattern_mismatch", setp(["asset", "version"], "two"))
    yield c("non_object_extras", setp(["nodes", 0, "extras"], 5))
    # References
    yield c("unresolved_mesh", setp(["nodes", 0, "mesh"], 7))
    yield c("unresolved_accessor", setp(["meshes", 0, "primitives", 0, "attributes", "NORMAL"], 30))
    yield c("unresolved_buffer", setp(["bufferViews", 2, "buffer"], 4))
    yield c("unresolved_texture", setp(["materials", 0, "pbrMetallicRoughness", "baseColorTexture", "index"], 3))
    yield c("unresolved_scene", setp(["scene"], 2))
    yield c("unresolved_child", setp(["nodes", 1, "children"], [9]))
    yield c("unused_object", lambda j: j["accessors"].append(copy.deepcopy(j["accessors"][2])))
    # Extensions
    yield c("undeclared_extension", setp(["nodes", 0, "extensions"], {"KHR_foo": {}}))
    yield c("unsupported_extension", lambda j: (setp(["nodes", 0, "extensions"], {"EXT_foo": {}})(j),
                                                 j.__setitem__("extensionsUsed", ["EXT_foo"])))
    yield c("unused_extension_required", lambda j: (j.__setitem__("extensionsUsed", ["KHR_materials_unlit"]),
                                                     j.__setitem__("extensionsRequired", ["KHR_materials_unlit"])))
    yield c("invalid_extension_name", lambda j: j.__setitem__("extensionsUsed", ["foo"]))
    yield c("unexpected_extension_object", lambda j: (j.__setitem__("extensionsUsed", ["KHR_materials_unlit"]),
                                                      setp(["nodes", 0, "extensions"], {"KHR_materials_unlit": {}})(j)))
    # Buffers and buffer views
    yield c("buffer_view_too_long", setp(["bufferViews", 8, "byteLength"], 60))
    yield c("buffer_byte_length_mismatch", setp(["buffers", 0, "byteLength"], 300))
    yield c("stride_too_small_value", setp(["bufferViews", 0, "byteStride"], 2))
    yield c("stride_not_multiple", setp(["bufferViews", 0, "byteStride"], 13))
    yield c("stride_too_big", lambda j: (setp(["bufferViews", 7, "byteStride"], 16)(j)))
    yield c("accessor_small_stride", setp(["bufferViews", 0, "byteStride"], 8))
    yield c("index_view_stride", setp(["bufferViews", 3, "byteStride"], 4))
    yield c("target_missing", delp(["bufferViews", 0, "target"]))
    yield c("data_uri_mime", setp(["buffers", 0, "uri"], "data:text/plain;base64,AAAA"))
    # Accessors
    yield c("accessor_too_long", setp(["accessors", 2, "count"], 4))
    yield c("accessor_offset_alignment", setp(["accessors", 2, "byteOffset"], 2))
    yield c("accessor_normalized_invalid", setp(["accessors", 1, "normalized"], True))
    yield c("accessor_min_mismatch", setp(["accessors", 0, "min"], [-1, 0, 0]))
    yield c("accessor_max_mismatch", setp(["accessors", 0, "max"], [2, 1, 0]))
    yield c("accessor_out_of_min", setp(["accessors", 0, "min"], [0.5, 0, 0]))
    yield c("accessor_out_of_max", setp(["accessors", 0, "max"], [0.5, 1, 0]))
    yield c("accessor_min_max_length", setp(["accessors", 0, "min"], [0, 0]))
    yield c("accessor_invalid_float", None, lambda x: setattr(x, "pos", [(0, 0, 0), (float("nan"), 0, 0), (0, 1, 0)]))
    yield c("accessor_normal_non_unit", None, lambda x: setattr(x, "nrm", [(0, 0, 2)] * 3))
    yield c("index_oob", None, lambda x: setattr(x, "idx", [0, 1, 5]))
    yield c("index_restart", None, lambda x: setattr(x, "idx", [0, 1, 65535]))
    yield c("index_degenerate", None, lambda x: setattr(x, "idx", [0, 1, 1]))
    def sparse(name, accessor, indices, values, fmt):
        """Accessor `accessor` gets sparse overrides: ushort `indices`, `values` packed
        with struct format `fmt`, in two new views after the base data."""
        ib = struct.pack("<%dH" % len(indices), *indices)
        ib += b"\0" * (-len(ib) % 4)
        vb = b"".join(struct.pack(fmt, *x) for x in values)
        def edit_json(j):
            n = len(j["bufferViews"])
            j["bufferViews"] += [{"buffer": 0, "byteOffset": 268, "byteLength": 2 * len(indices)},
                                 {"buffer": 0, "byteOffset": 268 + len(ib), "byteLength": len(vb)}]
            j["buffers"][0]["byteLength"] = 268 + len(ib) + len(vb)
            j["accessors"][accessor]["sparse"] = {"count": len(indices),
                                                  "indices": {"bufferView": n, "componentType": 5123},
                                                  "values": {"bufferView": n + 1}}
        return c(name, edit_json, lambda x: setattr(x, "extra", ib + vb))
    yield sparse("sparse_indices_non_increasing", 1, [2, 1], [(0, 0, 1)] * 2, "<3f")
    yield sparse("sparse_index_oob", 1, [1, 3], [(0, 0, 1)] * 2, "<3f")
    yield sparse("sparse_value_non_unit", 1, [0, 2], [(0, 0, 1), (0, 0, 2)], "<3f")
    yield sparse("sparse_max_mismatch", 0, [1], [(2, 0, 0)], "<3f")
    yield sparse("sparse_valid", 0, [1], [(1, 0, 0)], "<3f")
    yield c("ibm_invalid", None, lambda x: setattr(x, "ibm", [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0]))
    yield c("sparse_count", setp(["accessors", 2, "sparse"], {"count": 5, "indices": {"bufferView": 3, "componentType": 5123}, "values": {"bufferView": 2}}))
    # Meshes
    yield c("no_position", delp(["meshes", 0, "primitives", 0, "attributes", "POSITION"]))
    yield c("position_without_bounds", lambda j: (delp(["accessors", 0, "min"])(j), delp(["accessors", 0, "max"])(j)))
    yield c("attribute_invalid_format", setp(["meshes", 0, "primitives", 0, "attributes", "NORMAL"], 2))
    yield c("invalid_attribute", setp(["meshes", 0, "primitives", 0, "attributes", "normal"], 1))
    yield c("unequal_accessor_count", setp(["accessors", 2, "count"], 2))
    yield c("indices_invalid_format", setp(["accessors", 3, "componentType"], 5122))
    # POSITION and NORMAL share view 0 without byteStride: the second in document order
    # (NORMAL; "NORMAL" < "POSITION" by name) is the one named.
    yield c("attributes_share_view", lambda j: (setp(["bufferViews", 0, "byteLength"], 72)(j),
                                                 setp(["accessors", 1, "bufferView"], 0)(j),
                                                 setp(["accessors", 1, "byteOffset"], 36)(j)))
    yield c("tangent_without_normal", lambda j: j["accessors"].append({"bufferView": 8, "componentType": 5126, "count": 3, "type": "VEC4"}) or
            setp(["meshes", 0, "primitives", 0, "attributes"], {"POSITION": 0, "TANGENT": 9, "TEXCOORD_0": 2})(j))
    yield c("incompatible_mode", lambda j: setp(["meshes", 0, "primitives", 0, "mode"], 1)(j))
    yield c("texcoord_missing", delp(["meshes", 0, "primitives", 0, "attributes", "TEXCOORD_0"]))
    yield c("joints_without_weights", delp(["meshes", 1, "primitives", 0, "attributes", "WEIGHTS_0"]))
    yield c("morph_target_no_base", setp(["meshes", 0, "primitives", 0, "targets"], [{"TANGENT": 1}]))
    yield c("morph_unequal_targets", lambda j: (setp(["meshes", 0, "primitives", 0, "targets"], [{"NORMAL": 1}])(j),
                                                 j["meshes"][0]["primitives"].append(copy.deepcopy(g["meshes"][0]["primitives"][0]))))
    yield c("mesh_weights_count", lambda j: (setp(["meshes", 0, "primitives", 0, "targets"], [{"NORMAL": 1}])(j),
                                              setp(["meshes", 0, "weights"], [0, 0])(j)))
    yield c("node_weights_count", lambda j: (setp(["meshes", 0, "primitives", 0, "targets"], [{"NORMAL": 1}])(j),
                                              setp(["nodes", 0, "weights"], [0, 0])(j)))
    yield c("weights_negative", None, lambda x: setattr(x, "weights", [(1.5, -0.5, 0, 0)] * 3))
    yield c("weights_non_normalized", None, lambda x: setattr(x, "weights", [(0.5, 0, 0, 0)] * 3))
    yield c("joints_oob", None, lambda x: setattr(x, "joints", [(4, 0, 0, 0)] * 3))
    # Nodes and scenes
    yield c("node_loop", lambda j: (setp(["nodes", 0, "children"], [3])(j), setp(["nodes", 3, "children"], [0])(j),
                                    setp(["scenes", 0, "nodes"], [1, 2])(j)))
    yield c("node_parent_override", lambda j: (setp(["nodes", 0, "children"], [3])(j), setp(["nodes", 1, "children"], [3])(j),
                                               setp(["scenes", 0, "nodes"], [0, 1, 2])(j)))
    yield c("scene_non_root", lambda j: setp(["nodes", 0, "children"], [3])(j))
    yield c("node_matrix_trs", setp(["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]) if False else
            lambda j: (setp(["nodes", 1, "matrix"], [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])(j)))
    yield c("node_matrix_default", setp(["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]))
    yield c("node_matrix_non_trs", setp(["nodes", 0, "matrix"], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0]))
    yield c("rotation_non_unit", setp(["nodes", 0, "rotation"], [0, 0, 0, 2]))
    yield c("node_empty", lambda j: (j["nodes"].append({}), j["scenes"][0]["nodes"].append(4)))
    yield c("skin_with_non_skinned_mesh", setp(["nodes", 0, "skin"], 0))
    yield c("skinned_mesh_without_skin", delp(["nodes", 2, "skin"]))
    yield c("skinned_mesh_non_root", lambda j: (setp(["nodes", 3, "children"], [2])(j), setp(["scenes", 0, "nodes"], [0, 1, 3])(j)))
    yield c("skinned_mesh_local_transform", setp(["nodes", 2, "translation"], [1, 0, 0]))
    # Skins
    yield c("ibm_count", setp(["skins", 0, "joints"], [3, 0]))
    yield c("ibm_format", setp(["skins", 0, "inverseBindMatrices"], 5))
    yield c("skin_unresolved_joint", setp(["skins", 0, "joints"], [11]))
    # Animations
    yield c("anim_input_non_increasing", None, lambda x: setattr(x, "times", [1.0, 1.0]))
    yield c("anim_input_negative", lambda j: setp(["accessors", 4, "min"], [-1])(j), lambda x: setattr(x, "times", [-1.0, 1.0]))
    yield c("anim_quaternion_non_unit", None, lambda x: setattr(x, "rot", [(0, 0, 0, 1), (0, 0, 0, 2)]))
    yield c("anim_output_count", setp(["accessors", 5, "count"], 1))
    yield c("anim_input_without_bounds", lambda j: (delp(["accessors", 4, "min"])(j), delp(["accessors", 4, "max"])(j)))
    yield c("anim_input_format", setp(["animations", 0, "samplers", 0, "input"], 5))
    yield c("anim_output_format", setp(["animations", 0, "samplers", 0, "output"], 4))
    yield c("anim_duplicate_targets", lambda j: j["animations"][0]["channels"].append(copy.deepcopy(j["animations"][0]["channels"][0])))
    yield c("anim_target_matrix", lambda j: (setp(["nodes", 0, "matrix"], [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])(j)))
    yield c("anim_weights_no_morphs", setp(["animations", 0, "channels", 0, "target", "path"], "weights"))
    yield c("anim_unresolved_sampler", setp(["animations", 0, "channels", 0, "sampler"], 3))
    yield c("anim_bad_interpolation", setp(["animations", 0, "samplers", 0, "interpolation"], "SMOOTH"))
    yield c("anim_cubic_too_few", setp(["animations", 0, "samplers", 0, "interpolation"], "CUBICSPLINE"))
    yield c("anim_target_skinned", setp(["animations", 0, "channels", 0, "target", "node"], 2))
    # Cameras
    yield c("camera_zfar", setp(["cameras", 0, "perspective", "zfar"], 0.05))
    yield c("camera_yfov_pi", setp(["cameras", 0, "perspective", "yfov"], 3.5))
    yield c("camera_ortho_zero", setp(["cameras", 0], {"type": "orthographic", "orthographic": {"xmag": 0, "ymag": 1, "znear": 0, "zfar": 10}}))
    yield c("camera_ortho_negative", setp(["cameras", 0], {"type": "orthographic", "orthographic": {"xmag": -1, "ymag": 1, "znear": 0, "zfar": 10}}))
    yield c("camera_one_of", setp(["cameras", 0, "orthographic"], {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 10}))
    yield c("camera_type_missing", delp(["cameras", 0, "perspective"]))
    # Materials, textures, images
    yield c("alpha_cutoff_mode", setp(["materials", 0, "alphaCutoff"], 0.5))
    yield c("bad_alpha_mode", setp(["materials", 0, "alphaMode"], "CLIP"))
    yield c("base_color_range", setp(["materials", 0, "pbrMetallicRoughness", "baseColorFactor"], [2, 1, 1, 1]))
    yield c("sampler_bad_filter", setp(["samplers", 0, "magFilter"], 9987))
    yield c("image_mime_missing", lambda j: (j["images"][0].pop("uri"), j["images"][0].__setitem__("bufferView", 4)))
    yield c("image_one_of", setp(["images", 0, "bufferView"], 4))
    yield c("image_bad_mime", lambda j: (j["images"][0].pop("uri"), j["images"][0].update({"bufferView": 4, "mimeType": "image/gif"})))
    # Image data: what the bytes are against what the file says, and their headers.
    def image_view(name, data, mime):
        """Image 0 as `data` in a bufferView after the base data, declared `mime`."""
        padded = data + b"\0" * (-len(data) % 4)
        def edit_json(j):
            j["bufferViews"].append({"buffer": 0, "byteOffset": 268, "byteLength": len(data)})
            j["buffers"][0]["byteLength"] = 268 + len(padded)
            j["images"][0] = {"bufferView": len(j["bufferViews"]) - 1, "mimeType": mime}
        return c(name, edit_json, lambda x: setattr(x, "extra", padded))
    yield image_view("image_unrecognized", b"not an image at all", "image/png")
    yield image_view("image_mime_mismatch", png_1x1(), "image/jpeg")
    yield image_view("image_truncated", png_1x1()[:40], "image/png")
    yield image_view("image_npot", png_1x1(3, 1), "image/png")
    yield image_view("image_features", png_1x1(extra=(b"iCCP", b"sRGB\0\0" + zlib.compress(b"\0" * 16))), "image/png")
    yield c("texture_unresolved_source", setp(["textures", 0, "source"], 4))
    yield c("unlit_extension", lambda j: (j.__setitem__("extensionsUsed", ["KHR_materials_unlit"]),
                                          setp(["materials", 0, "extensions"], {"KHR_materials_unlit": {}})(j)))
    yield c("emissive_strength_zero", lambda j: (j.__setitem__("extensionsUsed", ["KHR_materials_emissive_strength"]),
                                                 setp(["materials", 0, "extensions"], {"KHR_materials_emissive_strength": {"emissiveStrength": 2}})(j)))
    # Material extensions: values out of their ranges, and what they say about each other.
    def mext(name, exts, **material):
        def f(j):
            j["extensionsUsed"] = sorted(exts)
            j["materials"][0]["extensions"] = exts
            j["materials"][0].update(material)
        return c(name, f)
    yield mext("ext_ior_range", {"KHR_materials_ior": {"ior": 0.5}})
    yield mext("ext_ior_type", {"KHR_materials_ior": {"ior": "glass"}})
    yield mext("ext_specular_range", {"KHR_materials_specular": {"specularFactor": 2, "specularColorFactor": [-1, 1, 1]}})
    yield mext("ext_specular_texture", {"KHR_materials_specular": {"specularTexture": {"index": 4}}})
    yield mext("ext_clearcoat_range", {"KHR_materials_clearcoat": {"clearcoatFactor": 2, "clearcoatRoughnessFactor": -1}})
    yield mext("ext_clearcoat_texcoord", {"KHR_materials_clearcoat": {"clearcoatNormalTexture": {"index": 0, "texCoord": 1}}},
               normalTexture={"index": 0})
    yield mext("ext_no_tangent_space", {"KHR_materials_clearcoat": {"clearcoatNormalTexture": {"index": 0}}})
    yield mext("ext_sheen_range", {"KHR_materials_sheen": {"sheenColorFactor": [2, 0, 0], "sheenRoughnessFactor": 1.5}})
    yield mext("ext_transmission_range", {"KHR_materials_transmission": {"transmissionFactor": 1.5}})
    yield mext("ext_volume_range", {"KHR_materials_transmission": {},
               "KHR_materials_volume": {"thicknessFactor": -1, "attenuationDistance": 0, "attenuationColor": [2, 0, 0]}})
    yield mext("ext_volume_no_transmission", {"KHR_materials_volume": {"thicknessFactor": 1}}, doubleSided=True)
    yield mext("ext_iridescence_range", {"KHR_materials_iridescence": {"iridescenceFactor": 2, "iridescenceIor": 0.5,
               "iridescenceThicknessMinimum": -1, "iridescenceThicknessMaximum": -2}})
    yield mext("ext_iridescence_texture_unused", {"KHR_materials_iridescence": {
               "iridescenceThicknessTexture": {"index": 0}, "iridescenceThicknessMinimum": 200, "iridescenceThicknessMaximum": 200}})
    yield mext("ext_iridescence_without_texture", {"KHR_materials_iridescence": {"iridescenceThicknessMinimum": 50}})
    yield mext("ext_anisotropy_range", {"KHR_materials_anisotropy": {"anisotropyStrength": 2, "anisotropyRotation": 7}})
    yield mext("ext_anisotropy_texcoord", {"KHR_materials_anisotropy": {"anisotropyTexture": {"index": 0, "texCoord": 1}}},
               normalTexture={"index": 0})
    yield mext("ext_dispersion_range", {"KHR_materials_dispersion": {"dispersion": -1}})
    yield mext("ext_emissive_strength_range", {"KHR_materials_emissive_strength": {"emissiveStrength": -1}}, emissiveFactor=[1, 1, 1])
    yield mext("ext_spec_gloss_range", {"KHR_materials_pbrSpecularGlossiness": {"diffuseFactor": [2, 0, 0, 1], "glossinessFactor": -1}})
    yield mext("ext_unlit_with_others", {"KHR_materials_unlit": {}, "KHR_materials_ior": {"ior": 1.4}})
    yield mext("ext_unexpected_property", {"KHR_materials_volume": {"thickness": 1}, "KHR_materials_transmission": {}})
    # Not known to the Khronos validator (UNSUPPORTED_EXTENSION): Sherpa's SHERPA_ codes.
    yield mext("ext_diffuse_transmission_range", {"KHR_materials_diffuse_transmission": {
               "diffuseTransmissionFactor": 2, "diffuseTransmissionColorFactor": [0, -1, 0]}})
    yield c("lights_spot_angles", lambda j: (j.__setitem__("extensionsUsed", ["KHR_lights_punctual"]),
            j.__setitem__("extensions", {"KHR_lights_punctual": {"lights": [{"type": "spot", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.4}}]}}),
            setp(["nodes", 3, "extensions"], {"KHR_lights_punctual": {"light": 0}})(j)))


def write(out_dir, name, j, data):
    raw = data.pack()
    j = copy.deepcopy(j)
    if "uri" not in j["buffers"][0]:
        j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(raw).decode()
    with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
        json.dump(j, f, allow_nan=True)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, j, x in case(base(), Data()):
        write(out, name, j, x)
    # GLB cases: a valid one, and one with a data: URI buffer and trailing bytes.
    for name, extra, data_uri in (("glb_valid", b"", False), ("glb_data_uri", b"", True),
                                  ("glb_extra_data", b"\0\0\0\0", False)):
        j, d = base(), Data()
        raw = d.pack()
        if data_uri:
            j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(raw).decode()
        text = json.dumps(j).encode()
        text += b" " * (-len(text) % 4)
        chunks = struct.pack("<I4s", len(text), b"JSON") + text
        if not data_uri:
            chunks += struct.pack("<I4s", len(raw), b"BIN\0") + raw
        blob = struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks + extra
        with open(os.path.join(out, name + ".glb"), "wb") as f:
            f.write(blob)


if __name__ == "__main__":
    main()
