#!/usr/bin/env python3
"""mitsuba_compare.py -- this renderer against Mitsuba 3 on the project's Cornell box,
calibrated to the same integral and then timed in the same run (issue 19's peer).

Calibration: both estimate the same image. The glTF camera (yfov, position and
rotation of its node); Lambertian walls of the file's base colours (for wavefront the
file gets KHR_materials_specular specularFactor 0 on every material, which leaves a
plain Lambertian surface; for Mitsuba a `diffuse` BSDF); the file's emissive quad as a
one-sided area light of radiance emissiveFactor x emissiveStrength; unlimited depth;
a one-pixel box filter; independent samples. The image means must agree within their
noise (the standard error over 16x16-pixel blocks); per-channel ratios are printed too.

Timing: `--rounds` rounds, each rendering once with wavefront (the closing report's
`render` time: kernels and host, without load and kernel build) and once with
Mitsuba (the wall time of mi.render, its result read back, after one untimed render
that JIT-compiles and caches its kernels), one after the other, so that a load on the
machine falls on both alike. Reported: samples/s of each, per round and the median,
and the ratio. Both path tracers start Russian roulette at depth 5 (Mitsuba's
`rr_depth`, wavefront's default --roulette-depth), Mitsuba capping survival at 0.95,
so both trace paths of about the same length for the same image.

Efficiency at equal time: each round also renders ours with Sobol points (our
default sampler) and Mitsuba with its `ldsampler`; every configuration's
1 / (relMSE x seconds) is reported, relMSE estimated from its renders of rounds 1
and 2 (seeds 1 and 2), which need no reference.

Not part of CI or the test suite. Mitsuba 3 comes from PyPI, in a virtual environment
outside the repository:

    python3 -m venv /work/venv-mitsuba && /work/venv-mitsuba/bin/pip install mitsuba numpy
    apt-get install libllvm19    # Dr.Jit's LLVM backend: Debian 12's default LLVM 14/15 fail
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 /work/venv-mitsuba/bin/python \\
        bench/mitsuba_compare.py --width 512 --spp 16 --rounds 3 --markdown bench/results/mitsuba-compare.md

(with Debian's LLVM 14, which PoCL loads, Dr.Jit's code generation stops at "Cannot
select: fminimum").
"""

import argparse
import base64
import json
import math
import statistics
import struct
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from gltf_variants import lambertian_gltf

REPO = Path(__file__).resolve().parents[1]
# (renderer, sampler) of the efficiency table; the time table compares the two independent ones.
EFFICIENCY_CONFIGS = [("ours", "independent"), ("ours", "sobol"), ("Mitsuba", "independent"), ("Mitsuba", "ldsampler")]
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
FORMATS = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}


def buffers_of(doc):
    """The bytes of each buffer; the project's scenes embed them as data URIs."""
    out = []
    for b in doc["buffers"]:
        uri = b["uri"]
        assert uri.startswith("data:"), "mitsuba_compare.py reads embedded buffers only"
        out.append(base64.b64decode(uri.split(",", 1)[1]))
    return out


def accessor(doc, buffers, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    n = COMPONENTS[a["type"]]
    fmt = FORMATS[a["componentType"]]
    size = struct.calcsize(fmt)
    stride = view.get("byteStride", n * size)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    data = buffers[view["buffer"]]
    rows = [struct.unpack_from("<" + fmt * n, data, start + i * stride) for i in range(a["count"])]
    return np.array(rows, dtype=np.float64 if fmt == "f" else np.int64)


def quaternion_rotate(q, v):
    x, y, z, w = q
    u = np.array([x, y, z])
    v = np.asarray(v, dtype=float)
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def mitsuba_scene(mi, doc, folder, width, height, sampler="independent"):
    buffers = buffers_of(doc)
    scene = {"type": "scene", "integrator": {"type": "path", "max_depth": -1}}
    for k, mesh in enumerate(doc["meshes"]):
        for j, prim in enumerate(mesh["primitives"]):
            positions = accessor(doc, buffers, prim["attributes"]["POSITION"])
            if "indices" in prim:
                faces = accessor(doc, buffers, prim["indices"]).reshape(-1, 3)
            else:
                faces = np.arange(len(positions)).reshape(-1, 3)
            m = mi.Mesh(f"m{k}_{j}", len(positions), len(faces), has_vertex_normals=False)
            params = mi.traverse(m)
            params["vertex_positions"] = mi.Float(positions.astype(np.float32).ravel())
            params["faces"] = mi.UInt32(faces.astype(np.uint32).ravel())
            params.update()
            ply = folder / f"m{k}_{j}.ply"
            m.write_ply(str(ply))
            material = doc["materials"][prim["material"]]
            base = material.get("pbrMetallicRoughness", {}).get("baseColorFactor", [1, 1, 1, 1])[:3]
            shape = {"type": "ply", "filename": str(ply), "face_normals": True,
                     "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": base}}}
            emissive = material.get("emissiveFactor", [0, 0, 0])
            strength = material.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get(
                "emissiveStrength", 1.0)
            if max(emissive) > 0:
                shape["emitter"] = {"type": "area",
                                    "radiance": {"type": "rgb", "value": [c * strength for c in emissive]}}
            scene[f"shape_{k}_{j}"] = shape
    node = next(n for n in doc["nodes"] if "camera" in n)
    camera = doc["cameras"][node["camera"]]["perspective"]
    q = node.get("rotation", [0, 0, 0, 1])
    origin = np.array(node.get("translation", [0, 0, 0]), dtype=float)
    forward = quaternion_rotate(q, [0, 0, -1])
    up = quaternion_rotate(q, [0, 1, 0])
    scene["sensor"] = {
        "type": "perspective",
        "fov_axis": "y",
        "fov": math.degrees(camera["yfov"]),
        "to_world": mi.ScalarTransform4f().look_at(origin=origin.tolist(), target=(origin + forward).tolist(),
                                                   up=up.tolist()),
        "sampler": {"type": sampler},
        "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                 "pixel_format": "rgb"},
    }
    return mi.load_dict(scene)


def read_exr(mi, path):
    return np.array(mi.Bitmap(str(path)), dtype=np.float64)[:, :, :3]


def relmse_of_two(a, b):
    """The relMSE of either of two renders of the same image with independent
    seeds, estimated without a reference: (a - b)^2 is twice a pixel's variance,
    over the squared mean plus 0.01 (image/error_metrics.h's relMSE)."""
    m = 0.5 * (a + b)
    return float(np.mean((a - b) ** 2 / (m * m + 0.01)) / 2.0)


def mean_and_error(a, b, block=16):
    """Mean of a and b over the image, and the standard error of their difference
    of means from the spread of block means."""
    h, w = a.shape[0] // block * block, a.shape[1] // block * block
    da = (a[:h, :w] - b[:h, :w]).mean(axis=2).reshape(h // block, block, w // block, block).mean(axis=(1, 3))
    return a.mean(), b.mean(), da.std(ddof=1) / math.sqrt(da.size)


def render_ours(scene_path, out, width, spp, seed, integrator, sampler="independent"):
    stats = Path(out).with_suffix(".json")
    cmd = [str(REPO / "build" / "wavefront"), "render", str(scene_path), "--width", str(width), "--height",
           str(width), "--spp", str(spp), "--seed", str(seed), "--integrator", integrator, "-o", str(out), "--quiet",
           "--stats-json", str(stats), "--max-depth", "unlimited",  # as Mitsuba's max_depth -1
           "--sampler", sampler]
    subprocess.run(cmd, check=True)
    return float(json.loads(stats.read_text())["times"]["render"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene", nargs="?", default=str(REPO / "scenes" / "cornell-box.gltf"))
    ap.add_argument("--width", type=int, default=512)
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--integrator", default="wavefront", choices=["wavefront", "megakernel"],
                    help="this renderer's integrator (the column named wavefront in the report)")
    ap.add_argument("--markdown")
    args = ap.parse_args()
    if args.rounds < 2:
        ap.error("--rounds must be at least 2: the efficiency table takes each configuration's relMSE from two renders")

    import mitsuba as mi
    mi.set_variant(args.variant)
    doc = json.loads(Path(args.scene).read_text())
    samples = args.width * args.width * args.spp
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        ours_scene = folder / "lambertian.gltf"
        lambertian_gltf(doc, ours_scene)
        scene = mitsuba_scene(mi, doc, folder, args.width, args.width)

        ld_scene = mitsuba_scene(mi, doc, folder, args.width, args.width, "ldsampler")

        start = time.perf_counter()
        np.array(mi.render(scene, spp=args.spp, seed=0))
        first = time.perf_counter() - start
        np.array(mi.render(ld_scene, spp=args.spp, seed=0))

        # Each round: ours with either sampler, then Mitsuba with either; each
        # configuration's images of rounds 1 and 2 (seeds 1 and 2) give its relMSE.
        seconds = {c: [] for c in EFFICIENCY_CONFIGS}
        images = {c: [] for c in EFFICIENCY_CONFIGS}
        for r in range(args.rounds):
            for config in EFFICIENCY_CONFIGS:
                renderer, sampler = config
                if renderer == "ours":
                    out = folder / f"ours-{sampler}-{r}.exr"
                    seconds[config].append(render_ours(ours_scene, out, args.width, args.spp, r + 1,
                                                       args.integrator, sampler))
                    images[config].append(read_exr(mi, out))
                else:
                    start = time.perf_counter()
                    image = np.array(mi.render(scene if sampler == "independent" else ld_scene, spp=args.spp,
                                               seed=r + 1))
                    seconds[config].append(time.perf_counter() - start)
                    images[config].append(np.asarray(image, dtype=np.float64)[:, :, :3])
        rows = list(zip(seconds[("ours", "independent")], seconds[("Mitsuba", "independent")]))
        ours = images[("ours", "independent")][-1]
        theirs = images[("Mitsuba", "independent")][-1]
        m_ours, m_theirs, error = mean_and_error(ours, theirs)
        channels = ours.reshape(-1, 3).mean(axis=0) / theirs.reshape(-1, 3).mean(axis=0)
        left = ours[:, : args.width // 8].mean(axis=(0, 1)), theirs[:, : args.width // 8].mean(axis=(0, 1))
        efficiency = {}
        for config in EFFICIENCY_CONFIGS:
            relmse = relmse_of_two(images[config][0], images[config][1])
            median = statistics.median(seconds[config])
            efficiency[config] = (median, relmse, 1.0 / (relmse * median))

    lines = [f"# wavefront against Mitsuba 3 ({mi.__version__}, `{args.variant}`) on {Path(args.scene).name}", "",
             f"`{' '.join(['bench/mitsuba_compare.py'] + [a for a in __import__('sys').argv[1:]])}`: "
             f"{args.width}x{args.width}, {args.spp} spp, unlimited depth, Lambertian walls, "
             f"{args.rounds} interleaved rounds on the same machine; ours is "
             f"`build/wavefront render --integrator {args.integrator}`.", "",
             "## Calibration (the last round's images)", "",
             f"- image mean: ours {m_ours:.5f}, Mitsuba {m_theirs:.5f}; difference "
             f"{m_ours - m_theirs:+.5f} ± {error:.5f} (standard error over 16x16 blocks), ratio "
             f"{m_ours / m_theirs:.4f}",
             f"- per channel, ours / Mitsuba: {channels[0]:.4f} {channels[1]:.4f} {channels[2]:.4f}",
             f"- left eighth of the image (the red wall): ours {np.round(left[0], 4).tolist()}, "
             f"Mitsuba {np.round(left[1], 4).tolist()}", "",
             "## Time", "",
             f"Mitsuba's first render, which JIT-compiles its kernels: {first:.2f} s.", "",
             "| round | ours s | ours M samples/s | Mitsuba s | Mitsuba M samples/s | Mitsuba / ours |",
             "|--:|--:|--:|--:|--:|--:|"]
    for i, (a, b) in enumerate(rows):
        lines.append(f"| {i + 1} | {a:.3f} | {samples / a / 1e6:.3f} | {b:.3f} | {samples / b / 1e6:.3f} | {a / b:.2f} |")
    ma = statistics.median(a for a, _ in rows)
    mb = statistics.median(b for _, b in rows)
    lines.append(f"| median | {ma:.3f} | {samples / ma / 1e6:.3f} | {mb:.3f} | {samples / mb / 1e6:.3f} | {ma / mb:.2f} |")
    base = efficiency[("Mitsuba", "independent")][2]
    lines += ["", "## Efficiency at equal time", "",
              "1 / (relMSE x seconds): seconds the median of the rounds, relMSE of one render estimated from the "
              "two renders of rounds 1 and 2 (seeds 1 and 2), without a reference. Mitsuba's `ldsampler` is its "
              "low-discrepancy sampler; ours `sobol` (the default), Owen-scrambled.", "",
              "| renderer | sampler | seconds | relMSE | efficiency / Mitsuba independent |",
              "|---|---|--:|--:|--:|"]
    for (renderer, sampler), (median, relmse, e) in efficiency.items():
        lines.append(f"| {renderer} | {sampler} | {median:.3f} | {relmse:.4g} | {e / base:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.markdown:
        Path(args.markdown).write_text(text)


if __name__ == "__main__":
    main()
