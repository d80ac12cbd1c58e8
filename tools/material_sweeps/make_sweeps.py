#!/usr/bin/env python3
"""Writes the material extension sweep files (tests/data/material_sweeps/*.gltf): rows
of spheres that each sweep one parameter of one extension, like the Khronos Compare*
sample assets, self-contained (buffers as data URIs). The render oracle test draws them
in Sherpa and in three.js. Usage: make_sweeps.py OUT_DIR"""
import base64
import json
import math
import struct
import sys

RINGS, SEGMENTS, RADIUS = 24, 48, 0.4


def sphere():
    """A UV sphere: positions, normals, texcoords and 16-bit indices, packed."""
    pos, nrm, uv, idx = [], [], [], []
    for r in range(RINGS + 1):
        theta = math.pi * r / RINGS
        for s in range(SEGMENTS + 1):
            phi = 2 * math.pi * s / SEGMENTS
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            nrm.append(n)
            pos.append(tuple(RADIUS * c for c in n))
            uv.append((s / SEGMENTS, r / RINGS))
    for r in range(RINGS):
        for s in range(SEGMENTS):
            a = r * (SEGMENTS + 1) + s
            b = a + SEGMENTS + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    blob = b''.join(struct.pack('<3f', *p) for p in pos)
    blob += b''.join(struct.pack('<3f', *n) for n in nrm)
    blob += b''.join(struct.pack('<2f', *t) for t in uv)
    blob += struct.pack('<%dH' % len(idx), *idx)
    return len(pos), len(idx), blob


def document(name, rows, extensions):
    """rows: lists of (material name, material JSON), one sphere each, 1 apart."""
    count, icount, blob = sphere()
    v = count * 12
    doc = {
        'asset': {'version': '2.0', 'generator': 'Sherpa tools/material_sweeps/make_sweeps.py'},
        'extensionsUsed': extensions,
        'scene': 0,
        'scenes': [{'name': name, 'nodes': []}],
        'nodes': [], 'meshes': [], 'materials': [],
        'buffers': [{'byteLength': len(blob),
                     'uri': 'data:application/octet-stream;base64,' + base64.b64encode(blob).decode()}],
        'bufferViews': [
            {'buffer': 0, 'byteOffset': 0, 'byteLength': 2 * v, 'target': 34962},
            {'buffer': 0, 'byteOffset': 2 * v, 'byteLength': count * 8, 'target': 34962},
            {'buffer': 0, 'byteOffset': 2 * v + count * 8, 'byteLength': icount * 2, 'target': 34963},
        ],
        'accessors': [
            {'bufferView': 0, 'byteOffset': 0, 'componentType': 5126, 'count': count, 'type': 'VEC3',
             'min': [-RADIUS] * 3, 'max': [RADIUS] * 3},
            {'bufferView': 0, 'byteOffset': v, 'componentType': 5126, 'count': count, 'type': 'VEC3'},
            {'bufferView': 1, 'componentType': 5126, 'count': count, 'type': 'VEC2'},
            {'bufferView': 2, 'componentType': 5123, 'count': icount, 'type': 'SCALAR'},
        ],
    }
    for r, row in enumerate(rows):
        for c, (label, material) in enumerate(row):
            m = len(doc['materials'])
            doc['materials'].append(dict(name=label, **material))
            doc['meshes'].append({'name': label, 'primitives': [
                {'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3,
                 'material': m}]})
            doc['scenes'][0]['nodes'].append(len(doc['nodes']))
            doc['nodes'].append({'name': label, 'mesh': m,
                                 'translation': [c - (len(row) - 1) / 2, (len(rows) - 1) / 2 - r, 0]})
    return doc


def pbr(color, roughness, metallic=0.0):
    return {'baseColorFactor': color + [1.0], 'roughnessFactor': roughness, 'metallicFactor': metallic}


# Base colours are black: the spheres show the specular reflection alone, the part these
# extensions change (the two renderers' diffuse differs by design in its irradiance,
# docs/environment.md, and would hide it).
BLACK = [0.0, 0.0, 0.0]


def ior_sweep():
    iors = [1.0, 1.2, 1.5, 1.8, 2.33]
    rows = []
    for roughness in (0.15, 0.5):
        rows.append([(f'ior {i} roughness {roughness}',
                      {'pbrMetallicRoughness': pbr(BLACK, roughness),
                       'extensions': {'KHR_materials_ior': {'ior': i}}}) for i in iors])
    return document('KHR_materials_ior sweep', rows, ['KHR_materials_ior'])


def specular_sweep():
    weights = [0.0, 0.25, 0.5, 0.75, 1.0]
    row1 = [(f'specular {w}', {'pbrMetallicRoughness': pbr(BLACK, 0.2),
                               'extensions': {'KHR_materials_specular': {'specularFactor': w}}})
            for w in weights]
    # F0 = min(0.04 x colour, 1): 0, 0.1, 0.2, 0.4 and 1 in red.
    reds = [0.0, 2.5, 5.0, 10.0, 25.0]
    row2 = [(f'specular colour {r} 0 0',
             {'pbrMetallicRoughness': pbr(BLACK, 0.2),
              'extensions': {'KHR_materials_specular': {'specularColorFactor': [r, 0.0, 0.0]}}})
            for r in reds]
    return document('KHR_materials_specular sweep', [row1, row2], ['KHR_materials_specular'])


def png_rgba(width, height, pixel):
    """A small RGBA8 PNG; pixel(x, y) -> (r, g, b, a)."""
    import zlib
    rows = b''.join(b'\0' + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 6, 0, 0, 0))
            + chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))


def specular_textures():
    """One row: specularColorTexture (left half red, right half green, sRGB) and
    specularTexture (alpha 0 in the left half, 1 in the right) through
    KHR_texture_transform (offset 0.5 in u: the halves swap), nearest filtering."""
    image = png_rgba(2, 1, lambda x, y: (255, 0, 0, 0) if x == 0 else (0, 255, 0, 255))
    transform = {'KHR_texture_transform': {'offset': [0.5, 0.0]}}
    row = [('textured specular', {
        'pbrMetallicRoughness': pbr(BLACK, 0.2),
        'extensions': {'KHR_materials_specular': {
            'specularTexture': {'index': 0, 'extensions': transform},
            'specularColorTexture': {'index': 0, 'extensions': transform}}}})]
    doc = document('KHR_materials_specular textures', [row],
                   ['KHR_materials_specular', 'KHR_texture_transform'])
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}]
    return doc


# The coated spheres' base: black and rough, so the coat's sharp reflection stands out
# from the base's blurred one.
COATED_BASE = 0.6


def clearcoat_sweep():
    """Row 1: clearcoatFactor 0 .. 1 (smooth coat); row 2: a full coat's
    clearcoatRoughnessFactor 0 .. 1."""
    steps = [0.0, 0.25, 0.5, 0.75, 1.0]
    row1 = [(f'clearcoat {f}', {'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
                                'extensions': {'KHR_materials_clearcoat': {'clearcoatFactor': f}}})
            for f in steps]
    row2 = [(f'clearcoat roughness {r}',
             {'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
              'extensions': {'KHR_materials_clearcoat': {'clearcoatFactor': 1.0,
                                                         'clearcoatRoughnessFactor': r}}})
            for r in steps]
    return document('KHR_materials_clearcoat sweep', [row1, row2], ['KHR_materials_clearcoat'])


def clearcoat_textures():
    """One sphere: clearcoatTexture (R) and clearcoatRoughnessTexture (G) read one 2x1
    image (left texel R 1 G 0, right R 0 G 1) through KHR_texture_transform (offset 0.5
    in u: the sphere's front, u = 0.75, reads the left texel), and a 1x1
    clearcoatNormalTexture that tilts the coat's normal onto the tangent."""
    factors = png_rgba(2, 1, lambda x, y: (255, 0, 0, 255) if x == 0 else (0, 255, 0, 255))
    normal = png_rgba(1, 1, lambda x, y: (255, 128, 128, 255))
    transform = {'KHR_texture_transform': {'offset': [0.5, 0.0]}}
    row = [('textured clearcoat', {
        'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
        'extensions': {'KHR_materials_clearcoat': {
            'clearcoatFactor': 1.0, 'clearcoatRoughnessFactor': 1.0,
            'clearcoatTexture': {'index': 0, 'texCoord': 0, 'extensions': transform},
            'clearcoatRoughnessTexture': {'index': 0, 'extensions': transform},
            'clearcoatNormalTexture': {'index': 1, 'scale': 1.0}}}})]
    doc = document('KHR_materials_clearcoat textures', [row],
                   ['KHR_materials_clearcoat', 'KHR_texture_transform'])
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(i).decode()}
                     for i in (factors, normal)]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}, {'source': 1, 'sampler': 0}]
    return doc


def sheen_sweep():
    """Row 1: a grey sheenColorFactor 0 .. 1 at sheenRoughnessFactor 0.5; row 2: a white
    sheen's roughness 0 .. 1 (small roughness is a thin rim at grazing angles)."""
    steps = [0.0, 0.25, 0.5, 0.75, 1.0]
    row1 = [(f'sheen {c}', {'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
                            'extensions': {'KHR_materials_sheen': {
                                'sheenColorFactor': [c, c, c], 'sheenRoughnessFactor': 0.5}}})
            for c in steps]
    row2 = [(f'sheen roughness {r}',
             {'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
              'extensions': {'KHR_materials_sheen': {'sheenColorFactor': [1.0, 1.0, 1.0],
                                                     'sheenRoughnessFactor': r}}})
            for r in steps]
    return document('KHR_materials_sheen sweep', [row1, row2], ['KHR_materials_sheen'])


def sheen_textures():
    """One sphere: sheenColorTexture (RGB, sRGB) and sheenRoughnessTexture (A) read one
    2x1 image (left texel red, alpha 0; right green, alpha 1) through
    KHR_texture_transform offset 0.5 in u (the front reads the left texel) and
    texCoord 0 named."""
    image = png_rgba(2, 1, lambda x, y: (255, 0, 0, 0) if x == 0 else (0, 255, 0, 255))
    transform = {'KHR_texture_transform': {'offset': [0.5, 0.0], 'texCoord': 0}}
    row = [('textured sheen', {
        'pbrMetallicRoughness': pbr(BLACK, COATED_BASE),
        'extensions': {'KHR_materials_sheen': {
            'sheenColorFactor': [1.0, 1.0, 1.0], 'sheenRoughnessFactor': 1.0,
            'sheenColorTexture': {'index': 0, 'extensions': transform},
            'sheenRoughnessTexture': {'index': 0, 'extensions': transform}}}})]
    doc = document('KHR_materials_sheen textures', [row],
                   ['KHR_materials_sheen', 'KHR_texture_transform'])
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}]
    return doc


def main():
    out = sys.argv[1]
    for name, doc in (('ior_sweep', ior_sweep()), ('specular_sweep', specular_sweep()),
                      ('specular_textures', specular_textures()),
                      ('clearcoat_sweep', clearcoat_sweep()),
                      ('clearcoat_textures', clearcoat_textures()),
                      ('sheen_sweep', sheen_sweep()), ('sheen_textures', sheen_textures())):
        with open(f'{out}/{name}.gltf', 'w') as f:
            json.dump(doc, f, indent=1)
            f.write('\n')


if __name__ == '__main__':
    main()
