#!/usr/bin/env python3
"""Pack sherpa binaries with their shared libraries for a machine that has a GPU
driver but none of our Debian packages (the NVIDIA device machine).

Why: the binaries' full library closure is ~350 MB, almost all of it pulled in by
OpenImageIO's optional plugins (video, DICOM, OpenVDB, HEIF, RAW, OpenCV, GDAL),
which rendering a glTF scene never calls. Those libraries are replaced by stubs
that export exactly the symbols (with their version nodes) the kept libraries
import, so the BIND_NOW loader is satisfied; every stub function aborts with a
message, so a stub that is reached says so instead of misbehaving.

Usage: make_bundle.py OUT_DIR BINARY... ; then run BINARY through
OUT_DIR/run.sh, which puts the bundled libraries first on the search path.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Library name prefixes replaced by stubs (matched against the SONAME).
STUBBED = (
    "libopencv_", "libdcm", "liboflog", "libofstd", "libavcodec", "libavformat",
    "libavutil", "libswscale", "libswresample", "libheif", "libopenvdb", "libraw_r",
    "libOpenColorIO", "libgdal", "libtbb",
)

# The C library stays the host's: the GPU driver loads host libraries (libX11)
# built against a newer glibc than ours, and glibc is backward compatible.
HOST = ("ld-linux", "libc.so", "libm.so", "libmvec.so", "libpthread.so", "libdl.so",
        "librt.so", "libresolv.so", "libutil.so")

# Stubbed functions that the kept libraries call from their static initialisers
# (plugin registration objects): these return instead of aborting.
NOOP = {
    "_ZN10DiRegisterC1Ev", "_ZN10DiRegisterD1Ev",
}
# Version queries called while OpenImageIO builds its library list: these return
# the string "stub" so the list says the library is not there.
RETURNS_STRING = {"libraw_version"}


def run(*cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def needed(path):
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", run("readelf", "-d", path))


def resolve(binaries):
    """SONAME -> real path for the binaries' closure, as the loader resolves it."""
    found = {}
    for b in binaries:
        for line in run("ldd", b).splitlines():
            m = re.match(r"\s*(\S+) => (\S+)", line)
            if m and m.group(2) != "not":
                found[m.group(1)] = os.path.realpath(m.group(2))
            m = re.match(r"\s*(/\S*ld-linux\S*)", line)
            if m:
                found[os.path.basename(m.group(1))] = os.path.realpath(m.group(1))
    return found


def kept_closure(binaries, libs):
    """Libraries reachable from the binaries without passing through a stub."""
    keep, stub, todo = set(), set(), list(binaries)
    while todo:
        for name in needed(todo.pop()):
            if name in keep or name in stub or name not in libs or name.startswith(HOST):
                continue
            if name.startswith(STUBBED):
                stub.add(name)
            else:
                keep.add(name)
                todo.append(libs[name])
    return keep, stub


def imports(paths):
    """(symbol, version) pairs the given ELF files import."""
    out = set()
    for p in paths:
        for line in run("nm", "-D", "--undefined-only", p).splitlines():
            sym = line.split()[-1]
            name, _, ver = sym.partition("@")
            out.add((name, ver.lstrip("@")))
    return out


def make_stub(soname, real_path, wanted, workdir, out_dir):
    defined = {}
    for line in run("nm", "-D", "-S", "--defined-only", real_path).splitlines():
        parts = line.split()
        if len(parts) < 3:
            continue
        kind, sym = parts[-2], parts[-1]
        size = int(parts[1], 16) if len(parts) == 4 else 8
        name, _, ver = sym.partition("@")
        defined[(name, ver.lstrip("@"))] = (kind, max(size, 8))
        defined.setdefault((name, ""), (kind, max(size, 8)))
    asm = [".section .rodata", '.Lstub: .asciz "stub"', ".text"]
    versions = {}
    for name, ver in sorted(wanted):
        hit = defined.get((name, ver)) or defined.get((name, ""))
        if not hit:
            continue
        kind, size = hit
        label = name
        if kind in "TtWiI" and name in RETURNS_STRING:
            asm += [f".globl {label}", f".type {label},@function", f"{label}:",
                    "  leaq .Lstub(%rip), %rax", "  ret"]
        elif kind in "TtWiI" and name in NOOP:
            asm += [f".globl {label}", f".type {label},@function", f"{label}:", "  ret"]
        elif kind in "TtWiI":
            n = len(asm)
            asm += [f".globl {label}", f".type {label},@function", f"{label}:",
                    f"  leaq .Lname{n}(%rip), %rdi", "  jmp sherpa_stub_called",
                    ".section .rodata", f".Lname{n}: .asciz \"{label}\"", ".text"]
        else:
            asm += [".data", f".globl {label}", f".type {label},@object",
                    f".size {label},{size}", f"{label}: .zero {size}", ".text"]
        versions.setdefault(ver, []).append(name)
    base = os.path.join(workdir, soname)
    with open(base + ".s", "w") as f:
        f.write("\n".join(asm) + "\n")
    with open(base + ".c", "w") as f:
        f.write('#include <stdio.h>\n#include <stdlib.h>\n'
                '__attribute__((visibility("hidden"))) void sherpa_stub_called(const char* name) {\n'
                f'  fprintf(stderr, "sherpa bundle: stub %s of {soname} was called\\n", name);\n'
                "  abort();\n}\n")
    script = []
    for ver, names in versions.items():
        if ver:
            script.append(ver + " { global: " + " ".join(f'"{n}";' for n in names) + " };")
    script.append("{ global: *; };" if not script else "")
    with open(base + ".map", "w") as f:
        f.write("\n".join(script) + "\n")
    cmd = ["gcc", "-shared", "-fPIC", "-o", os.path.join(out_dir, soname), base + ".s",
           base + ".c", f"-Wl,-soname,{soname}"]
    if any(versions):
        cmd.append(f"-Wl,--version-script={base}.map")
    run(*cmd)


def main():
    out_dir, binaries = sys.argv[1], sys.argv[2:]
    lib_dir = os.path.join(out_dir, "lib")
    os.makedirs(lib_dir, exist_ok=True)
    libs = resolve(binaries)
    keep, stub = kept_closure(binaries, libs)
    for name in keep:
        shutil.copy2(libs[name], os.path.join(lib_dir, name))
    wanted = imports(binaries + [libs[n] for n in keep])
    with tempfile.TemporaryDirectory() as work:
        for name in sorted(stub):
            make_stub(name, libs[name], wanted, work, lib_dir)
    for b in binaries:
        shutil.copy2(b, os.path.join(out_dir, os.path.basename(b)))
    with open(os.path.join(out_dir, "run.sh"), "w") as f:
        f.write('#!/bin/sh\n# run.sh BINARY ARGS...: a bundled binary with the bundled libraries\n'
                'here=$(cd "$(dirname "$0")" && pwd)\nbin=$1; shift\n'
                'LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/$bin" "$@"\n')
    os.chmod(os.path.join(out_dir, "run.sh"), 0o755)
    print(f"kept {len(keep)} libraries, stubbed {len(stub)}: {' '.join(sorted(stub))}")


if __name__ == "__main__":
    main()
