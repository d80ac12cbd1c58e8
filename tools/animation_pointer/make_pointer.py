#!/usr/bin/env python3
"""Writes tests/data/animation_pointer/pointer.gltf: KHR_animation_pointer channels on
material factors, a texture transform, a spot light, a camera, node visibility and a
node translation (the pointer form), with STEP, LINEAR and CUBICSPLINE samplers, plus
channels whose pointers Sherpa must refuse with a warning (an extension the material
does not use, a material that does not exist, an unsupported target, no pointer).
Self-contained (buffers as data URIs). Usage: make_pointer.py OUT_DIR"""
import base64
import json
import math
import struct
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, __file__.rsplit('/', 2)[0] + '/material_sweeps')
from make_sweeps import sphere, png_rgba  # noqa: E402


class Blob:
    def __init__(self):
        self.data = b''
        self.views, self.accessors = [], []

    def add(self, floats, kind, count, minmax=False):
        while len(self.data) % 4:
            self.data += b'\0'
        view = len(self.views)
        self.views.append({'buffer': 0, 'byteOffset': len(self.data), 'byteLength': 4 * len(floats)})
        self.data += struct.pack('<%df' % len(floats), *floats)
        acc = {'bufferView': view, 'componentType': 5126, 'count': count, 'type': kind}
        if minmax:
            acc['min'], acc['max'] = [min(floats)], [max(floats)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


KINDS = {1: 'SCALAR', 2: 'VEC2', 3: 'VEC3', 4: 'VEC4'}

# pointer, interpolation, width, key times, values (cubic: in, value, out per key)
CHANNELS = [
    ('/materials/0/pbrMetallicRoughness/baseColorFactor', 'LINEAR', 4, [0, 1, 2],
     [1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1]),
    ('/materials/1/emissiveFactor', 'CUBICSPLINE', 3, [0, 2],
     [0, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 1, 1, 1, 0, 0, 0]),
    ('/materials/1/pbrMetallicRoughness/metallicFactor', 'STEP', 1, [0, 0.5, 1.5], [0, 1, 0.25]),
    ('/materials/1/pbrMetallicRoughness/roughnessFactor', 'LINEAR', 1, [0.5, 1.5], [0.1, 0.9]),
    ('/materials/1/alphaCutoff', 'LINEAR', 1, [0, 2], [0.2, 0.8]),
    ('/materials/1/extensions/KHR_materials_emissive_strength/emissiveStrength', 'LINEAR', 1,
     [0, 2], [1, 5]),
    ('/materials/1/extensions/KHR_materials_ior/ior', 'CUBICSPLINE', 1, [0, 1, 2],
     [0, 1.0, 0.5, 0.2, 1.5, 0.3, 0, 2.0, 0]),
    ('/materials/1/emissiveTexture/extensions/KHR_texture_transform/offset', 'LINEAR', 2, [0, 2],
     [0, 0, 1, 0.5]),
    ('/materials/1/emissiveTexture/extensions/KHR_texture_transform/rotation', 'STEP', 1, [0, 1],
     [0, math.pi / 2]),
    ('/extensions/KHR_lights_punctual/lights/0/color', 'LINEAR', 3, [0, 2], [1, 1, 1, 1, 0.5, 0]),
    ('/extensions/KHR_lights_punctual/lights/0/intensity', 'CUBICSPLINE', 1, [0, 2],
     [0, 10, 4, -4, 30, 0]),
    ('/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle', 'LINEAR', 1, [0, 2],
     [0.5, 0.7]),
    ('/cameras/0/perspective/yfov', 'LINEAR', 1, [0, 2], [0.6, 1.2]),
    ('/cameras/0/perspective/znear', 'STEP', 1, [0, 1], [0.1, 0.5]),
    ('/nodes/2/extensions/KHR_node_visibility/visible', 'STEP', 1, [0, 1, 1.5], [1, 0, 1]),
    ('/nodes/1/translation', 'LINEAR', 3, [0, 2], [1.1, 0, 0, 1.1, 1, 0]),
    # Refused, each a warning naming its channel:
    ('/materials/1/extensions/KHR_materials_specular/specularFactor', 'LINEAR', 1, [0, 1], [0, 1]),
    ('/materials/7/alphaCutoff', 'LINEAR', 1, [0, 1], [0, 1]),
    ('/meshes/0/weights', 'LINEAR', 1, [0, 1], [0, 1]),
    (None, 'LINEAR', 1, [0, 1], [0, 1]),
]
VALID = 16  # the first VALID channels are animated


def main():
    count, icount, geometry = sphere()
    blob = Blob()
    blob.data = geometry
    v = count * 12
    blob.views = [
        {'buffer': 0, 'byteOffset': 0, 'byteLength': 2 * v, 'target': 34962},
        {'buffer': 0, 'byteOffset': 2 * v, 'byteLength': count * 8, 'target': 34962},
        {'buffer': 0, 'byteOffset': 2 * v + count * 8, 'byteLength': icount * 2, 'target': 34963},
    ]
    blob.accessors = [
        {'bufferView': 0, 'byteOffset': 0, 'componentType': 5126, 'count': count, 'type': 'VEC3',
         'min': [-0.4] * 3, 'max': [0.4] * 3},
        {'bufferView': 0, 'byteOffset': v, 'componentType': 5126, 'count': count, 'type': 'VEC3'},
        {'bufferView': 1, 'componentType': 5126, 'count': count, 'type': 'VEC2'},
        {'bufferView': 2, 'componentType': 5123, 'count': icount, 'type': 'SCALAR'},
    ]
    samplers, channels = [], []
    for pointer, interpolation, width, times, values in CHANNELS:
        inp = blob.add([float(t) for t in times], 'SCALAR', len(times), minmax=True)
        out = blob.add([float(x) for x in values], KINDS[width], len(values) // width)
        samplers.append({'input': inp, 'output': out, 'interpolation': interpolation})
        target = {'path': 'pointer'}
        if pointer:
            target['extensions'] = {'KHR_animation_pointer': {'pointer': pointer}}
        channels.append({'sampler': len(samplers) - 1, 'target': target})
    prim = {'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3}
    image = png_rgba(2, 2, lambda x, y: (255, 255, 255, 255) if (x + y) % 2 else (0, 0, 0, 255))
    doc = {
        'asset': {'version': '2.0', 'generator': 'Sherpa tools/animation_pointer/make_pointer.py'},
        'extensionsUsed': ['KHR_animation_pointer', 'KHR_lights_punctual', 'KHR_materials_unlit',
                           'KHR_materials_emissive_strength', 'KHR_materials_ior',
                           'KHR_texture_transform', 'KHR_node_visibility'],
        'scene': 0,
        'scenes': [{'nodes': [0, 1, 2, 3, 4]}],
        'nodes': [
            {'name': 'unlit sphere', 'mesh': 0, 'translation': [-1.1, 0, 0]},
            {'name': 'lit sphere', 'mesh': 1, 'translation': [1.1, 0, 0]},
            {'name': 'blinking sphere', 'mesh': 0, 'translation': [0, 0, 0],
             'extensions': {'KHR_node_visibility': {'visible': True}}},
            {'name': 'spot', 'translation': [0, 2, 2],
             'extensions': {'KHR_lights_punctual': {'light': 0}}},
            {'name': 'camera', 'camera': 0, 'translation': [0, 0, 5]},
        ],
        'meshes': [{'primitives': [dict(prim, material=0)]}, {'primitives': [dict(prim, material=1)]}],
        'materials': [
            {'name': 'unlit animated', 'pbrMetallicRoughness': {'baseColorFactor': [1, 0, 0, 1]},
             'extensions': {'KHR_materials_unlit': {}}},
            {'name': 'lit animated', 'alphaMode': 'MASK', 'emissiveFactor': [0, 0, 0],
             'emissiveTexture': {'index': 0, 'extensions': {'KHR_texture_transform': {}}},
             'pbrMetallicRoughness': {'baseColorFactor': [0.8, 0.8, 0.8, 0.5]},
             'extensions': {'KHR_materials_emissive_strength': {'emissiveStrength': 1},
                            'KHR_materials_ior': {'ior': 1.5}}},
        ],
        'textures': [{'source': 0}],
        'images': [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}],
        'cameras': [{'type': 'perspective', 'perspective': {'yfov': 0.6, 'znear': 0.1, 'zfar': 100}}],
        'extensions': {'KHR_lights_punctual': {'lights': [
            {'type': 'spot', 'color': [1, 1, 1], 'intensity': 10,
             'spot': {'innerConeAngle': 0.2, 'outerConeAngle': 0.5}}]}},
        'animations': [{'name': 'pointers', 'samplers': samplers, 'channels': channels}],
        'buffers': [{'byteLength': len(blob.data),
                     'uri': 'data:application/octet-stream;base64,' +
                            base64.b64encode(blob.data).decode()}],
        'bufferViews': blob.views,
        'accessors': blob.accessors,
    }
    with open(sys.argv[1] + '/pointer.gltf', 'w') as f:
        json.dump(doc, f, indent=1)
        f.write('\n')


if __name__ == '__main__':
    main()
