#!/usr/bin/env python3
"""Fails when a public render header reaches a <vulkan/...> header, transitively.

What the CLI and the editor include to render (renderer.h and the settings, camera,
statistics and service headers) must not bring Vulkan with it: the compiler's own
dependency list (-M) of a file that includes just that header is read, and every
vulkan/ path in it is a failure. Headers that are Vulkan-facing by nature are listed in
VULKAN_FACING with the reason; one of them that becomes Vulkan-free fails too, so the
list only shrinks.
Usage: check_vulkan_free_headers.py --compiler CXX --root SRC [--layer render]
Exit 0 when every header is as listed, 1 otherwise (one line per header).
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

# Header -> why it carries Vulkan types today.
VULKAN_FACING = {
    "material_extensions.h": "lays out GPU structs of gpu_structs.h (device addresses are VkDeviceAddress)",
    "acceleration_structures.h": "holds the TLAS/BLAS handles and device addresses (SceneAccelerationStructures)",
    "comparison.h": "ComparisonFrame is a gpu::FrameSource (records into a VkCommandBuffer)",
    "presented_frame.h": "PresentedFrame is a gpu::FrameSource (records into a VkCommandBuffer)",
    "gpu_culling.h": "GpuCuller records compute dispatches and owns buffers",
    "gpu_scene.h": "GpuScene hands buffer device addresses to the passes",
    "gpu_material_ext_structs.h": "extends gpu_structs.h (GPUTextureTransform)",
    "gpu_structs.h": "the GPU-visible structs hold VkDeviceAddress and VkDrawIndexedIndirectCommand",
    "scene_textures.h": "SceneTextures owns images, views and samplers",
}


def reaches_vulkan(compiler, includes, header):
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "probe.cpp"
        src.write_text(f"#include <{header}>\n")
        cmd = [compiler, "-std=c++20", "-M", *[f"-I{i}" for i in includes], str(src)]
        r = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if r.returncode != 0:
            raise RuntimeError(f"{header}: {' '.join(cmd)}\n{r.stderr}")
        return [d for d in r.stdout.replace("\\\n", " ").split() if "/vulkan/" in d]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--compiler", required=True)
    parser.add_argument("--root", required=True, type=Path)
    parser.add_argument("--layer", default="render")
    args = parser.parse_args()
    includes = sorted(str(p) for p in (args.root / "engine").glob("*/include"))
    folder = args.root / "engine" / args.layer / "include" / "sherpa" / args.layer
    failures = 0
    for path in sorted(folder.glob("*.h")):
        vulkan = reaches_vulkan(args.compiler, includes, f"sherpa/{args.layer}/{path.name}")
        facing = path.name in VULKAN_FACING
        if vulkan and not facing:
            failures += 1
            print(f"{path.name}: reaches {vulkan[0]} (callers of this header would need Vulkan)")
        elif facing and not vulkan:
            failures += 1
            print(f"{path.name}: is Vulkan-free now; remove it from VULKAN_FACING")
        else:
            print(f"ok   {path.name}: {'Vulkan-facing: ' + VULKAN_FACING[path.name] if facing else 'no Vulkan header'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
