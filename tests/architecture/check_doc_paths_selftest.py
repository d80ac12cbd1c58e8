#!/usr/bin/env python3
"""Self-test of check_doc_paths.py: a made-up tree whose documents name files that exist
and files that do not; the check passes on the first and names each of the second."""
import sys
from pathlib import Path

from selftest_tree import run_cases

CHECKER = Path(__file__).with_name("check_doc_paths.py")

TREE = {
    "engine/gpu/include/sherpa/gpu/context.h": "",
    "engine/gpu/src/memory.cpp": "",
    "engine/render/include/sherpa/render/renderer.h": "",
    "engine/render/src/passes.h": "",
    "shaders/mesh.vert": "",
    "shaders/mesh.frag": "",
}
GOOD_ARCH = ("`engine/gpu/src/memory.cpp`, `sherpa/render/renderer.h`, `<sherpa/gpu/context.h>`,\n"
             "`src/passes.h`, `shaders/mesh.vert/.frag`, `shaders/*.vert`, `build/x.glsl`, `.h`\n")
GOOD_GPU = "`context.h`, `src/memory.cpp`, `mesh.vert`, `sherpa/render/renderer.h`\n"


def tree(arch, gpu):
    return {**TREE, "docs/architecture.md": arch, "engine/gpu/README.md": gpu}


CASES = [
    ("every name resolves", tree(GOOD_ARCH, GOOD_GPU), [], 0, ["0 names that resolve nowhere"]),
    ("a moved file is named", tree(GOOD_ARCH + "`engine/gpu/src/gone.cpp`\n", GOOD_GPU), [], 1,
     ["docs/architecture.md:3: engine/gpu/src/gone.cpp", "1 names that resolve nowhere"]),
    ("a layer's README names another layer's file by bare name", tree(GOOD_ARCH, GOOD_GPU + "`passes.h`\n"),
     [], 1, ["engine/gpu/README.md:2: passes.h"]),
    ("an include name of a missing header", tree(GOOD_ARCH + "`<sherpa/gpu/gone.h>`\n", GOOD_GPU), [], 1,
     ["docs/architecture.md:3: <sherpa/gpu/gone.h>"]),
    ("a wildcard that matches nothing", tree(GOOD_ARCH + "`shaders/*.comp`\n", GOOD_GPU), [], 1,
     ["docs/architecture.md:3: shaders/*.comp"]),
    ("one half of a shader pair is missing", tree(GOOD_ARCH + "`shaders/mesh.vert/.geom`\n", GOOD_GPU),
     [], 1, ["docs/architecture.md:3: shaders/mesh.vert/.geom"]),
]


def main():
    return run_cases("check_doc_paths", CHECKER, CASES)


if __name__ == "__main__":
    sys.exit(main())
