#!/usr/bin/env python3
"""make_cornell_box.py -- writes scenes/cornell-box.gltf: the Cornell box from
its measured data (Cornell Program of Computer Graphics), in millimetres as
measured, with its light, materials and the classic camera. With
--small-light it writes scenes/cornell-box-small-light.gltf instead: the same
box with the light quad shrunk about its centre to a tenth of its width and
depth and its radiance raised 100 times, so it emits the same power from a
hundredth of the area -- the hard case for sampling the light by the BSDF.
With --mirror it writes scenes/cornell-mirror.gltf: the tall block a perfect
mirror (white base colour, metallic 1, roughness 0). With --glass it writes
scenes/cornell-glass.gltf: the blocks removed and a glass sphere on the floor
(transmission 1, ior 1.5, roughness 0, white; KHR_materials_transmission,
KHR_materials_ior, and KHR_materials_volume with the sphere's diameter as its
thickness, so that it is a solid ball, not glTF's thin wall), an icosphere of 4 subdivisions (5120 triangles) with
smooth normals, radius 110 mm, its lowest vertex 0.1 mm above the floor.

It owns the winding of every triangle: the listed corner order of the measured
quads is not trusted but checked against the side each face must face (walls
into the box, the light down, the blocks outward), and reversed where it
disagrees. The output is one self-contained glTF 2.0 file (buffer embedded as
a base64 data URI); running the script again reproduces it byte for byte.

The glTF writing (buffer packing, accessors and bounds, materials, camera,
the checks every file passes before it is written) is scenes/gltf_writer.py's;
scenes/make_teapot.py reuses the box from here.

Usage: python3 scenes/make_cornell_box.py [--small-light | --mirror | --glass]
(from any directory)
"""

import argparse
import math
import os

from gltf_writer import Builder, centroid, facing, icosphere, material, sub, write

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

# The variants' materials: a perfect mirror, and clear glass.
MIRROR = material("mirror", (1.0, 1.0, 1.0), metallic=1.0, roughness=0.0)
GLASS_SPHERE_RADIUS = 110.0
GLASS = material("glass", (1.0, 1.0, 1.0), metallic=0.0, roughness=0.0, transmission=1.0, ior=1.5,
                 thickness=2.0 * GLASS_SPHERE_RADIUS)

# The glass sphere: centred over the floor's middle, a little toward the
# camera; its lowest vertex 0.1 mm above the floor, so the two never touch.
GLASS_SPHERE_CENTRE_XZ = (278.0, 250.0)
GLASS_SPHERE_GAP = 0.1
GLASS_SPHERE_SUBDIVISIONS = 4


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


def scaled_about_centre(quad, factor):
    middle = centroid(quad)
    return [tuple(m + factor * (p - m) for p, m in zip(corner, middle)) for corner in quad]


def room_surfaces(light_scale):
    """(mesh name, material name, triangles) of the empty box and its light."""
    return [
        ("floor", "white", facing(FLOOR, UP)),
        ("ceiling", "white", facing(CEILING, DOWN)),
        ("back_wall", "white", facing(BACK_WALL, INTO_BOX_FROM_BACK)),
        ("right_wall_green", "green", facing(RIGHT_WALL, INTO_BOX_FROM_GREEN)),
        ("left_wall_red", "red", facing(LEFT_WALL, INTO_BOX_FROM_RED)),
        ("light", "light", facing(scaled_about_centre(LIGHT, light_scale), DOWN)),
    ]


def surfaces(light_scale, tall_block_material="white"):
    """(mesh name, material name, triangles) of every surface of the box with
    its two blocks."""
    return room_surfaces(light_scale) + [
        ("short_block", "white", block(SHORT_BLOCK_TOP)),
        ("tall_block", tall_block_material, block(TALL_BLOCK_TOP)),
    ]


def room_materials(light_scale):
    """The diffuse walls and the light, whose radiance over the area's factor
    keeps the emitted power of the measured light."""
    radiance = tuple(c / light_scale**2 for c in light_radiance())
    return [material("white", WHITE), material("red", RED), material("green", GREEN),
            material("light", LIGHT_ALBEDO, emission=radiance)]


def add_camera(builder):
    # glTF cameras look down -Z: half a turn about y makes this one look along +z.
    builder.add_camera("camera", CAMERA_POSITION, [0.0, 1.0, 0.0, 0.0], CAMERA_YFOV, 1.0, 1.0)

# ---------------------------------------------------------------------------
# The glass sphere


def glass_sphere():
    """(positions, normals, triangles) of the glass sphere: an icosphere with
    its exact sphere normals, its lowest vertex GLASS_SPHERE_GAP above the
    floor."""
    directions, faces = icosphere(GLASS_SPHERE_SUBDIVISIONS)
    lowest = min(d[1] for d in directions)
    x, z = GLASS_SPHERE_CENTRE_XZ
    centre = (x, GLASS_SPHERE_GAP - GLASS_SPHERE_RADIUS * lowest, z)
    positions = [tuple(c + GLASS_SPHERE_RADIUS * d for c, d in zip(centre, direction))
                 for direction in directions]
    return positions, directions, faces

# ---------------------------------------------------------------------------
# glTF


VARIANTS = {
    # option: (output, light scale, what replaces the blocks)
    None: ("cornell-box.gltf", FULL_LIGHT, "blocks"),
    "--small-light": ("cornell-box-small-light.gltf", SMALL_LIGHT, "blocks"),
    "--mirror": ("cornell-mirror.gltf", FULL_LIGHT, "mirror"),
    "--glass": ("cornell-glass.gltf", FULL_LIGHT, "glass"),
}


def build_gltf(variant):
    _, light_scale, contents = VARIANTS[variant]
    generator = "scenes/make_cornell_box.py" + (" " + variant if variant else "")
    materials = room_materials(light_scale)
    if contents == "mirror":
        materials.append(MIRROR)
    if contents == "glass":
        materials.append(GLASS)
    builder = Builder(materials)
    if contents == "glass":
        for name, material_name, triangles in room_surfaces(light_scale):
            builder.add_flat_mesh(name, material_name, triangles)
        builder.add_mesh("glass_sphere", "glass", *glass_sphere())
    else:
        tall = "mirror" if contents == "mirror" else "white"
        for name, material_name, triangles in surfaces(light_scale, tall):
            builder.add_flat_mesh(name, material_name, triangles)
    add_camera(builder)
    return builder.document(generator, "cornell_box")


def main():
    parser = argparse.ArgumentParser(description="Write the Cornell box as glTF.")
    options = parser.add_mutually_exclusive_group()
    options.add_argument("--small-light", action="store_true",
                         help="write cornell-box-small-light.gltf: a light of 1/100 the area, 100 times as bright")
    options.add_argument("--mirror", action="store_true",
                         help="write cornell-mirror.gltf: the tall block a perfect mirror")
    options.add_argument("--glass", action="store_true",
                         help="write cornell-glass.gltf: no blocks, a glass sphere on the floor")
    args = parser.parse_args()
    variant = next((v for v in VARIANTS if v and getattr(args, v[2:].replace("-", "_"))), None)
    output = os.path.join(SCENES_DIR, VARIANTS[variant][0])
    summary = write(output, build_gltf(variant))
    print(f"wrote {output}: {summary['triangles']} triangles")


if __name__ == "__main__":
    main()
