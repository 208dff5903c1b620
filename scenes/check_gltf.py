#!/usr/bin/env python3
"""check_gltf.py -- checks the glTF files the generators in scenes/ write
(embedded buffers, triangle lists, no node transforms on meshes), and prints
each one's triangle count and bounds. Every generator runs check() on its
document before writing it; run this on the files to check them as stored.

What it checks: the JSON parses; buffers decode to their byteLength; buffer
views lie inside their buffer and start 4-byte aligned; accessors fit their
views, and POSITION and index accessors carry min/max equal to the data;
positions and normals are finite; normals are unit length (within 1e-5);
indices are in range; every triangle has non-zero area (relative to the
scene's size); each triangle's winding agrees with its vertex normals (the
geometric normal lies on the side the normals point to); material factors lie
in their glTF ranges; every extension a material uses is in extensionsUsed,
and every name there is used; node references resolve; camera rotations are
unit quaternions.

Usage: python3 scenes/check_gltf.py FILE.gltf [...]   (exit status 1 on failure)
"""

import base64
import json
import math
import struct
import sys

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
FORMATS = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}
# A triangle's doubled area must exceed this times the square of the scene's extent.
MIN_RELATIVE_AREA = 1e-12
UNIT_TOLERANCE = 1e-5


class CheckError(Exception):
    pass


def require(condition, message):
    if not condition:
        raise CheckError(message)


def decode_buffers(gltf):
    buffers = []
    for i, buffer in enumerate(gltf["buffers"]):
        prefix = "data:application/octet-stream;base64,"
        require(buffer.get("uri", "").startswith(prefix), f"buffer {i}: not an embedded data URI")
        data = base64.b64decode(buffer["uri"][len(prefix):], validate=True)
        require(len(data) == buffer["byteLength"],
                f"buffer {i}: {len(data)} bytes, byteLength says {buffer['byteLength']}")
        buffers.append(data)
    return buffers


def read_accessor(gltf, buffers, index):
    accessor = gltf["accessors"][index]
    view = gltf["bufferViews"][accessor["bufferView"]]
    data = buffers[view["buffer"]]
    require(view["byteOffset"] % 4 == 0, f"bufferView {accessor['bufferView']}: not 4-byte aligned")
    require(view["byteOffset"] + view["byteLength"] <= len(data),
            f"bufferView {accessor['bufferView']}: runs past its buffer")
    require("byteStride" not in view, f"bufferView {accessor['bufferView']}: byteStride unsupported here")
    fmt = FORMATS[accessor["componentType"]]
    n = COMPONENTS[accessor["type"]]
    count = accessor["count"]
    size = struct.calcsize("<" + fmt) * n * count
    start = view["byteOffset"] + accessor.get("byteOffset", 0)
    require(start + size <= view["byteOffset"] + view["byteLength"],
            f"accessor {index}: {count} elements do not fit bufferView {accessor['bufferView']}")
    values = struct.unpack_from(f"<{n * count}{fmt}", data, start)
    rows = [tuple(values[k * n:(k + 1) * n]) for k in range(count)]
    for row in rows:
        require(all(math.isfinite(x) for x in row), f"accessor {index}: NaN or infinite value")
    if "min" in accessor or "max" in accessor:
        require([min(r[c] for r in rows) for c in range(n)] == accessor.get("min"),
                f"accessor {index}: min {accessor.get('min')} is not the data's")
        require([max(r[c] for r in rows) for c in range(n)] == accessor.get("max"),
                f"accessor {index}: max {accessor.get('max')} is not the data's")
    return rows


def check_material(i, m, used):
    where = f"material {i} ({m.get('name')})"
    pbr = m.get("pbrMetallicRoughness", {})
    require(all(0.0 <= c <= 1.0 for c in pbr.get("baseColorFactor", [1.0] * 4)), where + ": baseColorFactor")
    require(len(pbr.get("baseColorFactor", [1.0] * 4)) == 4, where + ": baseColorFactor needs 4 entries")
    for key in ("metallicFactor", "roughnessFactor"):
        require(0.0 <= pbr.get(key, 1.0) <= 1.0, f"{where}: {key}")
    require(all(0.0 <= c <= 1.0 for c in m.get("emissiveFactor", [0.0] * 3)), where + ": emissiveFactor")
    extensions = m.get("extensions", {})
    for name in extensions:
        require(name in used, f"{where}: {name} is not listed in extensionsUsed")
    if "KHR_materials_emissive_strength" in extensions:
        require(extensions["KHR_materials_emissive_strength"]["emissiveStrength"] > 0, where + ": emissiveStrength")
        require(max(m["emissiveFactor"]) > 0, where + ": emissive strength without an emissiveFactor")
    if "KHR_materials_transmission" in extensions:
        require(0.0 <= extensions["KHR_materials_transmission"]["transmissionFactor"] <= 1.0,
                where + ": transmissionFactor")
    if "KHR_materials_ior" in extensions:
        require(extensions["KHR_materials_ior"]["ior"] >= 1.0, where + ": ior below 1")
    return set(extensions)


def check(gltf):
    """Raises CheckError on the first fault; returns {"triangles", "min", "max"}."""
    gltf = json.loads(json.dumps(gltf, allow_nan=False))  # JSON as written, NaN refused
    require(gltf["asset"]["version"] == "2.0", "asset.version is not 2.0")
    used = set(gltf.get("extensionsUsed", []))
    require(len(used) == len(gltf.get("extensionsUsed", [])), "extensionsUsed repeats a name")
    require(not gltf.get("extensionsRequired"), "extensionsRequired would make loaders refuse the file")
    found = set()
    for i, m in enumerate(gltf.get("materials", [])):
        found |= check_material(i, m, used)
    require(found == used, f"extensionsUsed lists unused names: {sorted(used - found)}")
    buffers = decode_buffers(gltf)

    nodes = gltf["nodes"]
    for index in gltf["scenes"][gltf["scene"]]["nodes"]:
        require(0 <= index < len(nodes), f"scene node {index} does not exist")
    triangles = []  # (corners, vertex normals) in world space
    for n, node in enumerate(nodes):
        if "camera" in node:
            require(0 <= node["camera"] < len(gltf["cameras"]), f"node {n}: no camera {node['camera']}")
            q = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
            require(abs(math.sqrt(sum(x * x for x in q)) - 1.0) < UNIT_TOLERANCE, f"node {n}: rotation not unit")
            perspective = gltf["cameras"][node["camera"]]["perspective"]
            require(0 < perspective["yfov"] < math.pi and perspective["znear"] > 0, f"node {n}: camera")
        if "mesh" not in node:
            continue
        require(not any(k in node for k in ("matrix", "translation", "rotation", "scale", "children")),
                f"node {n}: mesh nodes carry no transform here")
        mesh = gltf["meshes"][node["mesh"]]
        for primitive in mesh["primitives"]:
            where = f"mesh '{mesh.get('name')}'"
            require(primitive.get("mode", 4) == 4, where + ": not a triangle list")
            require(0 <= primitive["material"] < len(gltf["materials"]), where + ": no such material")
            positions = read_accessor(gltf, buffers, primitive["attributes"]["POSITION"])
            require("min" in gltf["accessors"][primitive["attributes"]["POSITION"]], where + ": POSITION lacks min/max")
            normals = read_accessor(gltf, buffers, primitive["attributes"]["NORMAL"])
            require(len(normals) == len(positions), where + ": NORMAL and POSITION counts differ")
            for k, v in enumerate(normals):
                require(abs(math.sqrt(sum(x * x for x in v)) - 1.0) < UNIT_TOLERANCE,
                        f"{where}: normal {k} has length {math.sqrt(sum(x * x for x in v))}")
            if "indices" in primitive:
                require("min" in gltf["accessors"][primitive["indices"]], where + ": indices lack min/max")
                indices = [row[0] for row in read_accessor(gltf, buffers, primitive["indices"])]
                require(all(0 <= i < len(positions) for i in indices), where + ": index out of range")
            else:
                indices = list(range(len(positions)))
            require(len(indices) % 3 == 0, where + ": vertex count not a multiple of 3")
            for t in range(0, len(indices), 3):
                corners = [indices[t + j] for j in range(3)]
                triangles.append((where, t // 3, [positions[i] for i in corners], [normals[i] for i in corners]))

    require(triangles, "no triangles")
    lo = [min(p[c] for _, _, ps, _ in triangles for p in ps) for c in range(3)]
    hi = [max(p[c] for _, _, ps, _ in triangles for p in ps) for c in range(3)]
    extent = max(h - l for l, h in zip(lo, hi))
    for where, t, (a, b, c), ns in triangles:
        e1 = [b[k] - a[k] for k in range(3)]
        e2 = [c[k] - a[k] for k in range(3)]
        g = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        doubled_area = math.sqrt(sum(x * x for x in g))
        require(doubled_area > MIN_RELATIVE_AREA * extent * extent, f"{where}: triangle {t} has zero area")
        mean_normal = [sum(n[k] for n in ns) for k in range(3)]
        require(sum(g[k] * mean_normal[k] for k in range(3)) > 0,
                f"{where}: triangle {t} winds against its normals")
    return {"triangles": len(triangles), "min": lo, "max": hi}


def main():
    failed = False
    for path in sys.argv[1:]:
        try:
            with open(path, encoding="utf-8") as f:
                summary = check(json.load(f))
            lo = ", ".join(f"{x:.4g}" for x in summary["min"])
            hi = ", ".join(f"{x:.4g}" for x in summary["max"])
            print(f"{path}: ok, {summary['triangles']} triangles, bounds ({lo}) .. ({hi})")
        except (CheckError, KeyError, ValueError, IndexError) as error:
            print(f"{path}: FAILED: {error!r}")
            failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
