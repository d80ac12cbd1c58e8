"""Renders a glTF file with Blender's Cycles on the CPU: the independent path tracer the
Cycles oracle test compares Sherpa's with (tests/cli/cycles_oracle_test.cpp).
Run by Blender: blender -b --factory-startup --python cycles_render.py -- --gltf FILE
    --environment FILE.hdr --out OUT.png [--size N] [--spp N] [--max-bounces N] [--seed N]
The camera is the file's first; the environment is equirectangular at strength 1; the
image is linear radiance encoded as 8-bit sRGB (Standard view transform: no tone curve,
no dither), transparent where no surface is, box-filtered one pixel wide, not denoised."""
import argparse
import json
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


def principled_as_gltf(gltf):
    """The Principled BSDF's choices nearest glTF's BRDF: single-scattering GGX (glTF's
    has no multiple scattering), and a dielectric's F0 from KHR_materials_ior (Blender
    3.4's Principled takes its reflection's F0 from Specular, 0.08 x Specular, and its
    IOR input only for transmission; the importer fills IOR alone)."""
    with open(gltf, encoding='utf-8') as f:
        source = {m.get('name'): m for m in json.load(f).get('materials', [])}
    for m in bpy.data.materials:
        if not m.use_nodes:
            continue
        ext = source.get(m.name, {}).get('extensions', {})
        for node in m.node_tree.nodes:
            if node.type != 'BSDF_PRINCIPLED':
                continue
            node.distribution = 'GGX'
            if 'KHR_materials_ior' in ext and 'KHR_materials_specular' not in ext:
                ior = ext['KHR_materials_ior'].get('ior', 1.5)
                node.inputs['Specular'].default_value = ((ior - 1) / (ior + 1)) ** 2 / 0.08


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
