#!/usr/bin/env python3
"""Fails when a design document names a file or folder that does not exist.

The documents that describe the code (docs/architecture.md, engine/*/README.md and
whatever else is passed with --doc) name files in `backticks`. Every such name that
looks like a path is resolved, and each one that resolves nowhere is printed as
DOC:LINE: NAME. A name resolves when it exists
- relative to the repository root or to the document's folder;
- for a layer's README (engine/LAYER/README.md): relative to engine/LAYER, its src/
  or its include/sherpa/LAYER/;
- as an include name, with or without angle brackets (<sherpa/LAYER/file.h>,
  sherpa/LAYER): under engine/LAYER/include/;
- `src/...` in a document about several layers: under some engine/LAYER/;
- `shared/...`: the shared assets beside the checkout (../shared);
- `a.vert/.frag`: both a.vert and a.frag;
- as a bare file name (no folder): a layer's README must hold the file in its own
  layer (or shaders/, tools/); other documents anywhere in the tree.
Names with a wildcard (`*`) must match at least one file. Generated paths (build/...)
and placeholders (LAYER, NAME, ...) are not checked.
Exit 0 when every name resolves, 1 otherwise.
"""
import argparse
import re
import sys
from pathlib import Path

SOURCE_EXT = r"(?:h|hpp|cpp|inc|glsl|comp|vert|frag|rgen|rchit|rmiss|rahit|py|sh|cmake|md|txt|json|svg|ts|py)"
# A token that names a file: folders separated by '/', ending in a known extension, or
# a folder path ending in '/'.
PATH_TOKEN = re.compile(
    rf"^(?:[\w.*-]+/)*[\w.*-]+\.{SOURCE_EXT}(?:/\.\w+)?$|^(?:[\w.-]+/)+[\w.*-]*/?$")
INCLUDE_TOKEN = re.compile(r"^<?sherpa/(\w+)(/[\w./*]+)?>?$")
PLACEHOLDERS = ("LAYER", "NAME", "...", "build/", "$", "~")
SKIP_DIRS = {".git", "build", "build-asan", "node_modules"}


def tokens(text):
    """(line, token) for every backticked token of `text`."""
    for number, line in enumerate(text.splitlines(), 1):
        for token in re.findall(r"`([^`\n]+)`", line):
            yield number, token.strip()


def layer_of(doc, root):
    """The layer a README belongs to (engine/LAYER/README.md), else None."""
    rel = doc.relative_to(root)
    if len(rel.parts) == 3 and rel.parts[0] == "engine" and rel.name == "README.md":
        return rel.parts[1]
    return None


def exists(base, name):
    if "*" in name:
        return any(base.glob(name))
    return (base / name).exists()


def bare_name_found(name, folders):
    for folder in folders:
        if not folder.is_dir():
            continue
        for path in folder.rglob(name):
            if not SKIP_DIRS.intersection(path.relative_to(folder).parts):
                return True
    return False


def resolves(token, doc, root):
    include = INCLUDE_TOKEN.match(token)
    if include:
        return exists(root / "engine" / include.group(1) / "include", token.strip("<>"))
    sibling = re.match(r"^(.*)\.(\w+)/\.(\w+)$", token)
    if sibling:
        stem, a, b = sibling.groups()
        return resolves(f"{stem}.{a}", doc, root) and resolves(f"{stem}.{b}", doc, root)
    layer = layer_of(doc, root)
    name = token.rstrip("/")
    bases = [root, doc.parent]
    if name.startswith("shared/"):
        bases.append(root.parent)
    if name.startswith("src/") and not layer:
        bases += sorted(p for p in (root / "engine").iterdir() if p.is_dir())
    if layer:
        lroot = root / "engine" / layer
        bases += [lroot, lroot / "src", lroot / "include" / "sherpa" / layer]
    if any(exists(base, name) for base in bases):
        return True
    if "/" in name:
        return False
    if layer:
        return bare_name_found(name, [root / "engine" / layer, root / "shaders", root / "tools"])
    return bare_name_found(name, [root])


def check(doc, root):
    missing = []
    for number, token in tokens(doc.read_text(encoding="utf-8")):
        if not (PATH_TOKEN.match(token) or INCLUDE_TOKEN.match(token)):
            continue
        if token.startswith(("-", ".")) and "/" not in token:
            continue  # a file extension (`.h`) or an option, not a file
        if any(p in token for p in PLACEHOLDERS) or token.startswith(("http", "sherpa::")):
            continue
        if not resolves(token, doc, root):
            missing.append(f"{doc.relative_to(root)}:{number}: {token}")
    return missing


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, type=Path)
    parser.add_argument("--doc", action="append", default=[], help="another document to check")
    args = parser.parse_args()
    root = args.root.resolve()
    docs = [root / "docs" / "architecture.md", *sorted((root / "engine").glob("*/README.md"))]
    docs += [root / d for d in args.doc]
    missing = [line for doc in docs for line in check(doc, root)]
    for line in missing:
        print(line)
    print(f"{len(docs)} documents, {len(missing)} names that resolve nowhere")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
