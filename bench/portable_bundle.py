#!/usr/bin/env python3
"""portable_bundle.py -- this build's programs, runnable on another Linux that
has none of their packages (the GPU machines lent to sessions here run another
distribution, can install nothing, and take at most 64 MiB along).

    python3 bench/portable_bundle.py OUT.tar.xz build/wavefront build/bench/wavefront_ray_bench

The archive holds bin/NAME (a launcher), bin/NAME.elf and lib/: every library
the programs load, glibc's loader and libc included, so the host's own libc
does not matter. The launcher runs the program through that loader with lib/
first, then $WF_EXTRA_LIBRARY_PATH (where the machine's OpenCL driver lives).

OpenImageIO links some 250 libraries (OpenVDB, FFmpeg, GDAL, OpenCV, ...) for
formats the renderer never reads or writes, and Open MPI serves only
`wavefront cluster`. Those are replaced by stubs: libraries of the same name
that define just the symbols the kept ones import (OpenImageIO binds every
symbol at load time), each function returning a pointer to zeroed memory. A
program that calls one gets nonsense, so the bundle serves the benchmarks
(EXR, PNG and JPEG images, glTF, OpenCL, Embree), not every use.
"""

import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile

# What the benchmarks call into; everything else a kept library needs is stubbed.
KEEP = re.compile(r"^(ld-linux-x86-64|libc|libm|libpthread|libdl|librt|libstdc\+\+|libgcc_s|libOpenCL"
                  r"|libOpenImageIO|libOpenImageIO_Util|libOpenEXR|libOpenEXRCore|libImath|libIex|libIlmThread"
                  r"|libz|libpng16|libjpeg|libtinygltf|libstb|libembree3|libtbb|libtbbmalloc|libboost_thread)"
                  r"(-[0-9_]+)?\.so")

LAUNCHER = """#!/bin/sh
# Runs {name}.elf with the libraries beside it (bench/portable_bundle.py).
here=$(cd "$(dirname "$0")" && pwd)
exec "$here/../lib/ld-linux-x86-64.so.2" --argv0 "$0" \\
    --library-path "$here/../lib${{WF_EXTRA_LIBRARY_PATH:+:$WF_EXTRA_LIBRARY_PATH}}" "$here/{name}.elf" "$@"
"""


def needed(path):
    out = subprocess.run(["readelf", "-dW", path], check=True, capture_output=True, text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", out)


def resolve(soname):
    for d in ("/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu", "/lib64"):
        if os.path.exists(os.path.join(d, soname)):
            return os.path.realpath(os.path.join(d, soname))
    sys.exit(f"portable_bundle.py: {soname} is not installed here")


def dynamic_symbols(path):
    """(name, version, is_default, kind, size, defined) for each dynamic symbol."""
    out = subprocess.run(["readelf", "--dyn-syms", "-W", path], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":") or not f[0][:-1].isdigit():
            continue
        size, kind, bind, ndx, name = f[2], f[3], f[4], f[6], f[7]
        if bind == "LOCAL" or not name:
            continue
        version, default = "", True
        if "@@" in name:
            name, version = name.split("@@", 1)
        elif "@" in name:
            name, version = name.split("@", 1)
            default = False
        version = version.split(" ")[0]
        rows.append((name, version, default, kind, int(size, 0), ndx != "UND"))
    return rows


def make_stub(soname, real, wanted, workdir):
    """A library named `soname` defining those of `real`'s symbols in `wanted`."""
    asm = [".section .bss", ".balign 64", "wf_zero: .zero 4096", ".text"]
    nodes = {}
    for i, (name, version, default, kind, size, defined) in enumerate(dynamic_symbols(real)):
        if not defined or name not in wanted or kind == "TLS":
            continue
        local = f"wf_stub_{i}"
        if kind == "OBJECT":
            asm += [".section .data", ".balign 16", f".type {local}, @object", f".size {local}, {max(size, 1)}",
                    f"{local}: .zero {max(size, 1)}", ".text"]
        else:
            asm += [f".type {local}, @function", f"{local}: lea wf_zero(%rip), %rax", "ret"]
        if version and version != soname and not default:  # an old version kept beside the default
            asm += [f".globl {local}", f".symver {local}, {name}@{version}"]
            nodes.setdefault(version, [])
            continue
        asm += [f".globl {name}", f".set {name}, {local}"]
        if kind == "OBJECT":
            asm += [f".type {name}, @object", f".size {name}, {max(size, 1)}"]
        nodes.setdefault(version if version and version != soname else "", []).append(name)
    src = os.path.join(workdir, soname + ".s")
    with open(src, "w") as f:
        f.write("\n".join(asm) + "\n")
    script = os.path.join(workdir, soname + ".map")
    unversioned = nodes.pop("", [])
    with open(script, "w") as f:
        if not nodes:
            f.write("{ global: *; };\n")
        for i, version in enumerate(sorted(nodes)):  # symbols without a version go with the first
            names = nodes[version] + (unversioned if i == 0 else [])
            f.write(f"{version} {{ global: {' '.join(n + ';' for n in names)} }};\n")
    out = os.path.join(workdir, soname)
    subprocess.run(["gcc", "-shared", "-nostdlib", "-o", out, src, f"-Wl,-soname,{soname}",
                    f"-Wl,--version-script,{script}"], check=True)
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__.split("\n\n")[1])
    archive, programs = sys.argv[1], sys.argv[2:]
    kept, stubbed, queue = {}, {}, list(programs)
    while queue:
        path = queue.pop()
        for soname in needed(path):
            if soname in kept or soname in stubbed:
                continue
            if KEEP.match(soname):
                kept[soname] = resolve(soname)
                queue.append(kept[soname])
            else:
                stubbed[soname] = resolve(soname)
    # Every symbol the kept objects import, by name.
    wanted = set()
    for path in list(kept.values()) + programs:
        wanted |= {s[0] for s in dynamic_symbols(path) if not s[5]}
    with tempfile.TemporaryDirectory() as tmp:
        root = os.path.join(tmp, "bundle")
        os.makedirs(os.path.join(root, "bin"))
        os.makedirs(os.path.join(root, "lib"))
        for soname, path in kept.items():
            shutil.copy(path, os.path.join(root, "lib", soname))
        for soname, path in stubbed.items():
            make_stub(soname, path, wanted, os.path.join(root, "lib"))
            os.remove(os.path.join(root, "lib", soname + ".s"))
            os.remove(os.path.join(root, "lib", soname + ".map"))
        for p in programs:
            name = os.path.basename(p)
            shutil.copy(p, os.path.join(root, "bin", name + ".elf"))
            with open(os.path.join(root, "bin", name), "w") as f:
                f.write(LAUNCHER.format(name=name))
            os.chmod(os.path.join(root, "bin", name), 0o755)
        subprocess.run(["strip", "--strip-unneeded"] + [os.path.join(root, "lib", s) for s in kept], check=False)
        with tarfile.open(archive, "w:xz", preset=6) as tar:
            tar.add(root, arcname="bundle")
    print(f"{archive}: {len(kept)} libraries kept, {len(stubbed)} stubbed ({', '.join(sorted(stubbed))}); "
          f"{os.path.getsize(archive) / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
