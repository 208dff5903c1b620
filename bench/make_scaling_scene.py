#!/usr/bin/env python3
"""make_scaling_scene.py -- writes a generated .glb of about N triangles for
the scaling benchmark (bench/throughput.py --scaling): a floor under a square
light, and on it a jittered grid of icospheres (1280 triangles each, every one
its own flattened mesh, none instanced), so the triangle count grows while
the light transport stays the same. Deterministic: the same N gives the same
bytes. Numpy builds the arrays; a 4M-triangle scene takes a few seconds and
about 75 MiB, which is why it is generated where it is used and not stored.

With --instances K, the spheres are one mesh placed by K nodes, side by side
in a square of tiles under one floor and a light as strong as the floor is wide: K times
the triangles placed, for the memory of one (the renderer keeps a mesh that
several nodes place once, host/bvh/instance_bvh.h).

Usage: python3 bench/make_scaling_scene.py TRIANGLES OUT.glb [--instances K]
"""

import argparse
import json
import struct

import numpy as np

SPHERE_SUBDIVISIONS = 3  # 20 * 4^3 = 1280 triangles


def icosphere(subdivisions):
    t = (1.0 + 5.0 ** 0.5) / 2.0
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    vertices = [np.array(v, dtype=np.float64) / np.linalg.norm(v) for v in vertices]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        faces = [f for a, b, c in faces for f in
                 ((a, midpoint(a, b), midpoint(c, a)), (b, midpoint(b, c), midpoint(a, b)),
                  (c, midpoint(c, a), midpoint(b, c)),
                  (midpoint(a, b), midpoint(b, c), midpoint(c, a)))]
    return np.array(vertices, dtype=np.float32), np.array(faces, dtype=np.uint32)


def main():
    parser = argparse.ArgumentParser(description="Write a generated scene for the scaling benchmark.")
    parser.add_argument("triangles", type=int)
    parser.add_argument("out")
    parser.add_argument("--instances", type=int, default=1, help="nodes placing the spheres' mesh (default 1)")
    args = parser.parse_args()
    triangles, out, instances = args.triangles, args.out, args.instances
    sphere_v, sphere_f = icosphere(SPHERE_SUBDIVISIONS)
    count = max(1, round((triangles - 4) / len(sphere_f)))
    side = int(np.ceil(np.sqrt(count)))
    rng = np.random.default_rng(1)
    cells = np.stack(np.meshgrid(np.arange(side), np.arange(side), indexing="ij"), -1).reshape(-1, 2)[:count]
    radius = 0.35 * rng.uniform(0.6, 1.0, count)
    centres = np.zeros((count, 3), dtype=np.float64)
    centres[:, 0] = (cells[:, 0] - (side - 1) / 2) + rng.uniform(-0.1, 0.1, count)
    centres[:, 2] = (cells[:, 1] - (side - 1) / 2) + rng.uniform(-0.1, 0.1, count)
    centres[:, 1] = radius + rng.uniform(0.0, 0.3, count)
    positions = (sphere_v[None, :, :] * radius[:, None, None] + centres[:, None, :]).astype(np.float32)
    indices = (sphere_f[None, :, :] + (np.arange(count) * len(sphere_v))[:, None, None]).astype(np.uint32)
    # The tiles the spheres' mesh is placed on, side by side (one, unmoved, without --instances).
    tiles = int(np.ceil(np.sqrt(instances)))
    pitch = side + 1.0
    offsets = [((i % tiles - (tiles - 1) / 2) * pitch, (i // tiles - (tiles - 1) / 2) * pitch) for i in range(instances)]
    side_placed = side if instances == 1 else tiles * pitch
    half = side_placed / 2 + 1.0
    floor = np.array([[-half, 0, -half], [-half, 0, half], [half, 0, half], [half, 0, -half]], np.float32)
    light_y = 3.0 + side_placed * 0.5
    light = np.array([[-1, light_y, -1], [1, light_y, -1], [1, light_y, 1], [-1, light_y, 1]], np.float32)
    quad = np.array([[0, 1, 2], [0, 2, 3]], np.uint32)

    meshes = [("spheres", positions.reshape(-1, 3), indices.reshape(-1, 3), 0),
              ("floor", floor, quad, 0), ("light", light, quad, 1)]
    blob, views, accessors, gltf_meshes = bytearray(), [], [], []
    for name, p, f, mat in meshes:
        for data, target, kind, ctype in ((p, 34962, "VEC3", 5126), (f, 34963, "SCALAR", 5125)):
            raw = np.ascontiguousarray(data).tobytes()
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(raw), "target": target})
            blob += raw + b"\0" * (-len(raw) % 4)
            accessor = {"bufferView": len(views) - 1, "componentType": ctype,
                        "count": int(data.shape[0] if kind == "VEC3" else data.size), "type": kind}
            if kind == "VEC3":
                accessor["min"] = [float(x) for x in data.min(0)]
                accessor["max"] = [float(x) for x in data.max(0)]
            accessors.append(accessor)
        gltf_meshes.append({"name": name, "primitives": [
            {"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1, "material": mat}]})
    distance = 1.2 * side_placed + 2.0
    sphere_nodes = [{"mesh": 0}] if instances == 1 else \
        [{"mesh": 0, "translation": [float(x), 0.0, float(z)]} for x, z in offsets]
    gltf = {
        "asset": {"version": "2.0", "generator": "wavefront bench/make_scaling_scene.py"},
        "scene": 0, "scenes": [{"nodes": list(range(len(sphere_nodes) + len(meshes)))}],
        "nodes": sphere_nodes + [{"mesh": i} for i in range(1, len(meshes))] +
                 [{"camera": 0, "translation": [0.0, 0.6 * distance, distance],
                   "rotation": [float(-np.sin(0.25)), 0.0, 0.0, float(np.cos(0.25))]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01, "aspectRatio": 1.0}}],
        "meshes": gltf_meshes,
        "materials": [{"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.7, 1.0],
                                                                 "metallicFactor": 0.0, "roughnessFactor": 1.0}},
                      {"name": "light", "emissiveFactor": [1.0, 1.0, 1.0],
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0 * side_placed}}}],
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "buffers": [{"byteLength": len(blob)}], "bufferViews": views, "accessors": accessors,
    }
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    with open(out, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(blob)))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(blob), 0x004E4942) + bytes(blob))
    placed = f", {instances} placements of {count * len(sphere_f)}" if instances > 1 else ""
    print(f"{out}: {instances * count * len(sphere_f) + 4} triangles{placed}")


if __name__ == "__main__":
    main()
