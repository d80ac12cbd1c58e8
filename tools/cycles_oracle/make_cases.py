#!/usr/bin/env python3
"""Writes the Cycles oracle's test files (tests/data/cycles_oracle): one glTF with a grid
of spheres, one material each, seen by the file's own camera, an environment that
depends only on elevation (sky.hdr, Radiance RGBE), and cases.json: per sphere its
material, the disc of pixels inside its silhouette at the test's image size, and its
tolerance. The materials are those that map one to one onto Blender's Principled BSDF
through Blender's glTF importer. Adding a material is one line in CASES.
Usage: make_cases.py OUT_DIR"""
import base64
import json
import math
import struct
import sys

SIZE = 160                 # the test's image width and height
RINGS, SEGMENTS, RADIUS = 32, 64, 0.4
DISTANCE = 5.0             # the camera's distance from the grid's plane
INNER = 0.6                # the compared disc, as a fraction of the silhouette's radius


def pbr(color, roughness, metallic=0.0):
    return {'pbrMetallicRoughness': {'baseColorFactor': color + [1.0], 'roughnessFactor': roughness,
                                     'metallicFactor': metallic}}


def emissive(color, strength=None):
    m = pbr([0.0, 0.0, 0.0], 1.0)
    m['emissiveFactor'] = color
    if strength is not None:
        m['extensions'] = {'KHR_materials_emissive_strength': {'emissiveStrength': strength}}
    return m


def ior(value, color, roughness):
    m = pbr(color, roughness)
    m['extensions'] = {'KHR_materials_ior': {'ior': value}}
    return m


def glass(attenuation, distance, ior=None, roughness=0.0):
    """KHR_materials_transmission through a KHR_materials_volume as thick as the sphere
    (thicknessFactor 2 x RADIUS: Blender's importer makes a volume only where the
    thickness is not 0; both path tracers then measure the path inside the mesh), a white
    base colour (the two tint transmitted light by it differently: the colour is in the
    attenuation), and KHR_materials_ior where given."""
    m = pbr([1.0, 1.0, 1.0], roughness)
    m['extensions'] = {'KHR_materials_transmission': {'transmissionFactor': 1.0},
                       'KHR_materials_volume': {'thicknessFactor': 2 * RADIUS,
                                                'attenuationColor': attenuation,
                                                'attenuationDistance': distance}}
    if ior is not None:
        m['extensions']['KHR_materials_ior'] = {'ior': ior}
    return m


def clearcoat(color, roughness, coat, coat_roughness, metallic=0.0):
    """A smooth coat (KHR_materials_clearcoat) over a rough base: the coat's reflection
    sharp over the base's blur."""
    m = pbr(color, roughness, metallic)
    m['extensions'] = {'KHR_materials_clearcoat': {'clearcoatFactor': coat,
                                                   'clearcoatRoughnessFactor': coat_roughness}}
    return m


# (name, material, largest difference of the sphere's mean linear colour per channel).
# Tolerances: the difference measured here (docs/path_tracer.md) with a margin; the
# diffuse spheres differ most, by definition (Principled's diffuse is not glTF's).
CASES = [
    ('white diffuse', pbr([0.8, 0.8, 0.8], 1.0), 0.045),
    ('red plastic', pbr([0.8, 0.1, 0.1], 0.5), 0.03),
    ('green glossy', pbr([0.1, 0.6, 0.2], 0.2), 0.012),
    ('mirror', pbr([1.0, 1.0, 1.0], 0.0, 1.0), 0.004),
    ('gold', pbr([1.0, 0.78, 0.34], 0.3, 1.0), 0.004),
    ('rough metal', pbr([0.9, 0.9, 0.9], 0.7, 1.0), 0.005),
    ('black dielectric', pbr([0.0, 0.0, 0.0], 0.1), 0.004),
    ('emission', emissive([0.9, 0.5, 0.2]), 0.003),
    ('emission strength', emissive([0.2, 0.3, 0.1], 3.0), 0.003),
    ('ior 2', ior(2.0, [0.0, 0.0, 0.0], 0.1), 0.004),
    ('glass volume', glass([0.9, 0.6, 0.4], 0.8), 0.005),
    ('glass ior 1.33', glass([0.95, 0.95, 0.8], 1.0, 1.33), 0.005),
    ('clearcoat on black', clearcoat([0.0, 0.0, 0.0], 1.0, 1.0, 0.0), 0.004),
    ('clearcoat on metal', clearcoat([0.9, 0.6, 0.3], 0.6, 1.0, 0.0, 1.0), 0.006),
]


# An emissive panel above the grid, facing down, out of the camera's view: every sphere is
# also lit by an emissive mesh (the path tracer samples its triangles as lights, Cycles
# its own way). (centre, half width in x, half depth in z, emissive colour, strength).
PANEL = ((0.0, 2.6, 1.5), 2.0, 0.5, [1.0, 0.9, 0.8], 2.5)


def sphere():
    """A UV sphere: positions, normals and 16-bit indices, packed."""
    pos, idx = [], []
    for r in range(RINGS + 1):
        theta = math.pi * r / RINGS
        for s in range(SEGMENTS + 1):
            phi = 2 * math.pi * s / SEGMENTS
            pos.append((math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)))
    for r in range(RINGS):
        for s in range(SEGMENTS):
            a = r * (SEGMENTS + 1) + s
            b = a + SEGMENTS + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    blob = b''.join(struct.pack('<3f', *(RADIUS * c for c in p)) for p in pos)
    blob += b''.join(struct.pack('<3f', *p) for p in pos)
    blob += struct.pack('<%dH' % len(idx), *idx)
    return len(pos), len(idx), blob


def panel():
    """PANEL as two triangles whose front (counter-clockwise) faces -Y: positions,
    normals, 16-bit indices, packed."""
    (x, y, z), hx, hz = PANEL[0], PANEL[1], PANEL[2]
    pos = [(x - hx, y, z - hz), (x + hx, y, z - hz), (x + hx, y, z + hz), (x - hx, y, z + hz)]
    blob = b''.join(struct.pack('<3f', *p) for p in pos)
    blob += struct.pack('<3f', 0.0, -1.0, 0.0) * 4
    blob += struct.pack('<6H', 0, 1, 2, 0, 2, 3)
    return blob, pos


def grid():
    """Sphere centres (x, y) 1 apart, row by row from the top left, and the yfov that
    shows them all with a margin."""
    columns = math.ceil(math.sqrt(len(CASES)))
    rows = math.ceil(len(CASES) / columns)
    centres = [(i % columns - (columns - 1) / 2, (rows - 1) / 2 - i // columns) for i in range(len(CASES))]
    half = max(columns, rows) / 2 + 0.05
    return centres, 2 * math.atan(half / DISTANCE)


def document():
    count, icount, blob = sphere()
    v = count * 12
    panel_blob, panel_pos = panel()
    p0 = len(blob)
    centres, yfov = grid()
    extensions = sorted({e for _, m, _ in CASES for e in m.get('extensions', {})})
    doc = {
        'asset': {'version': '2.0', 'generator': 'Sherpa tools/cycles_oracle/make_cases.py'},
        'scene': 0,
        'scenes': [{'name': 'Cycles oracle', 'nodes': []}],
        'nodes': [], 'meshes': [], 'materials': [],
        'cameras': [{'type': 'perspective',
                     'perspective': {'yfov': yfov, 'aspectRatio': 1.0, 'znear': 0.1, 'zfar': 100.0}}],
        'buffers': [{'byteLength': len(blob) + len(panel_blob),
                     'uri': 'data:application/octet-stream;base64,' +
                            base64.b64encode(blob + panel_blob).decode()}],
        'bufferViews': [
            {'buffer': 0, 'byteOffset': 0, 'byteLength': v, 'target': 34962},
            {'buffer': 0, 'byteOffset': v, 'byteLength': v, 'target': 34962},
            {'buffer': 0, 'byteOffset': 2 * v, 'byteLength': icount * 2, 'target': 34963},
            {'buffer': 0, 'byteOffset': p0, 'byteLength': 48, 'target': 34962},
            {'buffer': 0, 'byteOffset': p0 + 48, 'byteLength': 48, 'target': 34962},
            {'buffer': 0, 'byteOffset': p0 + 96, 'byteLength': 12, 'target': 34963},
        ],
        'accessors': [
            {'bufferView': 0, 'componentType': 5126, 'count': count, 'type': 'VEC3',
             'min': [-RADIUS] * 3, 'max': [RADIUS] * 3},
            {'bufferView': 1, 'componentType': 5126, 'count': count, 'type': 'VEC3'},
            {'bufferView': 2, 'componentType': 5123, 'count': icount, 'type': 'SCALAR'},
            {'bufferView': 3, 'componentType': 5126, 'count': 4, 'type': 'VEC3',
             'min': [min(p[k] for p in panel_pos) for k in range(3)],
             'max': [max(p[k] for p in panel_pos) for k in range(3)]},
            {'bufferView': 4, 'componentType': 5126, 'count': 4, 'type': 'VEC3'},
            {'bufferView': 5, 'componentType': 5123, 'count': 6, 'type': 'SCALAR'},
        ],
    }
    cases = []
    pixels_per_unit = SIZE / 2 / math.tan(yfov / 2)
    for i, ((name, material, tolerance), (x, y)) in enumerate(zip(CASES, centres)):
        doc['materials'].append(dict(name=name, **material))
        doc['meshes'].append({'name': name, 'primitives': [
            {'attributes': {'POSITION': 0, 'NORMAL': 1}, 'indices': 2, 'material': i}]})
        doc['scenes'][0]['nodes'].append(len(doc['nodes']))
        doc['nodes'].append({'name': name, 'mesh': i, 'translation': [x, y, 0.0]})
        # The silhouette's centre and radius as the camera projects them (a sphere off
        # the axis projects to a slightly larger ellipse: the disc stays inside it).
        cases.append({'name': name, 'x': SIZE / 2 + x / DISTANCE * pixels_per_unit,
                      'y': SIZE / 2 - y / DISTANCE * pixels_per_unit,
                      'radius': INNER * RADIUS / math.sqrt(DISTANCE ** 2 - RADIUS ** 2) * pixels_per_unit,
                      'max_diff': tolerance})
    panel_material = emissive(PANEL[3], PANEL[4])
    doc['materials'].append(dict(name='panel', **panel_material))
    doc['meshes'].append({'name': 'panel', 'primitives': [
        {'attributes': {'POSITION': 3, 'NORMAL': 4}, 'indices': 5, 'material': len(doc['materials']) - 1}]})
    doc['scenes'][0]['nodes'].append(len(doc['nodes']))
    doc['nodes'].append({'name': 'panel', 'mesh': len(doc['meshes']) - 1})
    doc['extensionsUsed'] = sorted(set(extensions) | set(panel_material.get('extensions', {})))
    doc['scenes'][0]['nodes'].append(len(doc['nodes']))
    doc['nodes'].append({'name': 'camera', 'camera': 0, 'translation': [0.0, 0.0, DISTANCE]})
    return doc, {'size': SIZE, 'spheres': cases}


def sky(elevation):
    """Linear radiance by elevation (radians): a warm horizon to a blue zenith, a dark
    brown ground, blended smoothly across the horizon; at most 1, so that a linear
    8-bit image holds what the spheres reflect."""
    s = math.sin(elevation)
    up = max(s, 0.0) ** 0.5
    heaven = [0.95 + (0.25 - 0.95) * up, 0.9 + (0.45 - 0.9) * up, 0.8 + (0.9 - 0.8) * up]
    ground = [0.3, 0.22, 0.15]
    t = min(max((s + 0.08) / 0.16, 0.0), 1.0)
    t = t * t * (3 - 2 * t)
    return [g + (h - g) * t for g, h in zip(ground, heaven)]


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes(4)
    e = math.frexp(m)[1]
    scale = 256.0 / 2.0 ** e
    return bytes([min(255, int(c[0] * scale)), min(255, int(c[1] * scale)), min(255, int(c[2] * scale)), e + 128])


def sky_hdr(width=128, height=64):
    """An equirectangular Radiance image, flat (not run-length encoded) scanlines, the
    top row the zenith."""
    rows = b''.join(rgbe(sky(math.pi / 2 - math.pi * (y + 0.5) / height)) * width for y in range(height))
    return b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n' + f'-Y {height} +X {width}\n'.encode() + rows


def main():
    out = sys.argv[1]
    doc, cases = document()
    with open(f'{out}/spheres.gltf', 'w') as f:
        json.dump(doc, f, indent=1)
        f.write('\n')
    with open(f'{out}/cases.json', 'w') as f:
        json.dump(cases, f, indent=1)
        f.write('\n')
    with open(f'{out}/sky.hdr', 'wb') as f:
        f.write(sky_hdr())


if __name__ == '__main__':
    main()
