#!/usr/bin/env python3
"""Writes the motion test files of issue #16 into this directory (run it here).

motion_*.gltf: a skinned, morphed triangle pair and broken variants of it (import
errors and repaired, warned cases); interpolation_test.gltf: an equivalent of
Khronos' InterpolationTest (STEP/LINEAR/CUBICSPLINE on translation, rotation, scale:
nine animations on nine nodes) for the three.js oracle; sweep_*.gltf: the failure
sweep of docs/animation/failure_sweep.md. Every file is self-contained (data URIs).
"""
import base64
import copy
import json
import math
import struct


class Builder:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def add(self, fmt, values, type_, component_type=5126, normalized=False, minmax=False):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        flat = [x for v in values for x in (v if isinstance(v, (list, tuple)) else [v])]
        self.data += struct.pack("<%d%s" % (len(flat), fmt), *flat)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        acc = {"bufferView": len(self.views) - 1, "componentType": component_type,
               "count": len(values), "type": type_}
        if normalized:
            acc["normalized"] = True
        if minmax:
            n = len(values[0])
            acc["min"] = [min(v[i] for v in values) for i in range(n)]
            acc["max"] = [max(v[i] for v in values) for i in range(n)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def finish(self, doc):
        doc["asset"] = {"version": "2.0", "generator": "make_motion_cases.py"}
        doc["buffers"] = [{"byteLength": len(self.data), "uri": "data:application/octet-stream;base64,"
                           + base64.b64encode(bytes(self.data)).decode()}]
        doc["bufferViews"] = self.views
        doc["accessors"] = self.accessors
        return doc


def write(name, doc):
    with open(name, "w") as f:
        json.dump(doc, f, indent=1)


def quat_axis(axis, angle):
    s = math.sin(angle / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2)]


def rigged(times=(0.0, 1.0, 2.0), rot_keys=None, weights=None, ibm=None, joints=None,
           mesh_weights=(0.25, 0.5), node_weights=None, weight_times=None, weight_values=None,
           scale_keys=None, joint_type=5121, weight_type=5126, sparse_target=False,
           static_neighbour=False):
    """Two triangles (a strip of 4 vertices) skinned to a 2-joint chain, 2 morph targets,
    an animation rotating the second joint and driving the weights."""
    b = Builder()
    pos = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]
    p = b.add("f", pos, "VEC3", minmax=True)
    idx = b.add("H", [0, 1, 2, 2, 1, 3], "SCALAR", 5123)
    j = b.add("B" if joint_type == 5121 else "H", joints or [[0, 1, 0, 0]] * 4, "VEC4",
              joint_type)
    wv = weights or [[1, 0, 0, 0], [0.5, 0.5, 0, 0], [0.25, 0.75, 0, 0], [0, 1, 0, 0]]
    if weight_type == 5126:
        w = b.add("f", wv, "VEC4")
    else:  # normalized unsigned byte/short: sums of exactly 255 / 65535
        top = 255 if weight_type == 5121 else 65535
        q = [[round(x * top) for x in v] for v in wv]
        for v in q:
            v[v.index(max(v))] += top - sum(v)
        w = b.add("B" if weight_type == 5121 else "H", q, "VEC4", weight_type, normalized=True)
    t0 = b.add("f", [[0, 0, 0.5], [0, 0, 0], [0, 0, 0], [0, 0, 0.25]], "VEC3")
    if sparse_target:  # target 1 as a sparse accessor over zeros: vertices 1 and 2 move
        si = b.add("B", [1, 2], "SCALAR", 5121)
        sv = b.add("f", [[0, 0.2, 0], [0, 0, 0.3]], "VEC3")
        b.accessors.append({"componentType": 5126, "count": 4, "type": "VEC3",
                            "sparse": {"count": 2,
                                       "indices": {"bufferView": b.accessors[si]["bufferView"],
                                                   "componentType": 5121},
                                       "values": {"bufferView": b.accessors[sv]["bufferView"]}}})
        t1 = len(b.accessors) - 1
    else:
        t1 = b.add("f", [[0.1, 0, 0], [0, 0.2, 0], [0, 0, 0.3], [0, 0, 0]], "VEC3")
    ibm_values = ibm or [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1],
                         [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]]
    ib = b.add("f", ibm_values, "MAT4")
    tin = b.add("f", list(times), "SCALAR")
    rot = b.add("f", rot_keys or [quat_axis((0, 0, 1), a) for a in (0, 1.0, 2.0)][:len(times)],
                "VEC4")
    wt_in = b.add("f", list(weight_times or times), "SCALAR")
    wt_out = b.add("f", weight_values or [0, 0, 1, 0, 0, 1][: 2 * len(weight_times or times)],
                   "SCALAR")
    channels = [{"sampler": 0, "target": {"node": 2, "path": "rotation"}},
                {"sampler": 1, "target": {"node": 0, "path": "weights"}}]
    samplers = [{"input": tin, "output": rot}, {"input": wt_in, "output": wt_out}]
    if scale_keys:
        sc = b.add("f", scale_keys, "VEC3")
        samplers.append({"input": tin, "output": sc, "interpolation": "STEP"})
        channels.append({"sampler": 2, "target": {"node": 1, "path": "scale"}})
    mesh = {"primitives": [{"attributes": {"POSITION": p, "JOINTS_0": j, "WEIGHTS_0": w},
                            "indices": idx, "targets": [{"POSITION": t0}, {"POSITION": t1}]}]}
    if mesh_weights is not None:
        mesh["weights"] = list(mesh_weights)
    node0 = {"mesh": 0, "skin": 0}
    if node_weights is not None:
        node0["weights"] = node_weights
    meshes, nodes, roots = [mesh], [node0, {"children": [2]}, {"translation": [0, 1, 0]}], [0, 1]
    if static_neighbour:  # a still triangle at x in [3, 4] beside the skinned pair
        sp = b.add("f", [[3, 0, 0], [4, 0, 0], [3, 1, 0]], "VEC3", minmax=True)
        meshes.append({"primitives": [{"attributes": {"POSITION": sp}}]})
        nodes.append({"name": "still", "mesh": 1})
        roots.append(3)
    doc = {"scene": 0, "scenes": [{"nodes": roots}],
           "nodes": nodes,
           "meshes": meshes,
           "skins": [{"joints": [1, 2], "inverseBindMatrices": ib, "skeleton": 1}],
           "animations": [{"name": "bend", "samplers": samplers, "channels": channels}]}
    return b.finish(doc)


def interpolation_test():
    """Nine nodes, each a small box offset along x, each with one animation: STEP,
    LINEAR, CUBICSPLINE x translation, rotation, scale (like Khronos' InterpolationTest)."""
    b = Builder()
    pos = [[x, y, z] for x in (-0.1, 0.1) for y in (-0.1, 0.1) for z in (-0.1, 0.1)]
    p = b.add("f", pos, "VEC3", minmax=True)
    idx = b.add("H", [0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                      2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3], "SCALAR", 5123)
    times = [0.0, 0.4, 1.1, 1.5, 2.3]
    t_in = b.add("f", times, "SCALAR")
    values = {
        "translation": [[0, 0, 0], [0, 1.5, 0], [0.5, 0.2, -1], [0, -0.5, 0.3], [1, 1, 1]],
        "rotation": [quat_axis(ax, a) for ax, a in
                     [((0, 1, 0), 0), ((0, 1, 0), 2.5), ((1, 0, 0), 1.2),
                      ((0.6, 0.8, 0), -2.0), ((0, 0, 1), 3.0)]],
        "scale": [[1, 1, 1], [2, 0.5, 1], [0.3, 1.5, 2], [1, 1, 0.2], [0.5, 0.5, 0.5]],
    }
    nodes, anims = [], []
    for pi, path in enumerate(["translation", "rotation", "scale"]):
        for ii, interp in enumerate(["STEP", "LINEAR", "CUBICSPLINE"]):
            v = values[path]
            if interp == "CUBICSPLINE":
                out = []
                for k, val in enumerate(v):
                    n = len(val)
                    tin = [0.7 * ((k + c) % 3 - 1) for c in range(n)]
                    tout = [0.5 * ((k * 2 + c) % 3 - 1) for c in range(n)]
                    out += [tin, val, tout]
            else:
                out = v
            o = b.add("f", out, "VEC4" if path == "rotation" else "VEC3")
            node = len(nodes)
            nodes.append({"name": path + "_" + interp, "mesh": 0,
                          "translation": [3.0 * ii - 3.0, 3.0 * pi - 3.0, 0]})
            if path == "translation":
                nodes[-1].pop("translation")
                nodes[-1]["children"] = []
            anims.append({"name": path + " " + interp,
                          "samplers": [{"input": t_in, "output": o, "interpolation": interp}],
                          "channels": [{"sampler": 0, "target": {"node": node, "path": path}}]})
    doc = {"scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes,
           "meshes": [{"primitives": [{"attributes": {"POSITION": p}, "indices": idx}]}],
           "animations": anims}
    return b.finish(doc)


def main():
    write("motion_valid.gltf", rigged())
    write("interpolation_test.gltf", interpolation_test())
    write("motion_quantized.gltf", rigged(joint_type=5123, weight_type=5121))
    write("motion_quantized_u16.gltf", rigged(joint_type=5121, weight_type=5123))
    write("motion_sparse_target.gltf", rigged(sparse_target=True))
    # Import errors.
    write("motion_times_not_increasing.gltf", rigged(times=(0.0, 2.0, 1.0)))
    write("motion_nan_key.gltf",
          rigged(rot_keys=[[0, 0, 0, 1], [float("nan"), 0, 0, 1], [0, 0, 0, 1]]))
    write("motion_joint_out_of_range.gltf", rigged(joints=[[0, 1, 0, 0]] * 3 + [[0, 5, 0, 0]]))
    write("motion_output_count.gltf", rigged(rot_keys=[[0, 0, 0, 1]] * 2))
    # Repaired with a warning.
    write("motion_more_targets_than_weights.gltf", rigged(mesh_weights=(0.5,)))
    write("motion_unnormalized_weights.gltf",
          rigged(weights=[[2, 0, 0, 0], [1, 1, 0, 0], [0.5, 1.5, 0, 0], [0, 3, 0, 0]]))
    write("motion_zero_weights.gltf",
          rigged(weights=[[0, 0, 0, 0], [0.5, 0.5, 0, 0], [0.25, 0.75, 0, 0], [0, 1, 0, 0]]))
    # Failure sweep (docs/animation/failure_sweep.md).
    write("sweep_degenerate_ibm.gltf",
          rigged(ibm=[[0] * 16, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]]))
    write("sweep_scale_zero.gltf", rigged(scale_keys=[[1, 1, 1], [0, 0, 0], [1, 0, 1]]))
    write("sweep_quat_far_from_unit.gltf",
          rigged(rot_keys=[[0, 0, 0, 50], [0, 0, 0.001, 0.002], [0, 0, 0, 0]]))
    write("sweep_huge_times.gltf", rigged(times=(0.0, 1e30, 3e38)))
    # Finite but huge: posed positions leave the float range (warned, left out of the
    # posed bounds); the still triangle beside them keeps finite bounds.
    write("pose_overflow_scale.gltf",
          rigged(scale_keys=[[1, 1, 1], [3e38, 3e38, 3e38], [1, 1, 1]], static_neighbour=True))
    write("pose_overflow_ibm.gltf",
          rigged(ibm=[[3e38, 0, 0, 0, 0, 3e38, 0, 0, 0, 0, 3e38, 0, 3e38, -3e38, 3e38, 1],
                      [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]], static_neighbour=True))


if __name__ == "__main__":
    main()
