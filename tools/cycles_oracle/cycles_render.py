"""Renders a glTF file with Blender's Cycles on the CPU: the independent path tracer the
Cycles oracle test compares Sherpa's with (tests/cli/cycles_oracle_test.cpp).
Run by Blender: blender -b --factory-startup --python cycles_render.py -- --gltf FILE
    --environment FILE.hdr --out OUT.png [--size N] [--spp N] [--max-bounces N] [--seed N]
The camera is the file's first; the environment is equirectangular at strength 1; the
image is linear radiance encoded as 8-bit sRGB (Standard view transform: no tone curve,
no dither), transparent where no surface is, box-filtered one pixel wide, not denoised."""
import argparse
import json
import math
import sys

import numpy

# Blender 3.4's glTF importer uses numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, 'bool'):
    numpy.bool = bool

import bpy  # noqa: E402


def arguments():
    p = argparse.ArgumentParser(prog='cycles_render.py')
    p.add_argument('--gltf', required=True)
    p.add_argument('--environment', required=True)
    p.add_argument('--out', required=True)
    p.add_argument('--size', type=int, default=160)
    p.add_argument('--spp', type=int, default=64)
    p.add_argument('--max-bounces', type=int, default=8)
    p.add_argument('--seed', type=int, default=0)
    p.add_argument('--threads', type=int, default=2)
    return p.parse_args(sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else [])


def world(scene, environment):
    w = bpy.data.worlds.new('environment')
    w.use_nodes = True
    nodes = w.node_tree.nodes
    nodes.clear()
    tex = nodes.new('ShaderNodeTexEnvironment')
    tex.image = bpy.data.images.load(environment)
    tex.interpolation = 'Linear'
    background = nodes.new('ShaderNodeBackground')
    background.inputs['Strength'].default_value = 1.0
    out = nodes.new('ShaderNodeOutputWorld')
    w.node_tree.links.new(tex.outputs['Color'], background.inputs['Color'])
    w.node_tree.links.new(background.outputs['Background'], out.inputs['Surface'])
    scene.world = w


def volume_as_gltf(node, volume):
    """KHR_materials_volume's absorption in Cycles' Volume Absorption node. glTF's
    coefficient is -ln(attenuationColor) / attenuationDistance per channel; Cycles' is
    (1 - Color) x Density, and the importer sets Color = attenuationColor and Density =
    1 / attenuationDistance, which absorbs less (0.1 instead of 0.105 at a colour of 0.9,
    0.6 instead of 0.92 at 0.4). Density = the largest coefficient and Color = 1 -
    coefficient / Density give glTF's coefficients exactly."""
    color = volume.get('attenuationColor', [1.0, 1.0, 1.0])
    distance = volume.get('attenuationDistance')
    if distance is None or distance <= 0.0:
        return
    sigma = [-math.log(max(c, 1e-6)) / distance for c in color]
    density = max(sigma)
    node.inputs['Density'].default_value = density
    node.inputs['Color'].default_value = [1.0 - s / density if density > 0 else 1.0 for s in sigma] + [1.0]


def clearcoat_as_gltf(material, principled, coat):
    """KHR_materials_clearcoat as glTF layers it, from Cycles' own closures. Blender
    3.4's Clearcoat input is Disney's coat: a GTR1 lobe scaled by 0.25 x Clearcoat with a
    fixed F0 of 0.04, added over the base without taking from it (measured on a black
    rough base with a smooth coat: 0.0118 where glTF's layering gives 0.0267). glTF's
    coat is a GGX lobe at clearcoatRoughness weighted by clearcoatFactor x Fresnel (Schlick,
    F0 0.04), over the base weighted by 1 - clearcoatFactor x Fresnel: here a Mix Shader
    between the Principled BSDF (its Clearcoat 0) and a white GGX Glossy BSDF whose factor
    is clearcoatFactor x (0.04 + 0.96 (1 - n.v)^5), from Layer Weight's Facing (1 - n.v at
    blend 0.5). glTF takes Schlick's at each microfacet's half vector: the same for a
    smooth coat."""
    factor = coat.get('clearcoatFactor', 0.0)
    if factor <= 0.0 or 'clearcoatTexture' in coat or 'clearcoatRoughnessTexture' in coat:
        return  # textured coats are not mapped (no case uses them)
    tree = material.node_tree
    principled.inputs['Clearcoat'].default_value = 0.0
    output = next(n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL')
    link = next(l for l in tree.links if l.to_node == output and l.to_socket.name == 'Surface')
    surface = link.from_socket
    glossy = tree.nodes.new('ShaderNodeBsdfGlossy')
    glossy.distribution = 'GGX'
    glossy.inputs['Color'].default_value = (1.0, 1.0, 1.0, 1.0)
    glossy.inputs['Roughness'].default_value = coat.get('clearcoatRoughnessFactor', 0.0)
    facing = tree.nodes.new('ShaderNodeLayerWeight')
    facing.inputs['Blend'].default_value = 0.5
    power = tree.nodes.new('ShaderNodeMath')
    power.operation = 'POWER'
    power.inputs[1].default_value = 5.0
    schlick = tree.nodes.new('ShaderNodeMath')
    schlick.operation = 'MULTIPLY_ADD'  # x 0.96 + 0.04
    schlick.inputs[1].default_value = 0.96
    schlick.inputs[2].default_value = 0.04
    weight = tree.nodes.new('ShaderNodeMath')
    weight.operation = 'MULTIPLY'
    weight.inputs[1].default_value = factor
    mix = tree.nodes.new('ShaderNodeMixShader')
    tree.links.new(facing.outputs['Facing'], power.inputs[0])
    tree.links.new(power.outputs['Value'], schlick.inputs[0])
    tree.links.new(schlick.outputs['Value'], weight.inputs[0])
    tree.links.new(weight.outputs['Value'], mix.inputs['Fac'])
    tree.links.new(surface, mix.inputs[1])
    tree.links.new(glossy.outputs['BSDF'], mix.inputs[2])
    tree.links.new(mix.outputs['Shader'], output.inputs['Surface'])


def principled_as_gltf(gltf):
    """The Principled BSDF's choices nearest glTF's BRDF: single-scattering GGX (glTF's
    has no multiple scattering), a dielectric's F0 from KHR_materials_ior (Blender
    3.4's Principled takes its reflection's F0 from Specular, 0.08 x Specular, and its
    IOR input only for transmission; the importer fills IOR alone), glTF's volume
    absorption (volume_as_gltf) and glTF's clearcoat layering (clearcoat_as_gltf)."""
    with open(gltf, encoding='utf-8') as f:
        source = {m.get('name'): m for m in json.load(f).get('materials', [])}
    for m in bpy.data.materials:
        if not m.use_nodes:
            continue
        ext = source.get(m.name, {}).get('extensions', {})
        for node in list(m.node_tree.nodes):  # clearcoat_as_gltf adds nodes
            if node.type == 'VOLUME_ABSORPTION' and 'KHR_materials_volume' in ext:
                volume_as_gltf(node, ext['KHR_materials_volume'])
            if node.type != 'BSDF_PRINCIPLED':
                continue
            node.distribution = 'GGX'
            if 'KHR_materials_ior' in ext and 'KHR_materials_specular' not in ext:
                ior = ext['KHR_materials_ior'].get('ior', 1.5)
                node.inputs['Specular'].default_value = ((ior - 1) / (ior + 1)) ** 2 / 0.08
            if 'KHR_materials_clearcoat' in ext:
                clearcoat_as_gltf(m, node, ext['KHR_materials_clearcoat'])


def main():
    a = arguments()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.import_scene.gltf(filepath=a.gltf)
    if 'FINISHED' not in result:
        sys.exit(f'cycles_render: importing {a.gltf} failed: {result}')
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == 'CAMERA']
    if not cameras:
        sys.exit(f'cycles_render: {a.gltf} has no camera')
    scene.camera = cameras[0]
    world(scene, a.environment)
    principled_as_gltf(a.gltf)

    r = scene.render
    r.engine = 'CYCLES'
    r.resolution_x = r.resolution_y = a.size
    r.resolution_percentage = 100
    r.film_transparent = True
    r.dither_intensity = 0.0
    r.threads_mode = 'FIXED'
    r.threads = a.threads
    r.use_persistent_data = False
    r.image_settings.file_format = 'PNG'
    r.image_settings.color_mode = 'RGBA'
    r.image_settings.color_depth = '8'
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = 'sRGB'

    c = scene.cycles
    c.device = 'CPU'
    c.samples = a.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = a.seed
    c.max_bounces = a.max_bounces
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = a.max_bounces
    c.transparent_max_bounces = a.max_bounces
    c.volume_bounces = 0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.pixel_filter_type = 'BOX'
    c.filter_width = 1.0
    r.filepath = a.out
    bpy.ops.render.render(write_still=True)


main()
