#!/usr/bin/env python3
"""Writes tests/data/animation_pointer/pointer.gltf: KHR_animation_pointer channels on
material factors, a texture transform, a spot light, a camera, node visibility and a
node translation (the pointer form), with STEP, LINEAR and CUBICSPLINE samplers, plus
channels whose pointers Sherpa must refuse with a warning (an extension the material
does not use, a material that does not exist, an unsupported target, no pointer).
Also writes extensions.gltf: channels on every animatable property of the ratified
material extensions (the glTF Object Model's list) and KHR_texture_transform on every
extension texture slot, plus channels to refuse (an extension the material does not
use or does not draw, a texture it does not have, a property that is not animatable).
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


EXT = '/materials/0/extensions/'
EXT_SLOTS = [
    ('KHR_materials_specular', 'specularTexture'), ('KHR_materials_specular', 'specularColorTexture'),
    ('KHR_materials_clearcoat', 'clearcoatTexture'),
    ('KHR_materials_clearcoat', 'clearcoatRoughnessTexture'),
    ('KHR_materials_clearcoat', 'clearcoatNormalTexture'),
    ('KHR_materials_sheen', 'sheenColorTexture'), ('KHR_materials_sheen', 'sheenRoughnessTexture'),
    ('KHR_materials_transmission', 'transmissionTexture'), ('KHR_materials_volume', 'thicknessTexture'),
    ('KHR_materials_diffuse_transmission', 'diffuseTransmissionTexture'),
    ('KHR_materials_diffuse_transmission', 'diffuseTransmissionColorTexture'),
    ('KHR_materials_anisotropy', 'anisotropyTexture'),
    ('KHR_materials_iridescence', 'iridescenceTexture'),
    ('KHR_materials_iridescence', 'iridescenceThicknessTexture'),
]
EXTENSION_CHANNELS = [
    (EXT + 'KHR_materials_clearcoat/clearcoatFactor', 'LINEAR', 1, [0, 2], [0, 1]),
    (EXT + 'KHR_materials_clearcoat/clearcoatRoughnessFactor', 'STEP', 1, [0, 1], [0.2, 0.6]),
    (EXT + 'KHR_materials_clearcoat/clearcoatNormalTexture/scale', 'LINEAR', 1, [0, 2], [1, 0.5]),
    (EXT + 'KHR_materials_transmission/transmissionFactor', 'LINEAR', 1, [0, 2], [0, 1]),
    (EXT + 'KHR_materials_volume/thicknessFactor', 'LINEAR', 1, [0, 2], [0, 2]),
    (EXT + 'KHR_materials_volume/attenuationDistance', 'CUBICSPLINE', 1, [0, 2],
     [0, 1, 0.5, 0, 3, 0]),
    (EXT + 'KHR_materials_volume/attenuationColor', 'LINEAR', 3, [0, 2], [1, 1, 1, 0.2, 0.5, 0.8]),
    (EXT + 'KHR_materials_sheen/sheenColorFactor', 'LINEAR', 3, [0, 2], [0, 0, 0, 1, 0.5, 0.25]),
    (EXT + 'KHR_materials_sheen/sheenRoughnessFactor', 'STEP', 1, [0, 1], [0.3, 0.7]),
    (EXT + 'KHR_materials_iridescence/iridescenceFactor', 'LINEAR', 1, [0, 2], [0, 1]),
    (EXT + 'KHR_materials_iridescence/iridescenceIor', 'LINEAR', 1, [0, 2], [1.3, 2.0]),
    (EXT + 'KHR_materials_iridescence/iridescenceThicknessMinimum', 'LINEAR', 1, [0, 2], [100, 200]),
    (EXT + 'KHR_materials_iridescence/iridescenceThicknessMaximum', 'LINEAR', 1, [0, 2], [400, 800]),
    (EXT + 'KHR_materials_anisotropy/anisotropyStrength', 'LINEAR', 1, [0, 2], [0, 1]),
    (EXT + 'KHR_materials_anisotropy/anisotropyRotation', 'LINEAR', 1, [0, 2], [0, math.pi]),
    (EXT + 'KHR_materials_dispersion/dispersion', 'LINEAR', 1, [0, 2], [0, 1]),
    (EXT + 'KHR_materials_diffuse_transmission/diffuseTransmissionFactor', 'LINEAR', 1, [0, 2],
     [0, 1]),
    (EXT + 'KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor', 'LINEAR', 3, [0, 2],
     [1, 1, 1, 0, 1, 0]),
] + [
    (EXT + ext + '/' + slot + '/extensions/KHR_texture_transform/offset', 'LINEAR', 2, [0, 2],
     [0, 0, 0.05 * (k + 1), 0.5]) for k, (ext, slot) in enumerate(EXT_SLOTS)
] + [
    (EXT + 'KHR_materials_clearcoat/clearcoatNormalTexture/extensions/KHR_texture_transform/rotation',
     'STEP', 1, [0, 1], [0, math.pi / 2]),
    (EXT + 'KHR_materials_sheen/sheenColorTexture/extensions/KHR_texture_transform/scale', 'LINEAR',
     2, [0, 2], [1, 1, 2, 4]),
    # Refused, each a warning naming its channel:
    ('/materials/1/extensions/KHR_materials_clearcoat/clearcoatFactor', 'LINEAR', 1, [0, 1], [0, 1]),
    ('/materials/2/extensions/KHR_materials_clearcoat/clearcoatFactor', 'LINEAR', 1, [0, 1], [0, 1]),
    ('/materials/1/extensions/KHR_materials_sheen/sheenColorTexture/extensions/KHR_texture_transform/'
     'offset', 'LINEAR', 2, [0, 1], [0, 0, 1, 1]),
    ('/materials/3/extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale', 'LINEAR', 1,
     [0, 1], [0, 1]),
    ('/materials/3/extensions/KHR_materials_clearcoat/clearcoatTexture/extensions/'
     'KHR_texture_transform/offset', 'LINEAR', 2, [0, 1], [0, 0, 1, 1]),
    (EXT + 'KHR_materials_clearcoat/clearcoatTexture/texCoord', 'LINEAR', 1, [0, 1], [0, 1]),
]
EXTENSION_VALID = 18 + len(EXT_SLOTS) + 2


def every_extension():
    """Material 0: every ratified extension Sherpa draws, a texture in every slot."""
    tex = lambda: {'index': 0, 'extensions': {'KHR_texture_transform': {}}}
    ext = {
        'KHR_materials_ior': {'ior': 1.5},
        'KHR_materials_specular': {'specularFactor': 1, 'specularColorFactor': [1, 1, 1]},
        'KHR_materials_clearcoat': {'clearcoatFactor': 0, 'clearcoatRoughnessFactor': 0.2},
        'KHR_materials_sheen': {'sheenColorFactor': [0, 0, 0], 'sheenRoughnessFactor': 0.3},
        'KHR_materials_transmission': {'transmissionFactor': 0},
        'KHR_materials_volume': {'thicknessFactor': 0, 'attenuationDistance': 1,
                                 'attenuationColor': [1, 1, 1]},
        'KHR_materials_iridescence': {'iridescenceFactor': 0, 'iridescenceIor': 1.3,
                                      'iridescenceThicknessMinimum': 100,
                                      'iridescenceThicknessMaximum': 400},
        'KHR_materials_anisotropy': {'anisotropyStrength': 0, 'anisotropyRotation': 0},
        'KHR_materials_dispersion': {'dispersion': 0},
        'KHR_materials_diffuse_transmission': {'diffuseTransmissionFactor': 0,
                                               'diffuseTransmissionColorFactor': [1, 1, 1]},
    }
    for name, slot in EXT_SLOTS:
        ext[name][slot] = tex()
    return ext


def write(path, doc, blob):
    doc['buffers'] = [{'byteLength': len(blob.data),
                       'uri': 'data:application/octet-stream;base64,' +
                              base64.b64encode(blob.data).decode()}]
    doc['bufferViews'] = blob.views
    doc['accessors'] = blob.accessors
    with open(path, 'w') as f:
        json.dump(doc, f, indent=1)
        f.write('\n')


def sphere_blob():
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
    return blob


def animation(blob, channel_list, extras=None):
    samplers, channels = [], []
    for pointer, interpolation, width, times, values in channel_list:
        inp = blob.add([float(t) for t in times], 'SCALAR', len(times), minmax=True)
        out = blob.add([float(x) for x in values], KINDS[width], len(values) // width)
        samplers.append({'input': inp, 'output': out, 'interpolation': interpolation})
        target = {'path': 'pointer'}
        if pointer:
            target['extensions'] = {'KHR_animation_pointer': {'pointer': pointer}}
        channels.append({'sampler': len(samplers) - 1, 'target': target})
    out = {'name': 'pointers', 'samplers': samplers, 'channels': channels}
    if extras:
        out['extras'] = extras
    return out


def write_extensions(out_dir):
    blob = sphere_blob()
    prim = {'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3}
    image = png_rgba(2, 2, lambda x, y: (255, 255, 255, 255) if (x + y) % 2 else (128, 128, 255, 255))
    used = sorted({name for name, _ in EXT_SLOTS} | {
        'KHR_animation_pointer', 'KHR_materials_ior', 'KHR_materials_dispersion',
        'KHR_materials_unlit', 'KHR_texture_transform'})
    doc = {
        'asset': {'version': '2.0', 'generator': 'Sherpa tools/animation_pointer/make_pointer.py'},
        'extensionsUsed': used,
        'scene': 0,
        'scenes': [{'nodes': [0, 1, 2, 3]}],
        'nodes': [{'name': 'every extension', 'mesh': 0, 'translation': [-1.5, 0, 0]},
                  {'name': 'plain', 'mesh': 1, 'translation': [-0.5, 0, 0]},
                  {'name': 'unlit with clearcoat', 'mesh': 2, 'translation': [0.5, 0, 0]},
                  {'name': 'clearcoat without textures', 'mesh': 3, 'translation': [1.5, 0, 0]}],
        'meshes': [{'primitives': [dict(prim, material=m)]} for m in range(4)],
        'materials': [
            # A normal map: anisotropy's tangent space comes from it (the validator's rule).
            {'name': 'every extension', 'pbrMetallicRoughness': {'metallicFactor': 0},
             'normalTexture': {'index': 0}, 'extensions': every_extension()},
            {'name': 'plain', 'pbrMetallicRoughness': {'metallicFactor': 0}},
            {'name': 'unlit with clearcoat',
             'extensions': {'KHR_materials_unlit': {},
                            'KHR_materials_clearcoat': {'clearcoatFactor': 1}}},
            {'name': 'clearcoat without textures', 'pbrMetallicRoughness': {'metallicFactor': 0},
             'extensions': {'KHR_materials_clearcoat': {'clearcoatFactor': 1}}},
        ],
        'textures': [{'source': 0}],
        'images': [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}],
        'animations': [animation(blob, EXTENSION_CHANNELS, {'valid_channels': EXTENSION_VALID})],
    }
    write(out_dir + '/extensions.gltf', doc, blob)


def main():
    write_extensions(sys.argv[1])
    blob = sphere_blob()
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
        'animations': [animation(blob, CHANNELS)],
    }
    write(sys.argv[1] + '/pointer.gltf', doc, blob)


if __name__ == '__main__':
    main()
