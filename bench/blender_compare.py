#!/usr/bin/env python3
"""blender_compare.py -- render one glTF file with this renderer and with Blender's
Cycles, and compare the two linear EXR images on the image mean and on patches.

Blender imports the file with its own glTF importer and renders it with Cycles on the
CPU, set to estimate the same integral as `wavefront render`: the glTF camera, a
one-pixel box filter (Cycles' BOX at width 1 averages over the pixel as wavefront
does; its minimum width, 0.01, would point-sample the centre), no denoising, no adaptive sampling, no clamping, no glossy
filter, no light threshold, 1024 bounces of every kind, an opaque film and a black
world (or uniform radiance L with --env-uniform L, or 1 where the scene has no light,
as wavefront does). Lights are imported in the 'COMPAT' lighting mode, which reads
candela as W/sr and lux as W/m^2 as wavefront does ('SPEC' divides by 683 lm/W, 'RAW'
drops the 4 pi of point and spot lights); punctual lights are made points (radius 0,
no soft falloff, sun angle 0). Emissive factor x KHR_materials_emissive_strength is
the Emission Strength either way; unless a material is doubleSided its emission is
masked to the front face, since Cycles emits from both.

The table gives, for the image and for each patch (given with --patch x0,y0,x1,y1, in
pixels, y down, end exclusive, plus a 4x4 grid over the image), the mean of the
channel average in each render, their ratio ours/Blender with a standard error, and
the ratio per channel. The standard error is the delta-method estimate
std(a - r b) / (sqrt(n) mean(b)) over the n pixels of the patch. It is rough, and
rather too large than too small: it treats pixels as independent, which Cycles'
blue-noise sampler makes them not, and it counts as noise any real change of the
ratio across the patch (as on the whole image, where walls and light differ).

Not part of CI or the test suite. It needs Blender as a Python module (bpy 5.0.1
wants Python 3.11), in a virtual environment outside the repository:

    python3.11 -m venv /work/venv-bpy
    /work/venv-bpy/bin/pip install bpy==5.0.1 numpy OpenEXR

and runs under that interpreter, for example:

    nice -n 10 /work/venv-bpy/bin/python bench/blender_compare.py scenes/cornell-box.gltf \\
        --width 128 --height 128 --spp 256 --patch 40,30,88,60 --markdown out.md
"""

import argparse
import json
import shlex
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import OpenEXR

REPO = Path(__file__).resolve().parents[1]


def gltf_document(path):
    """The JSON of a .gltf file, or the JSON chunk of a .glb file."""
    data = path.read_bytes()
    if data[:4] != b"glTF":
        return json.loads(data)
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A, "the first chunk of a .glb file must be JSON"
    return json.loads(data[20:20 + length])


def default_camera(doc):
    """wavefront's default: the first perspective camera met walking the scene's nodes."""
    nodes = doc.get("nodes", [])
    stack = list(reversed(doc["scenes"][doc.get("scene", 0)]["nodes"]))
    while stack:
        node = nodes[stack.pop()]
        if "camera" in node and doc["cameras"][node["camera"]]["type"] == "perspective":
            return node["camera"]
        stack.extend(reversed(node.get("children", [])))
    sys.exit("the scene places no perspective camera; pass --camera N")


def has_light(doc):
    """Whether the file has an emissive material or a punctual light."""
    lights = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    for material in doc.get("materials", []):
        strength = material.get("extensions", {}).get(
            "KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
        if strength > 0 and any(material.get("emissiveFactor", [0, 0, 0])):
            return True
    return bool(lights)


def one_sided_emission(material):
    """Cycles emits from both faces; glTF (and wavefront) only from the front unless
    doubleSided, which the importer keeps as use_backface_culling = False."""
    nodes, links = material.node_tree.nodes, material.node_tree.links
    for bsdf in [n for n in nodes if n.type == "BSDF_PRINCIPLED"]:
        strength = bsdf.inputs["Emission Strength"]
        if strength.is_linked or strength.default_value == 0.0:
            continue
        front = nodes.new("ShaderNodeMath")
        front.operation = "SUBTRACT"
        front.inputs[0].default_value = 1.0
        links.new(nodes.new("ShaderNodeNewGeometry").outputs["Backfacing"], front.inputs[1])
        scaled = nodes.new("ShaderNodeMath")
        scaled.operation = "MULTIPLY"
        scaled.inputs[0].default_value = strength.default_value
        links.new(front.outputs[0], scaled.inputs[1])
        links.new(scaled.outputs[0], strength)


def render_blender(gltf, out, args, camera_name, world_radiance):
    import bpy

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=str(gltf), export_import_convert_lighting_mode="COMPAT")
    scene = bpy.context.scene

    cameras = [o for o in scene.objects if o.type == "CAMERA"
               and (o.data.name == camera_name or o.data.name.startswith(camera_name + "."))]
    if len(cameras) != 1:
        sys.exit(f"{len(cameras)} imported cameras are named '{camera_name}'; need one")
    scene.camera = cameras[0]

    for material in bpy.data.materials:
        if material.use_backface_culling and material.node_tree:
            one_sided_emission(material)
    for light in bpy.data.lights:
        if light.type in ("POINT", "SPOT"):
            light.shadow_soft_size = 0.0
            light.use_soft_falloff = False
        elif light.type == "SUN":
            light.angle = 0.0

    scene.world = bpy.data.worlds.new("uniform")
    background = scene.world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (world_radiance,) * 3 + (1.0,)
    background.inputs["Strength"].default_value = 1.0

    render, cycles = scene.render, scene.cycles
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = args.width, args.height
    render.resolution_percentage = 100
    render.film_transparent = False
    cycles.device = "CPU"
    cycles.samples = args.spp
    cycles.seed = args.seed
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    for bounces in ("max_bounces", "diffuse_bounces", "glossy_bounces",
                    "transmission_bounces", "transparent_max_bounces"):
        setattr(cycles, bounces, 1024)
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.caustics_reflective = cycles.caustics_refractive = True
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0

    image = render.image_settings
    image.file_format = "OPEN_EXR"
    image.color_depth = "32"
    image.color_mode = "RGB"
    render.filepath = str(out)
    bpy.ops.render.render(write_still=True)
    return bpy.app.version_string


def render_wavefront(gltf, out, args):
    command = [str(args.wavefront), "render", str(gltf), "-o", str(out),
               "--width", str(args.width), "--height", str(args.height),
               "--spp", str(args.spp), "--seed", str(args.seed), "--quiet"]
    if args.camera is not None:
        command += ["--camera", str(args.camera)]
    if args.env_uniform is not None:
        command += ["--env-uniform", str(args.env_uniform)]
    log = out.with_suffix(".log")
    with log.open("w") as f:
        if subprocess.run(command, stdout=f, stderr=subprocess.STDOUT).returncode:
            sys.exit(f"wavefront failed; see {log}")
    return shlex.join(command)


def read_rgb(path):
    """An EXR's RGB channels as a float64 array of shape (height, width, 3), top row first."""
    with OpenEXR.File(str(path)) as f:
        channels = f.channels()
        for name in ("RGB", "RGBA"):
            if name in channels:
                return channels[name].pixels[..., :3].astype(np.float64)
        return np.stack([channels[c].pixels for c in "RGB"], axis=-1).astype(np.float64)


def compare(ours, theirs, name, box):
    x0, y0, x1, y1 = box
    a, b = ours[y0:y1, x0:x1].reshape(-1, 3), theirs[y0:y1, x0:x1].reshape(-1, 3)
    grey_a, grey_b = a.mean(axis=1), b.mean(axis=1)
    ratio = grey_a.mean() / grey_b.mean()
    se = np.std(grey_a - ratio * grey_b, ddof=1) / np.sqrt(len(grey_a)) / grey_b.mean()
    with np.errstate(divide="ignore", invalid="ignore"):
        per_channel = a.mean(axis=0) / b.mean(axis=0)
    return dict(name=name, box=box, ours=grey_a.mean(), blender=grey_b.mean(), ratio=ratio,
                se=se, channels=per_channel, ours_rgb=a.mean(axis=0), blender_rgb=b.mean(axis=0))


def grid(width, height, cells=4):
    xs = [round(i * width / cells) for i in range(cells + 1)]
    ys = [round(j * height / cells) for j in range(cells + 1)]
    return [(f"grid {j},{i}", (xs[i], ys[j], xs[i + 1], ys[j + 1]))
            for j in range(cells) for i in range(cells)]


def table(rows):
    header = ("| region | x0,y0,x1,y1 | ours | Blender | ratio | ± se | R | G | B |\n"
              "|---|---|--:|--:|--:|--:|--:|--:|--:|\n")
    return header + "".join(
        f"| {r['name']} | {','.join(map(str, r['box']))} | {r['ours']:.4f} | {r['blender']:.4f}"
        f" | {r['ratio']:.4f} | {r['se']:.4f} | "
        + " | ".join(f"{c:.4f}" for c in r["channels"]) + " |\n" for r in rows)


def patch(text):
    box = tuple(int(v) for v in text.split(","))
    if len(box) != 4 or box[0] >= box[2] or box[1] >= box[3]:
        raise argparse.ArgumentTypeError("a patch is x0,y0,x1,y1 with x0 < x1 and y0 < y1")
    return box


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("gltf", type=Path)
    p.add_argument("--width", type=int, default=128)
    p.add_argument("--height", type=int, default=128)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--camera", type=int, help="glTF camera index (default: wavefront's choice)")
    p.add_argument("--env-uniform", type=float, metavar="L",
                   help="uniform environment radiance L in both renderers")
    p.add_argument("--patch", type=patch, action="append", default=[],
                   metavar="x0,y0,x1,y1", help="a patch to compare (repeatable)")
    p.add_argument("--wavefront", type=Path, default=REPO / "build" / "wavefront")
    p.add_argument("--out-dir", type=Path, help="where the EXRs go (default: a new temp dir)")
    p.add_argument("--compare-only", action="store_true",
                   help="compare ours.exr and blender.exr already in --out-dir")
    p.add_argument("--markdown", type=Path, help="also write the table here")
    args = p.parse_args()

    gltf = args.gltf.resolve()
    doc = gltf_document(gltf)
    camera = args.camera if args.camera is not None else default_camera(doc)
    camera_name = doc["cameras"][camera].get("name") or "Camera"
    world = args.env_uniform if args.env_uniform is not None else (
        0.0 if has_light(doc) else 1.0)
    out_dir = args.out_dir or Path(tempfile.mkdtemp(prefix="blender-compare-"))
    out_dir.mkdir(parents=True, exist_ok=True)
    ours_exr, blender_exr = out_dir / "ours.exr", out_dir / "blender.exr"

    if args.compare_only:
        command, blender_version = "(not rerun)", "(not rerun)"
    else:
        command = render_wavefront(gltf, ours_exr, args)
        blender_version = render_blender(gltf, blender_exr, args, camera_name, world)
    ours, theirs = read_rgb(ours_exr), read_rgb(blender_exr)
    if ours.shape != theirs.shape:
        sys.exit(f"image sizes differ: {ours.shape} and {theirs.shape}")

    h, w = ours.shape[:2]
    rows = [compare(ours, theirs, "image", (0, 0, w, h))]
    rows += [compare(ours, theirs, f"patch {i}", box) for i, box in enumerate(args.patch)]
    rows += [compare(ours, theirs, name, box) for name, box in grid(w, h)]
    image = rows[0]
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    summary = (f"scene `{args.gltf}`, {w}x{h}, {args.spp} spp, camera {camera} "
               f"('{camera_name}'), world radiance {world:g}; repository at {commit}, "
               f"Blender {blender_version}\n\n"
               f"wavefront: `{command}`\n\n"
               f"image mean RGB: ours {np.array2string(image['ours_rgb'], precision=4)}, "
               f"Blender {np.array2string(image['blender_rgb'], precision=4)}\n\n"
               "ratio = ours / Blender of the channel average; se from the per-pixel "
               "scatter, assuming independent pixels (rough)\n\n")
    print(summary + table(rows))
    print(f"images in {out_dir}")
    if args.markdown:
        args.markdown.write_text(summary + table(rows))


if __name__ == "__main__":
    main()
