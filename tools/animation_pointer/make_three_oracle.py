#!/usr/bin/env python3
"""Writes tests/data/animation_pointer/three_oracle.gltf: a KHR_animation_pointer channel
on every kind of property the three.js oracle (tools/motion/three_pointer_oracle.mjs)
is asked about -- the core material factors and texture transforms, every ratified
material extension's factors, a spot and a point light, a perspective and two
orthographic cameras and a node's visibility -- spread over STEP, LINEAR and CUBICSPLINE
samplers, with keys that start after 0 s or end before 2 s on some channels so that
times before the first and after the last key differ from the clip's ends. Every
channel is valid: Sherpa animates them all; the oracle says which ones three.js cannot.
Visibility is a bool, so its keys are unsigned bytes (KHR_animation_pointer requires it).
Self-contained (buffers as data URIs). Usage: make_three_oracle.py OUT_DIR"""
import base64
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, __file__.rsplit('/', 1)[0])
from make_pointer import KINDS, animation, png_rgba, sphere_blob, write  # noqa: E402

M0, M1 = '/materials/0/', '/materials/1/extensions/'
LIGHTS = '/extensions/KHR_lights_punctual/lights/'
TT = '/extensions/KHR_texture_transform/'
# pointer, interpolation, width, key times, values (cubic: in, value, out per key)
CHANNELS = [
    (M0 + 'pbrMetallicRoughness/baseColorFactor', 'CUBICSPLINE', 4, [0, 2],
     [0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, -0.5, -1, 1, 0, 0, 0, 1, 1, 0.5, 0, 0, 0, 0]),
    (M0 + 'pbrMetallicRoughness/metallicFactor', 'STEP', 1, [0, 0.5, 1.5], [0, 1, 0.25]),
    (M0 + 'pbrMetallicRoughness/roughnessFactor', 'LINEAR', 1, [0.5, 1.5], [0.1, 0.9]),
    (M0 + 'emissiveFactor', 'LINEAR', 3, [0, 1, 2], [0, 0, 0, 1, 0.5, 0, 0, 1, 1]),
    (M0 + 'alphaCutoff', 'CUBICSPLINE', 1, [0, 1, 2], [0, 0.2, 0.3, -0.2, 0.6, 0.1, 0, 0.8, 0]),
    (M0 + 'normalTexture/scale', 'LINEAR', 1, [0, 2], [1, 0.25]),
    (M0 + 'occlusionTexture/strength', 'STEP', 1, [0, 1], [1, 0.4]),
    (M0 + 'pbrMetallicRoughness/baseColorTexture' + TT + 'offset', 'LINEAR', 2, [0, 2],
     [0, 0, 0.5, -0.25]),
    (M0 + 'pbrMetallicRoughness/baseColorTexture' + TT + 'scale', 'CUBICSPLINE', 2, [0, 2],
     [0, 0, 1, 1, 1, 0, 0, 0, 2, 3, 0, 0]),
    (M0 + 'pbrMetallicRoughness/baseColorTexture' + TT + 'rotation', 'LINEAR', 1, [0, 2], [0, 1]),
    (M0 + 'emissiveTexture' + TT + 'offset', 'STEP', 2, [0, 1], [0, 0, 0.25, 0.75]),
    (M0 + 'emissiveTexture' + TT + 'scale', 'LINEAR', 2, [0.5, 1.5], [1, 1, 0.5, 2]),
    (M0 + 'extensions/KHR_materials_emissive_strength/emissiveStrength', 'CUBICSPLINE', 1,
     [0, 2], [0, 1, 3, 0, 5, 0]),
    (M1 + 'KHR_materials_clearcoat/clearcoatFactor', 'CUBICSPLINE', 1, [0, 2], [0, 0, 1, -1, 1, 0]),
    (M1 + 'KHR_materials_clearcoat/clearcoatRoughnessFactor', 'STEP', 1, [0, 1], [0.2, 0.6]),
    (M1 + 'KHR_materials_clearcoat/clearcoatNormalTexture/scale', 'LINEAR', 1, [0, 2], [1, 0.5]),
    (M1 + 'KHR_materials_transmission/transmissionFactor', 'LINEAR', 1, [0.5, 1.5], [0, 1]),
    (M1 + 'KHR_materials_ior/ior', 'STEP', 1, [0, 1], [1.5, 1.8]),
    (M1 + 'KHR_materials_volume/thicknessFactor', 'CUBICSPLINE', 1, [0, 2], [0, 0, 2, 0, 2, 0]),
    (M1 + 'KHR_materials_volume/attenuationDistance', 'LINEAR', 1, [0, 2], [1, 3]),
    (M1 + 'KHR_materials_volume/attenuationColor', 'STEP', 3, [0, 1], [1, 1, 1, 0.2, 0.5, 0.8]),
    (M1 + 'KHR_materials_sheen/sheenColorFactor', 'CUBICSPLINE', 3, [0, 2],
     [0, 0, 0, 0, 0, 0, 1, 1, 1, -1, 0, 0, 1, 0.5, 0.25, 0, 0, 0]),
    (M1 + 'KHR_materials_sheen/sheenRoughnessFactor', 'LINEAR', 1, [0, 2], [0.3, 0.7]),
    (M1 + 'KHR_materials_iridescence/iridescenceFactor', 'CUBICSPLINE', 1, [0, 2],
     [0, 0, 0.5, 0.5, 1, 0]),
    (M1 + 'KHR_materials_iridescence/iridescenceIor', 'STEP', 1, [0, 0.5], [1.3, 2.0]),
    (M1 + 'KHR_materials_iridescence/iridescenceThicknessMinimum', 'LINEAR', 1, [0, 2], [100, 200]),
    (M1 + 'KHR_materials_iridescence/iridescenceThicknessMaximum', 'CUBICSPLINE', 1, [0, 2],
     [0, 400, 100, 0, 800, 0]),
    (M1 + 'KHR_materials_specular/specularFactor', 'LINEAR', 1, [0, 1], [1, 0.5]),
    (M1 + 'KHR_materials_specular/specularColorFactor', 'CUBICSPLINE', 3, [0, 2],
     [0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0.5, 1, 0.25, 0, 0, 0]),
    (M1 + 'KHR_materials_anisotropy/anisotropyStrength', 'LINEAR', 1, [0, 2], [0, 1]),
    (M1 + 'KHR_materials_anisotropy/anisotropyRotation', 'CUBICSPLINE', 1, [0, 2],
     [0, 0, 1, 0, 3, 0]),
    (M1 + 'KHR_materials_dispersion/dispersion', 'STEP', 1, [0, 1.5], [0, 1]),
    (M1 + 'KHR_materials_diffuse_transmission/diffuseTransmissionFactor', 'LINEAR', 1, [0, 2],
     [0, 1]),
    (LIGHTS + '0/color', 'STEP', 3, [0, 1], [1, 1, 1, 1, 0.5, 0]),
    (LIGHTS + '0/intensity', 'LINEAR', 1, [0, 2], [10, 30]),
    (LIGHTS + '0/range', 'CUBICSPLINE', 1, [0, 2], [0, 5, 2, 0, 9, 0]),
    (LIGHTS + '0/spot/innerConeAngle', 'LINEAR', 1, [0, 2], [0.1, 0.3]),
    (LIGHTS + '0/spot/outerConeAngle', 'CUBICSPLINE', 1, [0, 2], [0, 0.5, 0.1, 0, 0.7, 0]),
    (LIGHTS + '1/color', 'CUBICSPLINE', 3, [0, 2],
     [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0]),
    (LIGHTS + '1/intensity', 'STEP', 1, [0, 0.5, 1.5], [5, 1, 8]),
    (LIGHTS + '1/range', 'LINEAR', 1, [0.5, 1.5], [4, 2]),
    ('/cameras/0/perspective/yfov', 'CUBICSPLINE', 1, [0, 2], [0, 0.6, 0.2, 0, 1.2, 0]),
    ('/cameras/0/perspective/znear', 'STEP', 1, [0, 1], [0.1, 0.5]),
    ('/cameras/0/perspective/zfar', 'LINEAR', 1, [0, 2], [100, 50]),
    ('/cameras/0/perspective/aspectRatio', 'LINEAR', 1, [0, 2], [1.5, 2]),
    ('/cameras/1/orthographic/xmag', 'LINEAR', 1, [0, 2], [1, 3]),
    ('/cameras/1/orthographic/znear', 'CUBICSPLINE', 1, [0, 2], [0, 0.1, 0.2, 0, 0.4, 0]),
    ('/cameras/1/orthographic/zfar', 'STEP', 1, [0, 1], [20, 40]),
    ('/cameras/2/orthographic/ymag', 'CUBICSPLINE', 1, [0, 2], [0, 1, 0.5, 0, 2, 0]),
]
VISIBILITY = ('/nodes/2/extensions/KHR_node_visibility/visible', [0, 1, 1.5], [1, 0, 1])


def materials():
    tex = lambda index, **extra: dict({'index': index, 'extensions': {
        'KHR_texture_transform': {'offset': [0, 0]}}}, **extra)
    every = {
        'KHR_materials_clearcoat': {'clearcoatFactor': 0, 'clearcoatRoughnessFactor': 0.2,
                                    'clearcoatNormalTexture': tex(2, scale=1)},
        'KHR_materials_transmission': {'transmissionFactor': 0},
        'KHR_materials_ior': {'ior': 1.5},
        'KHR_materials_volume': {'thicknessFactor': 0, 'attenuationDistance': 1,
                                 'attenuationColor': [1, 1, 1]},
        'KHR_materials_sheen': {'sheenColorFactor': [0, 0, 0], 'sheenRoughnessFactor': 0.3},
        'KHR_materials_iridescence': {'iridescenceFactor': 0, 'iridescenceIor': 1.3,
                                      'iridescenceThicknessMinimum': 100,
                                      'iridescenceThicknessMaximum': 400},
        'KHR_materials_specular': {'specularFactor': 1, 'specularColorFactor': [1, 1, 1]},
        'KHR_materials_anisotropy': {'anisotropyStrength': 0, 'anisotropyRotation': 0},
        'KHR_materials_dispersion': {'dispersion': 0},
        'KHR_materials_diffuse_transmission': {'diffuseTransmissionFactor': 0},
    }
    # Separate textures per slot: three.js shares one texture object between slots
    # that name the same texture, and each slot's transform is animated on its own.
    core = {'name': 'core', 'alphaMode': 'MASK', 'emissiveFactor': [0, 0, 0],
            'pbrMetallicRoughness': {'baseColorFactor': [1, 0, 0, 1], 'baseColorTexture': tex(0)},
            'emissiveTexture': tex(1), 'normalTexture': tex(2, scale=1),
            'occlusionTexture': tex(3, strength=1),
            'extensions': {'KHR_materials_emissive_strength': {'emissiveStrength': 1}}}
    return [core, {'name': 'every extension', 'pbrMetallicRoughness': {'metallicFactor': 0},
                   'normalTexture': tex(2), 'extensions': every}]


def main():
    blob = sphere_blob()
    anim = animation(blob, CHANNELS)
    pointer, times, values = VISIBILITY
    inp = blob.add([float(t) for t in times], 'SCALAR', len(times), minmax=True)
    while len(blob.data) % 4:
        blob.data += b'\0'
    blob.views.append({'buffer': 0, 'byteOffset': len(blob.data), 'byteLength': len(values)})
    blob.data += bytes(values)
    blob.accessors.append({'bufferView': len(blob.views) - 1, 'componentType': 5121,
                           'count': len(values), 'type': KINDS[1]})
    anim['samplers'].append({'input': inp, 'output': len(blob.accessors) - 1,
                             'interpolation': 'STEP'})
    anim['channels'].append({'sampler': len(anim['samplers']) - 1, 'target': {
        'path': 'pointer', 'extensions': {'KHR_animation_pointer': {'pointer': pointer}}}})
    prim = {'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3}
    image = png_rgba(2, 2, lambda x, y: (255, 255, 255, 255) if (x + y) % 2 else (128, 128, 255, 255))
    extensions = sorted({p.split('/')[4] for p, *_ in CHANNELS if '/extensions/KHR_materials' in p}
                        | {'KHR_animation_pointer', 'KHR_lights_punctual', 'KHR_node_visibility',
                           'KHR_texture_transform'})
    doc = {
        'asset': {'version': '2.0',
                  'generator': 'Sherpa tools/animation_pointer/make_three_oracle.py'},
        'extensionsUsed': extensions,
        'scene': 0,
        'scenes': [{'nodes': list(range(8))}],
        'nodes': [
            {'name': 'core sphere', 'mesh': 0, 'translation': [-1, 0, 0]},
            {'name': 'extensions sphere', 'mesh': 1, 'translation': [1, 0, 0]},
            {'name': 'blinking sphere', 'mesh': 0, 'translation': [0, 1, 0],
             'extensions': {'KHR_node_visibility': {'visible': True}}},
            {'name': 'spot', 'translation': [0, 2, 2],
             'extensions': {'KHR_lights_punctual': {'light': 0}}},
            {'name': 'point', 'translation': [2, 2, 0],
             'extensions': {'KHR_lights_punctual': {'light': 1}}},
            {'name': 'perspective camera', 'camera': 0, 'translation': [0, 0, 5]},
            {'name': 'orthographic camera', 'camera': 1, 'translation': [0, 0, 6]},
            {'name': 'second orthographic camera', 'camera': 2, 'translation': [0, 0, 7]},
        ],
        'meshes': [{'primitives': [dict(prim, material=m)]} for m in range(2)],
        'materials': materials(),
        'textures': [{'source': 0} for _ in range(4)],
        'images': [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}],
        'cameras': [
            {'type': 'perspective',
             'perspective': {'yfov': 0.6, 'znear': 0.1, 'zfar': 100, 'aspectRatio': 1.5}},
            {'type': 'orthographic', 'orthographic': {'xmag': 1, 'ymag': 1, 'znear': 0.1, 'zfar': 20}},
            {'type': 'orthographic', 'orthographic': {'xmag': 1, 'ymag': 1, 'znear': 0.1, 'zfar': 20}},
        ],
        'extensions': {'KHR_lights_punctual': {'lights': [
            {'type': 'spot', 'color': [1, 1, 1], 'intensity': 10, 'range': 5,
             'spot': {'innerConeAngle': 0.1, 'outerConeAngle': 0.5}},
            {'type': 'point', 'color': [1, 0, 0], 'intensity': 5, 'range': 4}]}},
        'animations': [anim],
    }
    write(sys.argv[1] + '/three_oracle.gltf', doc, blob)


if __name__ == '__main__':
    main()
