#!/usr/bin/env python3
"""make_cornell_box.py -- writes scenes/cornell-box.gltf: the Cornell box from
its measured data (Cornell Program of Computer Graphics), in millimetres as
measured, with its light, materials and the classic camera. With
--small-light it writes scenes/cornell-box-small-light.gltf instead: the same
box with the light quad shrunk about its centre to a tenth of its width and
depth and its radiance raised 100 times, so it emits the same power from a
hundredth of the area -- the hard case for sampling the light by the BSDF.

It owns the winding of every triangle: the listed corner order of the measured
quads is not trusted but checked against the side each face must face (walls
into the box, the light down, the blocks outward), and reversed where it
disagrees. The output is one self-contained glTF 2.0 file (buffer embedded as
a base64 data URI); running the script again reproduces it byte for byte.

Usage: python3 scenes/make_cornell_box.py [--small-light]   (from any directory)
"""

import argparse
import base64
import json
import math
import os
import struct

SCENES_DIR = os.path.dirname(os.path.abspath(__file__))
# The light's side length relative to the measured one, as each output has it.
FULL_LIGHT, SMALL_LIGHT = 1.0, 0.1

# ---------------------------------------------------------------------------
# Measured data (mm). x runs from the green wall (x = 0) to the red one,
# y up, z from the open front (z = 0) to the back wall.

FLOOR = [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]
CEILING = [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)]
BACK_WALL = [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)]
RIGHT_WALL = [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]
LEFT_WALL = [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]
# 0.1 mm below the ceiling, so the two never share a plane.
LIGHT = [(343, 548.7, 227), (343, 548.7, 332), (213, 548.7, 332), (213, 548.7, 227)]
SHORT_BLOCK_TOP = [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)]
TALL_BLOCK_TOP = [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)]

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT_ALBEDO = (0.78, 0.78, 0.78)


def light_radiance():
    """The measured emission spectrum folded into RGB."""
    terms = [(8.0, (0.805, 1.005, 0.747)), (15.6, (1.027, 0.900, 0.740)),
             (18.4, (1.379, 0.896, 0.737))]
    return tuple(sum(weight * rgb[c] for weight, rgb in terms) for c in range(3))


CAMERA_POSITION = (278.0, 273.0, -800.0)
CAMERA_YFOV = math.radians(39.3)

# Where front faces must point.
UP, DOWN = (0, 1, 0), (0, -1, 0)
INTO_BOX_FROM_BACK, INTO_BOX_FROM_GREEN, INTO_BOX_FROM_RED = (0, 0, -1), (1, 0, 0), (-1, 0, 0)

# ---------------------------------------------------------------------------
# Geometry


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    length = math.sqrt(dot(v, v))
    return tuple(x / length for x in v)


def centroid(points):
    return tuple(sum(p[c] for p in points) / len(points) for c in range(3))


def front_normal(triangle):
    """Unnormalized normal of the counter-clockwise (front) side."""
    a, b, c = triangle
    return cross(sub(b, a), sub(c, a))


def facing(quad, toward):
    """Quad a-b-c-d as triangles (a,b,c), (a,c,d) whose front faces lie along
    `toward`; the corner order is reversed where the listed one faces away."""
    if dot(front_normal(quad[:3]), toward) < 0:
        quad = quad[::-1]
    a, b, c, d = quad
    triangles = [(a, b, c), (a, c, d)]
    for triangle in triangles:
        assert dot(front_normal(triangle), toward) > 0, (quad, toward)
    return triangles


def block(top):
    """A block standing on the floor: its top and four sides, facing outward."""
    bottom = [(x, 0.0, z) for x, _, z in top]
    middle = centroid(top + bottom)
    triangles = facing(top, UP)
    for i in range(4):
        j = (i + 1) % 4
        side = [top[i], top[j], bottom[j], bottom[i]]
        triangles += facing(side, sub(centroid(side), middle))
    return triangles


def scaled_about_centre(quad, scale):
    middle = centroid(quad)
    return [tuple(m + scale * (p - m) for p, m in zip(corner, middle)) for corner in quad]


def surfaces(light_scale):
    """(mesh name, material name, triangles) of every surface."""
    return [
        ("floor", "white", facing(FLOOR, UP)),
        ("ceiling", "white", facing(CEILING, DOWN)),
        ("back_wall", "white", facing(BACK_WALL, INTO_BOX_FROM_BACK)),
        ("right_wall_green", "green", facing(RIGHT_WALL, INTO_BOX_FROM_GREEN)),
        ("left_wall_red", "red", facing(LEFT_WALL, INTO_BOX_FROM_RED)),
        ("light", "light", facing(scaled_about_centre(LIGHT, light_scale), DOWN)),
        ("short_block", "white", block(SHORT_BLOCK_TOP)),
        ("tall_block", "white", block(TALL_BLOCK_TOP)),
    ]

# ---------------------------------------------------------------------------
# glTF


def as_float32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def material(name, albedo, emission=None):
    entry = {
        "name": name,
        "pbrMetallicRoughness": {
            "baseColorFactor": list(albedo) + [1.0],
            "metallicFactor": 0.0,
            "roughnessFactor": 1.0,
        },
    }
    if emission is not None:
        # The factor stays in [0, 1] as glTF requires; the strength carries the scale.
        strength = max(emission)
        entry["emissiveFactor"] = [c / strength for c in emission]
        entry["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
    return entry


def build_gltf(light_scale, generator):
    # Radiance over the area's factor keeps the emitted power of the measured light.
    radiance = tuple(c / light_scale**2 for c in light_radiance())
    materials = [material("white", WHITE), material("red", RED), material("green", GREEN),
                 material("light", LIGHT_ALBEDO, radiance)]
    material_index = {m["name"]: i for i, m in enumerate(materials)}

    blob = bytearray()
    buffer_views, accessors, meshes, nodes = [], [], [], []

    def add_vec3_accessor(vectors, with_bounds):
        buffer_views.append({"buffer": 0, "byteOffset": len(blob),
                             "byteLength": 12 * len(vectors), "target": 34962})
        for v in vectors:
            blob.extend(struct.pack("<3f", *v))
        accessor = {"bufferView": len(buffer_views) - 1, "componentType": 5126,
                    "count": len(vectors), "type": "VEC3"}
        if with_bounds:
            accessor["min"] = [min(as_float32(v[c]) for v in vectors) for c in range(3)]
            accessor["max"] = [max(as_float32(v[c]) for v in vectors) for c in range(3)]
        accessors.append(accessor)
        return len(accessors) - 1

    for name, material_name, triangles in surfaces(light_scale):
        # Three vertices per triangle, so each carries its triangle's flat normal.
        positions = [corner for triangle in triangles for corner in triangle]
        normals = [normalize(front_normal(t)) for t in triangles for _ in range(3)]
        primitive = {
            "attributes": {"POSITION": add_vec3_accessor(positions, True),
                           "NORMAL": add_vec3_accessor(normals, False)},
            "material": material_index[material_name],
        }
        meshes.append({"name": name, "primitives": [primitive]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    # glTF cameras look down -Z: half a turn about y makes this one look along +z.
    nodes.append({"name": "camera", "camera": 0, "translation": list(CAMERA_POSITION),
                  "rotation": [0.0, 1.0, 0.0, 0.0]})

    return {
        "asset": {"version": "2.0", "generator": generator},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "cornell_box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "camera", "type": "perspective",
                     "perspective": {"yfov": CAMERA_YFOV, "aspectRatio": 1.0, "znear": 1.0}}],
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": buffer_views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64,"
                            + base64.b64encode(bytes(blob)).decode("ascii")}],
    }


def main():
    parser = argparse.ArgumentParser(description="Write the Cornell box as glTF.")
    parser.add_argument("--small-light", action="store_true",
                        help="write cornell-box-small-light.gltf: a light of 1/100 the area, 100 times as bright")
    args = parser.parse_args()
    name, light_scale, generator = "cornell-box.gltf", FULL_LIGHT, "scenes/make_cornell_box.py"
    if args.small_light:
        name, light_scale = "cornell-box-small-light.gltf", SMALL_LIGHT
        generator += " --small-light"
    output = os.path.join(SCENES_DIR, name)
    with open(output, "w", encoding="ascii", newline="\n") as out:
        json.dump(build_gltf(light_scale, generator), out, indent=1)
        out.write("\n")
    triangles = sum(len(t) for _, _, t in surfaces(light_scale))
    print(f"wrote {output}: {triangles} triangles")


if __name__ == "__main__":
    main()
