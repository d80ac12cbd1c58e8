#!/usr/bin/env python3
"""Shows that check_layers.py catches what it must, on made-up trees in a temporary folder.

Runs the checker as CTest does (same --layers list, passed on by CMake) on a clean tree
(exit 0) and on trees with one violation each (exit 1 and a line naming the file, the
line and the layers). Exit 0 when every case behaves, 1 otherwise.
"""
import argparse
import sys
from pathlib import Path

from selftest_tree import run_cases

CHECKER = Path(__file__).with_name("check_layers.py")

# Files of a tree that follows the layers (render absent: the check tolerates it).
CLEAN = {
    "engine/core/include/sherpa/core/aabb.h": "#pragma once\n#include <glm/glm.hpp>\n",
    "engine/scene/src/scene.cpp": "#include <sherpa/scene/scene.h>\n#include <sherpa/core/aabb.h>\n",
    "engine/texture/src/ktx2.cpp": "#include <sherpa/texture/ktx2.h>\n#include <sherpa/scene/scene.h>\n",
    "engine/gpu/src/renderer.cpp": '#include "sherpa/texture/ktx2.h"\n#include <sherpa/scene/scene.h>\n',
    "cli/main.cpp": "#include <sherpa/gpu/renderer.h>\n",
    "editor/src/main_window.cpp": "#include <QMainWindow>\n#include <sherpa/gpu/renderer.h>\n",
}

# (name, extra files, expected exit code, fragments the output must contain)
CASES = [
    ("clean tree", {}, 0, ["0 violation(s)", "(absent: render"]),
    ("core includes scene", {"engine/core/src/file_io.cpp": "#include <sherpa/scene/scene.h>\n"},
     1, ["engine/core/src/file_io.cpp:1: layer core includes <sherpa/scene/...>, a layer above"]),
    ("scene header includes gpu, quoted, indented",
     {"engine/scene/include/sherpa/scene/x.h": '#pragma once\n  #  include "sherpa/gpu/context.h"\n'},
     1, ["engine/scene/include/sherpa/scene/x.h:2: layer scene includes <sherpa/gpu/...>"]),
    ("render exists and includes cli", {"engine/render/src/pass.cpp": "#include <sherpa/cli/x.h>\n"},
     1, ["engine/render/src/pass.cpp:1: layer render includes <sherpa/cli/...>, a layer above"]),
    ("render exists and includes gpu", {"engine/render/src/pass.cpp": "#include <sherpa/gpu/x.h>\n"},
     0, ["layers core gpu render scene texture cli editor", "0 violation(s)"]),
    ("gpu includes render", {"engine/gpu/src/y.cpp": "#include <sherpa/render/renderer.h>\n"},
     1, ["layer gpu includes <sherpa/render/...>, a layer above"]),
    ("cli includes editor (peers)", {"cli/z.cpp": "#include <sherpa/editor/x.h>\n"},
     1, ["cli/z.cpp:1: layer cli includes <sherpa/editor/...>, a layer beside"]),
    ("Qt below the editor", {"engine/gpu/src/q.cpp": "#include <QString>\n"},
     1, ["engine/gpu/src/q.cpp:1: layer gpu includes Qt"]),
    ("unknown engine folder", {"engine/physics/src/a.cpp": "int a;\n"},
     1, ["engine folder 'physics' is no layer"]),
    ("unknown sherpa include", {"cli/w.cpp": "#include <sherpa/physics/a.h>\n"},
     1, ["cli/w.cpp:1: includes <sherpa/physics/...>, which is no layer"]),
    ("a commented-out include is no include",
     {"engine/core/src/c.cpp": "// #include <sherpa/gpu/x.h>\n"}, 0, ["0 violation(s)"]),
]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--layers", required=True, nargs="+", help="layer order, lowest first")
    layers = ap.parse_args(argv).layers
    cases = [(name, {**CLEAN, **extra}, ["--layers", *layers], want_rc, fragments)
             for name, extra, want_rc, fragments in CASES]
    return run_cases("check_layers", CHECKER, cases)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
