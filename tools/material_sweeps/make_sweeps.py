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


def sphere_tangents():
    """The sphere's TANGENT stream: along increasing u (around the sphere), w = 1, so
    the bitangent cross(normal, tangent) points toward decreasing v (up), glTF's
    convention; defined at the poles too."""
    out = []
    for r in range(RINGS + 1):
        for s in range(SEGMENTS + 1):
            phi = 2 * math.pi * s / SEGMENTS
            out.append((-math.sin(phi), 0.0, -math.cos(phi), 1.0))
    return b''.join(struct.pack('<4f', *t) for t in out)


def document(name, rows, extensions, tangents=False):
    """rows: lists of (material name, material JSON), one sphere each, 1 apart; with
    `tangents`, the spheres carry authored TANGENT (sphere_tangents)."""
    count, icount, blob = sphere()
    tangent_offset = len(blob) + (-len(blob)) % 4
    if tangents:
        blob += b'\0' * (tangent_offset - len(blob)) + sphere_tangents()
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
    attributes = {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}
    if tangents:
        doc['bufferViews'].append({'buffer': 0, 'byteOffset': tangent_offset,
                                   'byteLength': count * 16, 'target': 34962})
        doc['accessors'].append({'bufferView': 3, 'componentType': 5126, 'count': count,
                                 'type': 'VEC4'})
        attributes['TANGENT'] = 4
    for r, row in enumerate(rows):
        for c, (label, material) in enumerate(row):
            m = len(doc['materials'])
            doc['materials'].append(dict(name=label, **material))
            doc['meshes'].append({'name': label, 'primitives': [
                {'attributes': dict(attributes), 'indices': 3, 'material': m}]})
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


def with_backdrop(doc):
    """Adds an unlit backdrop 1.5 behind the spheres (z = -1.5, 9 x 7, filling the sweep
    camera's view) with vertical stripes 0.1 wide (dark 0.05, light 0.6, nearest
    filtering): what transmissive spheres refract. Stripes this fine average to the same
    mean behind every sphere, and show a blur or a shift in the image."""
    image = png_rgba(2, 1, lambda x, y: (63, 63, 63, 255) if x == 0 else (203, 203, 203, 255))
    w, h, z = 4.5, 3.5, -1.5
    quad = struct.pack('<12f', -w, -h, z, w, -h, z, w, h, z, -w, h, z)
    quad += struct.pack('<12f', *([0.0, 0.0, 1.0] * 4))
    stripes = 2 * w / 0.2  # periods of two texels
    quad += struct.pack('<8f', 0.0, 0.0, stripes, 0.0, stripes, 1.0, 0.0, 1.0)
    quad += struct.pack('<6H', 0, 1, 2, 0, 2, 3)
    buffer = base64.b64decode(doc['buffers'][0]['uri'].split(',', 1)[1])
    base = len(buffer)
    buffer += quad
    doc['buffers'][0] = {'byteLength': len(buffer),
                         'uri': 'data:application/octet-stream;base64,' + base64.b64encode(buffer).decode()}
    views = doc['bufferViews']
    first_view = len(views)
    views += [{'buffer': 0, 'byteOffset': base, 'byteLength': 96, 'target': 34962},
              {'buffer': 0, 'byteOffset': base + 96, 'byteLength': 32, 'target': 34962},
              {'buffer': 0, 'byteOffset': base + 128, 'byteLength': 12, 'target': 34963}]
    acc = doc['accessors']
    first = len(acc)
    acc += [{'bufferView': first_view, 'byteOffset': 0, 'componentType': 5126, 'count': 4, 'type': 'VEC3',
             'min': [-w, -h, z], 'max': [w, h, z]},
            {'bufferView': first_view, 'byteOffset': 48, 'componentType': 5126, 'count': 4, 'type': 'VEC3'},
            {'bufferView': first_view + 1, 'componentType': 5126, 'count': 4, 'type': 'VEC2'},
            {'bufferView': first_view + 2, 'componentType': 5123, 'count': 6, 'type': 'SCALAR'}]
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}]
    m = len(doc['materials'])
    doc['materials'].append({'name': 'backdrop', 'pbrMetallicRoughness': {
        'baseColorTexture': {'index': 0}}, 'extensions': {'KHR_materials_unlit': {}}})
    doc['meshes'].append({'name': 'backdrop', 'primitives': [
        {'attributes': {'POSITION': first, 'NORMAL': first + 1, 'TEXCOORD_0': first + 2},
         'indices': first + 3, 'material': m}]})
    doc['scenes'][0]['nodes'].append(len(doc['nodes']))
    doc['nodes'].append({'name': 'backdrop', 'mesh': len(doc['meshes']) - 1})
    doc['extensionsUsed'].append('KHR_materials_unlit')
    return doc


WHITE = [1.0, 1.0, 1.0]


def transmissive(color, roughness, transmission=1.0, **extensions):
    e = {'KHR_materials_transmission': {'transmissionFactor': transmission}}
    e.update(extensions)
    return {'pbrMetallicRoughness': pbr(color, roughness), 'extensions': e}


def transmission_sweep():
    """Row 1: transmissionFactor 1 .. 0 on a white smooth dielectric (the striped
    backdrop gives way to the white diffuse); row 2: transmission 1 with base colour
    (the transmission tint) 0.1 .. 1."""
    row1 = [(f'transmission {t}', transmissive(WHITE, 0.0, t)) for t in (1.0, 0.75, 0.5, 0.25, 0.0)]
    row2 = [(f'tint {c}', transmissive([c, c, c], 0.0)) for c in (0.1, 0.3, 0.5, 0.75, 1.0)]
    return with_backdrop(document('KHR_materials_transmission sweep', [row1, row2],
                                  ['KHR_materials_transmission']))


def transmission_roughness():
    """Roughness 0 .. 0.8 (row 1) and ior 1.0 .. 2.0 at roughness 0.4 (row 2): the
    refracted backdrop blurs (three.js's and the Sample Viewer's roughness x
    clamp(2 ior - 2, 0, 1) mip level)."""
    row1 = [(f'roughness {r}', transmissive(WHITE, r)) for r in (0.0, 0.2, 0.4, 0.6, 0.8)]
    row2 = [(f'ior {i}', transmissive(WHITE, 0.4, KHR_materials_ior={'ior': i}))
            for i in (1.0, 1.1, 1.25, 1.5, 2.0)]
    return with_backdrop(document('KHR_materials_transmission roughness', [row1, row2],
                                  ['KHR_materials_transmission', 'KHR_materials_ior']))


def volume_sweep():
    """Spheres as volumes (thickness 0.8, their diameter): attenuationDistance 0.1 .. inf
    of an orange attenuationColor (row 1), grey attenuationColor 0.1 .. 0.9 at
    attenuationDistance 0.4 (row 2)."""
    def volume(**v):
        return transmissive(WHITE, 0.0, KHR_materials_volume=dict(thicknessFactor=0.8, **v))
    row1 = [(f'distance {d}', volume(attenuationDistance=d, attenuationColor=[1.0, 0.5, 0.1]))
            for d in (0.1, 0.3, 1.0, 3.0)]
    row1.append(('distance infinite', volume(attenuationColor=[1.0, 0.5, 0.1])))
    row2 = [(f'colour {c}', volume(attenuationDistance=0.4, attenuationColor=[c, c, c]))
            for c in (0.1, 0.3, 0.5, 0.7, 0.9)]
    return with_backdrop(document('KHR_materials_volume sweep', [row1, row2],
                                  ['KHR_materials_transmission', 'KHR_materials_volume']))


def dispersion_sweep():
    """dispersion 0 .. 10 through a volume of ior 1.5 and thickness 0.8, smooth (row 1)
    and at roughness 0.2 (row 2): the refracted stripes split into colours."""
    rows = []
    for roughness in (0.0, 0.2):
        rows.append([(f'dispersion {d} roughness {roughness}',
                      transmissive(WHITE, roughness, KHR_materials_volume={'thicknessFactor': 0.8},
                                   KHR_materials_dispersion={'dispersion': d}))
                     for d in (0.0, 1.0, 3.0, 6.0, 10.0)])
    return with_backdrop(document('KHR_materials_dispersion sweep', rows,
                                  ['KHR_materials_transmission', 'KHR_materials_volume',
                                   'KHR_materials_dispersion']))


def diffuse_transmission_sweep():
    """diffuseTransmissionFactor 0 .. 1 on a white rough dielectric (row 1), and factor 1
    with diffuseTransmissionColorFactor from white to red (row 2): light from behind the
    sphere comes through its diffuse lobe."""
    def dt(factor, color):
        return {'pbrMetallicRoughness': pbr(WHITE, 0.5), 'extensions': {
            'KHR_materials_diffuse_transmission': {'diffuseTransmissionFactor': factor,
                                                   'diffuseTransmissionColorFactor': color}}}
    row1 = [(f'diffuse transmission {f}', dt(f, WHITE)) for f in (0.0, 0.25, 0.5, 0.75, 1.0)]
    row2 = [(f'diffuse transmission colour {g}', dt(1.0, [1.0, g, g]))
            for g in (1.0, 0.75, 0.5, 0.25, 0.0)]
    doc = document('KHR_materials_diffuse_transmission sweep', [row1, row2],
                   ['KHR_materials_diffuse_transmission', 'KHR_lights_punctual'])
    # A point light behind the rows: what comes through to the front.
    doc['extensions'] = {'KHR_lights_punctual': {'lights': [
        {'type': 'point', 'color': [1.0, 1.0, 1.0], 'intensity': 20.0}]}}
    doc['scenes'][0]['nodes'].append(len(doc['nodes']))
    doc['nodes'].append({'name': 'back light', 'translation': [0.0, 0.0, -2.0],
                         'extensions': {'KHR_lights_punctual': {'light': 0}}})
    return doc


def unlit(color, alpha=1.0, texture=None, **extra):
    pbr_part = {'baseColorFactor': color + [alpha]}
    if texture is not None:
        pbr_part['baseColorTexture'] = {'index': texture}
    return dict({'pbrMetallicRoughness': pbr_part,
                 'extensions': {'KHR_materials_unlit': {}}}, **extra)


def variants():
    """KHR_materials_variants: three unlit spheres (grey, grey, grey) and two variants.
    "Warm": sphere 0 red, sphere 2 a 2x2 yellow/blue checker texture (a texture no
    default material reads: it must be on the GPU before the switch). "Cool": sphere 1
    masked away (alpha 0.25 under the cutoff 0.5: an alpha-mode change), sphere 2 green.
    Unlit, so that both renderers draw the factors as they are."""
    grey = [0.5, 0.5, 0.5]
    doc = document('KHR_materials_variants', [[('grey 0', unlit(grey)), ('grey 1', unlit(grey)),
                                                ('grey 2', unlit(grey))]],
                   ['KHR_materials_unlit', 'KHR_materials_variants'])
    extra = [('red', unlit([1.0, 0.0, 0.0])),
             ('checker', unlit([1.0, 1.0, 1.0], texture=0)),
             ('masked', unlit([0.0, 0.0, 1.0], 0.25, alphaMode='MASK')),
             ('green', unlit([0.0, 1.0, 0.0]))]
    for label, material in extra:
        doc['materials'].append(dict(name=label, **material))
    red, checker, masked, green = 3, 4, 5, 6
    doc['extensions'] = {'KHR_materials_variants': {'variants': [{'name': 'Warm'}, {'name': 'Cool'}]}}
    mappings = [[{'material': red, 'variants': [0]}],
                [{'material': masked, 'variants': [1]}],
                [{'material': checker, 'variants': [0]}, {'material': green, 'variants': [1]}]]
    for mesh, m in zip(doc['meshes'], mappings):
        mesh['primitives'][0]['extensions'] = {'KHR_materials_variants': {'mappings': m}}
    image = png_rgba(2, 2, lambda x, y: (255, 220, 0, 255) if (x + y) % 2 == 0 else (0, 60, 255, 255))
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


# The anisotropic spheres: a bright smooth metal, whose sharp reflections of the studio's
# lights are what the anisotropy stretches along the tangent (around the sphere, along
# u). They carry authored tangents: three.js's frame from screen derivatives points its
# bitangent toward increasing v, against glTF's convention (it flips normal maps' y to
# compensate, not the anisotropy's direction), so only authored tangents give both
# renderers the same frame.
ANISOTROPIC_BASE = [0.9, 0.9, 0.9]


def anisotropy_sweep():
    """Row 1: anisotropyStrength 0 .. 1 along the tangent; row 2: strength 0.8 rotated
    by anisotropyRotation 0, 30, 60, 90 and 135 degrees (counter-clockwise from the
    tangent)."""
    steps = [0.0, 0.25, 0.5, 0.75, 1.0]
    angles = [0, 30, 60, 90, 135]
    row1 = [(f'anisotropy {a}', {'pbrMetallicRoughness': pbr(ANISOTROPIC_BASE, 0.3, 1.0),
                                 'extensions': {'KHR_materials_anisotropy': {
                                     'anisotropyStrength': a}}})
            for a in steps]
    row2 = [(f'anisotropy rotation {d}',
             {'pbrMetallicRoughness': pbr(ANISOTROPIC_BASE, 0.3, 1.0),
              'extensions': {'KHR_materials_anisotropy': {
                  'anisotropyStrength': 0.8, 'anisotropyRotation': math.radians(d)}}})
            for d in angles]
    return document('KHR_materials_anisotropy sweep', [row1, row2], ['KHR_materials_anisotropy'],
                    tangents=True)


def anisotropy_textures():
    """One sphere: anisotropyTexture reads a 2x1 image (left texel: direction +y of the
    tangent frame, strength 1; right: +x, strength 0) through KHR_texture_transform
    offset 0.5 in u (the front reads the left texel), under anisotropyStrength 1 and
    no rotation."""
    image = png_rgba(2, 1, lambda x, y: (128, 255, 255, 255) if x == 0 else (255, 128, 0, 255))
    transform = {'KHR_texture_transform': {'offset': [0.5, 0.0]}}
    row = [('textured anisotropy', {
        'pbrMetallicRoughness': pbr(ANISOTROPIC_BASE, 0.3, 1.0),
        'extensions': {'KHR_materials_anisotropy': {
            'anisotropyStrength': 1.0,
            'anisotropyTexture': {'index': 0, 'extensions': transform}}}})]
    doc = document('KHR_materials_anisotropy textures', [row],
                   ['KHR_materials_anisotropy', 'KHR_texture_transform'], tangents=True)
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}]
    return doc


# The iridescent spheres' base: a black, fairly smooth dielectric, so the film's
# coloured reflection of the environment is what they show.
IRIDESCENT_ROUGHNESS = 0.2


def iridescence_sweep():
    """Row 1: iridescenceFactor 0 .. 1 on the default film (ior 1.3, 400 nm without a
    thickness texture); row 2: a full film of thickness 100 .. 700 nm
    (iridescenceThicknessMaximum)."""
    steps = [0.0, 0.25, 0.5, 0.75, 1.0]
    thicknesses = [100, 250, 400, 550, 700]
    row1 = [(f'iridescence {f}', {'pbrMetallicRoughness': pbr(BLACK, IRIDESCENT_ROUGHNESS),
                                  'extensions': {'KHR_materials_iridescence': {
                                      'iridescenceFactor': f}}})
            for f in steps]
    row2 = [(f'iridescence thickness {t}',
             {'pbrMetallicRoughness': pbr(BLACK, IRIDESCENT_ROUGHNESS),
              'extensions': {'KHR_materials_iridescence': {
                  'iridescenceFactor': 1.0, 'iridescenceThicknessMaximum': t}}})
            for t in thicknesses]
    return document('KHR_materials_iridescence sweep', [row1, row2],
                    ['KHR_materials_iridescence'])


def iridescence_textures():
    """One sphere: iridescenceTexture (R) and iridescenceThicknessTexture (G) read a 2x1
    image (left R 1 G 0.5; right R 0 G 1) through KHR_texture_transform offset 0.5 in u
    (the front reads the left texel: factor 1, thickness mix(200, 600, 0.5) = 400 nm)."""
    image = png_rgba(2, 1, lambda x, y: (255, 128, 0, 255) if x == 0 else (0, 255, 0, 255))
    transform = {'KHR_texture_transform': {'offset': [0.5, 0.0]}}
    row = [('textured iridescence', {
        'pbrMetallicRoughness': pbr(BLACK, IRIDESCENT_ROUGHNESS),
        'extensions': {'KHR_materials_iridescence': {
            'iridescenceFactor': 1.0, 'iridescenceThicknessMinimum': 200,
            'iridescenceThicknessMaximum': 600,
            'iridescenceTexture': {'index': 0, 'extensions': transform},
            'iridescenceThicknessTexture': {'index': 0, 'extensions': transform}}}})]
    doc = document('KHR_materials_iridescence textures', [row],
                   ['KHR_materials_iridescence', 'KHR_texture_transform'])
    doc['images'] = [{'uri': 'data:image/png;base64,' + base64.b64encode(image).decode()}]
    doc['samplers'] = [{'magFilter': 9728, 'minFilter': 9728, 'wrapS': 10497, 'wrapT': 10497}]
    doc['textures'] = [{'source': 0, 'sampler': 0}]
    return doc


def variants_bad():
    """The variants file with broken mappings: a material index past the end, a variant
    index past the end, a variant mapped twice, and a mapping without variants."""
    doc = variants()
    doc['meshes'][0]['primitives'][0]['extensions']['KHR_materials_variants']['mappings'] = [
        {'material': 99, 'variants': [0]}, {'material': 3, 'variants': [7, 1]},
        {'material': 6, 'variants': [1]}, {'material': 3}]
    return doc


def main():
    out = sys.argv[1]
    for name, doc in (('ior_sweep', ior_sweep()), ('specular_sweep', specular_sweep()),
                      ('specular_textures', specular_textures()),
                      ('transmission_sweep', transmission_sweep()),
                      ('transmission_roughness', transmission_roughness()),
                      ('volume_sweep', volume_sweep()), ('dispersion_sweep', dispersion_sweep()),
                      ('diffuse_transmission_sweep', diffuse_transmission_sweep()),
                      ('clearcoat_sweep', clearcoat_sweep()),
                      ('clearcoat_textures', clearcoat_textures()),
                      ('sheen_sweep', sheen_sweep()), ('sheen_textures', sheen_textures()),
                      ('anisotropy_sweep', anisotropy_sweep()),
                      ('anisotropy_textures', anisotropy_textures()),
                      ('iridescence_sweep', iridescence_sweep()),
                      ('iridescence_textures', iridescence_textures()),
                      ('variants', variants()), ('variants_bad', variants_bad())):
        with open(f'{out}/{name}.gltf', 'w') as f:
            json.dump(doc, f, indent=1)
            f.write('\n')


if __name__ == '__main__':
    main()
