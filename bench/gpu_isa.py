#!/usr/bin/env python3
"""gpu_isa.py -- what the renderer's kernels cost a GPU, without a GPU:
every program the host builds for a GPU device (build/wavefront_kernel_source
writes it out, expanded, with the host's own options), compiled by Debian's
clang-15 for an AMD GPU with rocm-device-libs, and each kernel's registers,
scratch (spills and private arrays), LDS and occupancy as the compiler's
kernel-resource-usage remarks give them.

Programs: the wavefront (the GPU's default schedule), the wavefront's group
schedule, and the megakernel, each for the feature set of every scene given
(default: the repository's scenes, the Cornell box with every specular
factor 0 (lambertian_cornell), and every feature at once).

--target nvptx compiles each program to NVIDIA's PTX instead (clang's
nvptx64-nvidia-nvcl, left unlinked: the driver supplies OpenCL's built-ins)
and gives its program-scope __constant data, which must fit NVIDIA's 64 KiB
constant bank: 117 KiB of albedo tables once kept every program off an H200
(bench/results/gpu-run.md). Registers there come from the driver itself
(bench/gpu.sh with WF_KERNEL_OPTIONS=-cl-nv-verbose).

Usage: python3 bench/gpu_isa.py [--target gfx90a|gfx1100|gfx1030|nvptx] [--json FILE]
                                [--markdown FILE] [--check] [--tool PATH] [SCENE ...]
--check: exit 1 unless every program compiles (and, for nvptx, fits the
constant bank) (the CI test); prints nothing else. Needs clang-15 and
rocm-device-libs (apt-get install clang-15 rocm-device-libs). gfx90a is CDNA2
(MI200), gfx1100 RDNA3, gfx1030 RDNA2. Debian 12's rocm-device-libs (5.2)
predate RDNA3: of its libraries only the file naming the ISA version is
missing, one constant, which this script compiles (device_libraries).
"""

import argparse
import glob
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

from gltf_variants import lambertian_gltf

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BITCODE = "/usr/lib/x86_64-linux-gnu/amdgcn/bitcode"
PROGRAMS = [("wavefront", ["--integrator", "wavefront"]),
            ("wavefront group", ["--integrator", "wavefront", "--schedule", "group"]),
            ("megakernel", ["--integrator", "megakernel"])]
NVIDIA_CONSTANT_BANK = 64 * 1024
# ISA versions newer than Debian 12's rocm-device-libs, as ROCm's own
# oclc/src/isa_version_*.cl define them (major, minor, stepping in decimal).
ISA_VERSIONS = {"gfx1100": 11000, "gfx1101": 11001, "gfx1102": 11002}
FIELDS = {"SGPRs": "sgprs", "VGPRs": "vgprs", "ScratchSize [bytes/lane]": "scratch",
          "LDS Size [bytes/block]": "lds", "Occupancy [waves/SIMD]": "waves"}


def kernel_source(tool, scene, flags, out):
    what = ["--all-features"] if scene is None else [scene]
    done = subprocess.run([tool] + what + ["--device-type", "gpu", "-o", out] + flags, cwd=ROOT,
                          capture_output=True, text=True, check=True)
    return done.stdout.strip()


def device_libraries(target, tmp):
    """The folder of device libraries for `target`: Debian's, or where
    Debian's lack the target's oclc_isa_version file (ISA_VERSIONS), a new
    folder in `tmp` of links to them beside that file, compiled from its
    constant. Exits with the compiler's error if that fails."""
    isa_file = f"oclc_isa_version_{target[3:]}.bc"
    if os.path.exists(os.path.join(BITCODE, isa_file)) or target not in ISA_VERSIONS:
        return BITCODE
    folder = os.path.join(tmp, "bitcode")
    os.mkdir(folder)
    for name in os.listdir(BITCODE):
        os.symlink(os.path.join(BITCODE, name), os.path.join(folder, name))
    source = os.path.join(tmp, "isa_version.cl")
    with open(source, "w") as f:
        f.write(f"const __constant int __oclc_ISA_version = {ISA_VERSIONS[target]};\n")
    done = subprocess.run(["clang-15", "-x", "cl", "-cl-std=CL1.2", "-target", "amdgcn-amd-amdhsa",
                           f"-mcpu={target}", "-nogpulib", "-fvisibility=protected", "-O3", "-emit-llvm", "-c",
                           source, "-o", os.path.join(folder, isa_file)], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"gpu_isa.py: cannot compile {isa_file} for {target}: " + done.stderr.strip().splitlines()[0]
                 if done.stderr.strip() else f"gpu_isa.py: cannot compile {isa_file} for {target}")
    return folder


def lambertian_cornell(tmp):
    """scenes/cornell-box.gltf as bench/mitsuba_compare.py renders it
    (lambertian_gltf): a program without the interface (WF_HAS_SPECULAR 0),
    which no file in scenes/ makes."""
    with open(os.path.join(ROOT, "scenes", "cornell-box.gltf")) as f:
        doc = json.load(f)
    path = os.path.join(tmp, "cornell-box-lambertian.gltf")
    lambertian_gltf(doc, pathlib.Path(path))
    return path


def compile_for(target, source, options, libraries):
    """Each kernel's figures, or raises CalledProcessError with the compiler's
    errors. Compiled and linked into a code object, as a GPU driver would: a
    function left undefined (C99 inline not inlined) fails only at the link."""
    command = ["clang-15", "-x", "cl", "-cl-std=CL1.2", "-target", "amdgcn-amd-amdhsa", f"-mcpu={target}",
               f"--rocm-device-lib-path={libraries}", "-Xclang", "-finclude-default-header", "-O3", source,
               "-o", source + ".hsaco", "-Rpass-analysis=kernel-resource-usage"] + options.split()
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise subprocess.CalledProcessError(done.returncode, command, done.stdout, done.stderr)
    kernels, current = [], None
    for line in done.stderr.splitlines():
        m = re.search(r"remark: +(.+?): (\S+) \[-Rpass-analysis", line)
        if not m:
            continue
        key, value = m.group(1).strip(), m.group(2)
        if key == "Function Name":
            current = {"kernel": value}
            kernels.append(current)
        elif current is not None and key in FIELDS:
            current[FIELDS[key]] = int(value)
    return kernels


def constant_bytes_for_nvptx(source, options):
    """The program's module-scope .const data in NVIDIA's PTX, in bytes, or
    raises CalledProcessError with the compiler's errors."""
    command = ["clang-15", "-x", "cl", "-cl-std=CL1.2", "-target", "nvptx64-nvidia-nvcl", "-Xclang",
               "-finclude-default-header", "-O3", "-S", source, "-o", source + ".ptx"] + options.split()
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise subprocess.CalledProcessError(done.returncode, command, done.stdout, done.stderr)
    total = 0
    with open(source + ".ptx") as f:
        for line in f:
            m = re.match(r"(?:\.visible |\.global )?\.const (?:\.align \d+ )?\.[bufs](\d+) \w+(?:\[(\d+)\])?", line)
            if m:
                total += int(m.group(1)) // 8 * int(m.group(2) or 1)
    return total


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--target", default="gfx90a")
    parser.add_argument("--json")
    parser.add_argument("--markdown")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--tool", default=os.path.join(ROOT, "build", "bench", "wavefront_kernel_source"),
                        help="the wavefront_kernel_source to use (default: build/bench/)")
    args = parser.parse_args()
    if not shutil.which("clang-15") or not os.path.isdir(BITCODE):
        sys.exit("gpu_isa.py: needs clang-15 and rocm-device-libs (apt-get install clang-15 rocm-device-libs)")
    rows, failures = [], []
    with tempfile.TemporaryDirectory() as tmp:
        scenes = args.scenes or sorted(glob.glob(os.path.join(ROOT, "scenes", "*.gltf"))) + [lambertian_cornell(tmp),
                                                                                              None]
        libraries = device_libraries(args.target, tmp) if args.target != "nvptx" else None
        for scene in scenes:
            name = "all features" if scene is None else os.path.basename(scene)
            for program, flags in PROGRAMS:
                source = os.path.join(tmp, "program.cl")
                options = kernel_source(args.tool, scene, flags, source)
                with open(source) as f:
                    names = set(re.findall(r"__kernel\s+void\s+(\w+)", f.read()))
                try:
                    if args.target == "nvptx":
                        const = constant_bytes_for_nvptx(source, options)
                        rows.append({"scene": name, "program": program, "target": "nvptx", "constant_bytes": const})
                        if const > NVIDIA_CONSTANT_BANK:
                            failures.append(f"{name}, {program}: {const} bytes of __constant data, more than "
                                            f"NVIDIA's {NVIDIA_CONSTANT_BANK}-byte constant bank")
                        continue
                    kernels = [k for k in compile_for(args.target, source, options, libraries)
                               if k["kernel"] in names]
                except subprocess.CalledProcessError as e:
                    errors = [line for line in e.stderr.splitlines() if "error" in line][:3]
                    failures.append(f"{name}, {program}: " + ("; ".join(errors) or "clang-15 failed"))
                    continue
                for k in kernels:
                    rows.append({"scene": name, "program": program, "target": args.target, **k})
    if failures:
        for f in failures:
            print(f"gpu_isa.py: fails on {args.target}: {f}", file=sys.stderr)
        sys.exit(1)
    if args.check:
        return
    if args.target == "nvptx":
        lines = ["`python3 bench/gpu_isa.py --target nvptx`: each program's __constant data in NVIDIA's PTX "
                 f"(the constant bank holds {NVIDIA_CONSTANT_BANK} bytes).", "",
                 "| scene | program | __constant bytes |", "|---|---|--:|"]
        lines += [f"| {r['scene']} | {r['program']} | {r['constant_bytes']} |" for r in rows]
        return write_outputs(lines, rows, args)

    lines = [f"`python3 bench/gpu_isa.py --target {args.target}` (clang-15, rocm-device-libs; the programs "
             "the host builds for a GPU device, expanded by `wavefront_kernel_source`).", "",
             "Kernels of the group program that the plain wavefront program shows alike are left out "
             "(`--json` gives every row).", "",
             "| scene | program | kernel | VGPRs | SGPRs | scratch (bytes a lane) | LDS (bytes) | waves a SIMD |",
             "|---|---|---|--:|--:|--:|--:|--:|"]
    plain = {(r["scene"], r["kernel"]): r for r in rows if r["program"] == "wavefront"}
    for r in rows:
        same = plain.get((r["scene"], r["kernel"]))
        if r["program"] != "wavefront" and same and all(same.get(f) == r.get(f) for f in FIELDS.values()):
            continue  # the group program's copy of a kernel the plain one shows alike
        lines.append(f"| {r['scene']} | {r['program']} | {r['kernel']} | {r.get('vgprs', '')} | {r.get('sgprs', '')} "
                     f"| {r.get('scratch', '')} | {r.get('lds', '')} | {r.get('waves', '')} |")
    write_outputs(lines, rows, args)


def write_outputs(lines, rows, args):
    """The table to stdout and --markdown, the rows to --json."""
    text = "\n".join(lines) + "\n"
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
