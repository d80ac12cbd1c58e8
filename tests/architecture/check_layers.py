#!/usr/bin/env python3
"""Fails when a file of one layer includes a header of a layer above it, or Qt below the editor.

The layers and their order come from the command line (--layers, lowest first), which
CMake fills from SHERPA_LAYERS in cmake/SherpaLayers.cmake: the one list. Names joined
by a comma are peers that may not include each other (cli,editor).

A file's layer is where it lives: engine/LAYER/... (every folder of engine/ must be a
layer), cli/... and editor/.... A layer listed but absent from the tree (engine/render
before it exists) is simply not scanned. An include names a layer when it reads
#include <sherpa/LAYER/...> or "sherpa/LAYER/...".

Exit 0: clean; 1: violations, one line each (file:line: what); 2: bad usage.
"""
import argparse
import re
import sys
from pathlib import Path

SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".cc", ".inl"}
SHERPA_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]sherpa/([A-Za-z0-9_]+)/')
# Qt's headers: <QWidget>, <QtCore/...>, <qglobal.h> style is not used by the project.
QT_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](Q[A-Za-z0-9]+|Qt[A-Za-z]*/[^>"]*)[>"]')
QT_LAYER = "editor"  # the only layer that may know Qt


def parse_layers(words):
    """Maps each layer name to its level (0 = lowest); peers share a level."""
    levels = {}
    for level, word in enumerate(words):
        for name in word.split(","):
            if not name or name in levels:
                raise ValueError(f"layer list {' '.join(words)}: bad or repeated name '{name}'")
            levels[name] = level
    return levels


def layer_roots(root, levels):
    """(layer, folder) for every layer folder in the tree; unknown engine folders are errors."""
    roots, errors = [], []
    engine = root / "engine"
    if engine.is_dir():
        for d in sorted(p for p in engine.iterdir() if p.is_dir()):
            if d.name in levels:
                roots.append((d.name, d))
            else:
                errors.append(f"{d.relative_to(root)}: engine folder '{d.name}' is no layer; "
                              "add it to SHERPA_LAYERS in cmake/SherpaLayers.cmake")
    for name in ("cli", "editor"):
        if (root / name).is_dir() and name in levels:
            roots.append((name, root / name))
    return roots, errors


def check_file(path, rel, layer, levels):
    errors = []
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as e:
        return [f"{rel}: cannot read: {e.strerror}"]
    for number, line in enumerate(text.splitlines(), 1):
        m = SHERPA_INCLUDE.match(line)
        if m:
            used = m.group(1)
            if used not in levels:
                errors.append(f"{rel}:{number}: includes <sherpa/{used}/...>, which is no layer")
            elif used != layer and levels[used] >= levels[layer]:
                errors.append(f"{rel}:{number}: layer {layer} includes <sherpa/{used}/...>, "
                              f"a layer {'beside' if levels[used] == levels[layer] else 'above'} it")
        if layer != QT_LAYER and QT_INCLUDE.match(line):
            errors.append(f"{rel}:{number}: layer {layer} includes Qt ({line.strip()}); "
                          f"only {QT_LAYER} may")
    return errors


def check_tree(root, levels):
    roots, errors = layer_roots(root, levels)
    files = 0
    for layer, folder in roots:
        for path in sorted(folder.rglob("*")):
            if path.suffix in SOURCE_SUFFIXES and path.is_file():
                files += 1
                errors += check_file(path, path.relative_to(root), layer, levels)
    return files, [layer for layer, _ in roots], errors


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, type=Path, help="the source tree")
    ap.add_argument("--layers", required=True, nargs="+", help="layer order, lowest first")
    args = ap.parse_args(argv)
    try:
        levels = parse_layers(args.layers)
    except ValueError as e:
        print(f"check_layers: {e}", file=sys.stderr)
        return 2
    if not args.root.is_dir():
        print(f"check_layers: {args.root}: not a directory", file=sys.stderr)
        return 2
    files, present, errors = check_tree(args.root, levels)
    for e in errors:
        print(e)
    absent = [name for name in levels if name not in present]
    print(f"check_layers: {files} files in layers {' '.join(present)}"
          + (f" (absent: {' '.join(absent)})" if absent else "")
          + f"; {len(errors)} violation(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
