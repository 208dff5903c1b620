#!/usr/bin/env python3
"""make_veach_mis.py -- writes scenes/veach-mis.gltf: Veach's multiple
importance sampling scene (thesis fig. 9.4, pbrt's "veach-mis"), laid out
afresh here from the reflection law rather than copied from a mesh.

Units are arbitrary (call them metres); y up; the camera looks along -z.

Lights: four spheres in a row at y = 0, z = 0, x = -3.75, -1.25, 1.25, 3.75,
radii 1/30, 0.1, 0.3, 0.9. Each radiance is 1/r^2 (900, 100, 11.11, 1.235),
so all four emit the same power, 4 pi^2 * L r^2 = 4 pi^2 (the tessellated
area is the same fraction of the sphere's for each, as they are one mesh
scaled). Each is an icosphere of 3 subdivisions (1280 flat triangles facing
outward). A fill light -- a sphere of radius 0.5 and radiance 100 at
(10, 10, 4), far up and to the side -- lights the backdrop dimly. All white.

Plates: four thin metal slabs (8 long in x, 0.8 deep, 0.05 thick), metallic 1,
base colour grey 0.7, stepping up and back from the camera towards the
lights. Plate k (0 nearest) is centred at PLATE_CENTRES[k] -- (0, -2.9, 3.8),
(0, -2.6, 2.75), (0, -2.3, 1.8), (0, -2.0, 0.95); a shallow stair, so the
way from each plate up to the lights passes over the plates behind it -- and
tilted about
the x axis so its normal is the half vector between the directions from its
centre to the camera and to the middle of the light row: each plate mirrors
the row of lights to the camera, and since the lights lie along x, which the
tilt leaves alone, every light's highlight falls on every plate. The normals
tip towards the camera by 6.9, 11.4, 17.0 and 24.4 degrees from vertical,
nearest first. The script
asserts it: the mirror point of each light's centre on each plate lies on
the plate, with the camera and that light both in sight from it (no other
plate in the way), and inside the picture. Roughness (glTF, alpha =
roughness^2) rises towards the camera as in Veach's figure: far plate 0.03,
then 0.1, 0.2, near plate 0.35 -- so the far plate shows four small sharp
highlights and the near one four broad ones.

Backdrop: a dark diffuse floor (y = -4) and back wall (z = -3), albedo 0.2.

Camera: at (0, 2, 15) looking at (0, -1.5, 2.5), vertical field of view 28
degrees, aspect 3:2 (768 x 512 in the original).

The file passes scenes/check_gltf.py's checks before it is written; running
the script again reproduces it byte for byte.

Usage: python3 scenes/make_veach_mis.py   (from any directory)
"""

import math
import os

from gltf_writer import (Builder, add, box, cross, dot, facing, icosphere, look_at_rotation, material,
                         normalize, scale, sub, write)

SCENES_DIR = os.path.dirname(os.path.abspath(__file__))
OUTPUT = os.path.join(SCENES_DIR, "veach-mis.gltf")

LIGHT_XS = (-3.75, -1.25, 1.25, 3.75)
LIGHT_RADII = (1.0 / 30.0, 0.1, 0.3, 0.9)
LIGHT_SUBDIVISIONS = 3
FILL_CENTRE, FILL_RADIUS, FILL_RADIANCE = (10.0, 10.0, 4.0), 0.5, 100.0

PLATE_CENTRES = ((0.0, -2.9, 3.8), (0.0, -2.6, 2.75), (0.0, -2.3, 1.8), (0.0, -2.0, 0.95))
PLATE_ROUGHNESS = (0.35, 0.2, 0.1, 0.03)  # nearest first
PLATE_LENGTH, PLATE_DEPTH, PLATE_THICKNESS = 8.0, 0.8, 0.05
PLATE_COLOUR = (0.7, 0.7, 0.7)

FLOOR_Y, BACK_WALL_Z, BACKDROP_HALF_WIDTH, BACKDROP_TOP, BACKDROP_FRONT = -4.0, -3.0, 14.0, 12.0, 16.0
BACKDROP_ALBEDO = (0.2, 0.2, 0.2)

CAMERA_POSITION, CAMERA_TARGET = (0.0, 2.0, 15.0), (0.0, -1.5, 2.5)
CAMERA_YFOV, CAMERA_ASPECT = math.radians(28.0), 1.5

LIGHT_ROW_MIDDLE = (0.0, 0.0, 0.0)

# ---------------------------------------------------------------------------
# Geometry


def plate_frame(centre):
    """(normal, depth direction) of a plate: the normal halves the angle
    between the camera and the middle of the light row; the depth direction
    is perpendicular to it and to x."""
    normal = normalize(add(normalize(sub(CAMERA_POSITION, centre)),
                           normalize(sub(LIGHT_ROW_MIDDLE, centre))))
    return normal, normalize(cross((1.0, 0.0, 0.0), normal))


def plate_triangles(centre):
    normal, depth = plate_frame(centre)
    top = add(centre, scale(normal, PLATE_THICKNESS / 2))  # the reflecting face is flush with `centre` + t/2

    def corner(i, j, k):
        return add(add(add(top, (PLATE_LENGTH * (i - 0.5), 0.0, 0.0)),
                       scale(depth, PLATE_DEPTH * (j - 0.5))),
                   scale(normal, -PLATE_THICKNESS * k))
    return box(corner)


def sphere_triangles(centre, radius):
    directions, faces = icosphere(LIGHT_SUBDIVISIONS)
    return [tuple(add(centre, scale(directions[i], radius)) for i in face) for face in faces]


def backdrop():
    w, f = BACKDROP_HALF_WIDTH, BACKDROP_FRONT
    floor = [(-w, FLOOR_Y, BACK_WALL_Z), (w, FLOOR_Y, BACK_WALL_Z), (w, FLOOR_Y, f), (-w, FLOOR_Y, f)]
    wall = [(-w, FLOOR_Y, BACK_WALL_Z), (w, FLOOR_Y, BACK_WALL_Z), (w, BACKDROP_TOP, BACK_WALL_Z),
            (-w, BACKDROP_TOP, BACK_WALL_Z)]
    return facing(floor, (0.0, 1.0, 0.0)) + facing(wall, (0.0, 0.0, 1.0))

# ---------------------------------------------------------------------------
# The layout's checks


def segment_blocked(a, b, triangles):
    """Whether the open segment a-b passes through any triangle."""
    d = sub(b, a)
    for p, q, r in triangles:
        e1, e2 = sub(q, p), sub(r, p)
        h = cross(d, e2)
        det = dot(e1, h)
        if abs(det) < 1e-12:
            continue
        s = sub(a, p)
        u = dot(s, h) / det
        if u < 0.0 or u > 1.0:
            continue
        qv = cross(s, e1)
        v = dot(d, qv) / det
        if v < 0.0 or u + v > 1.0:
            continue
        t = dot(e2, qv) / det
        if 1e-6 < t < 1.0 - 1e-6:
            return True
    return False


def in_picture(point):
    rotation_back = normalize(sub(CAMERA_POSITION, CAMERA_TARGET))
    right = normalize(cross((0.0, 1.0, 0.0), rotation_back))
    up = cross(rotation_back, right)
    v = sub(point, CAMERA_POSITION)
    depth = -dot(v, rotation_back)
    tan_half = math.tan(CAMERA_YFOV / 2)
    return depth > 0 and abs(dot(v, up) / depth) < tan_half and \
        abs(dot(v, right) / depth) < tan_half * CAMERA_ASPECT


def check_layout(plates):
    """Every light's mirror point on every plate's top face lies on the plate,
    sees the camera and the light past the other plates, and is in the picture."""
    everything = [t for triangles in plates for t in triangles]
    for k, centre in enumerate(PLATE_CENTRES):
        normal, depth = plate_frame(centre)
        face = add(centre, scale(normal, PLATE_THICKNESS / 2))
        others = [t for j, triangles in enumerate(plates) if j != k for t in triangles]
        for x, radius in zip(LIGHT_XS, LIGHT_RADII):
            light = (x, 0.0, 0.0)
            image = sub(light, scale(normal, 2 * dot(sub(light, face), normal)))
            ray = sub(image, CAMERA_POSITION)
            t = dot(sub(face, CAMERA_POSITION), normal) / dot(ray, normal)
            hit = add(CAMERA_POSITION, scale(ray, t))
            offset = sub(hit, face)
            where = f"plate {k}, light at x = {x}"
            assert abs(offset[0]) < PLATE_LENGTH / 2 - 0.1, where + ": highlight off the plate's end"
            assert abs(dot(offset, depth)) < PLATE_DEPTH / 2 - 0.05, where + ": highlight off the plate's edge"
            assert not segment_blocked(CAMERA_POSITION, hit, others), where + ": hidden from the camera"
            assert not segment_blocked(hit, light, everything), where + ": the light is hidden"
            assert in_picture(hit), where + ": outside the picture"
        for corner in (add(face, (PLATE_LENGTH / 2, 0.0, 0.0)), add(face, (-PLATE_LENGTH / 2, 0.0, 0.0))):
            assert in_picture(corner), f"plate {k} is cut off by the picture's edge"
    for x, radius in zip(LIGHT_XS, LIGHT_RADII):
        assert in_picture((x, radius, 0.0)) and in_picture((x + radius, 0.0, 0.0)), f"light at {x}"
        assert not segment_blocked(CAMERA_POSITION, (x, radius, 0.0), everything), f"light at {x} hidden"

# ---------------------------------------------------------------------------
# glTF


def build_gltf():
    plates = [plate_triangles(centre) for centre in PLATE_CENTRES]
    check_layout(plates)

    materials = [material("backdrop", BACKDROP_ALBEDO)]
    materials += [material(f"plate_roughness_{r}", PLATE_COLOUR, metallic=1.0, roughness=r)
                  for r in PLATE_ROUGHNESS]
    materials += [material(f"light_radius_{i}", (0.0, 0.0, 0.0), emission=(1 / r**2,) * 3)
                  for i, r in enumerate(LIGHT_RADII)]
    materials.append(material("fill_light", (0.0, 0.0, 0.0), emission=(FILL_RADIANCE,) * 3))

    builder = Builder(materials)
    builder.add_flat_mesh("backdrop", "backdrop", backdrop())
    for k, (triangles, r) in enumerate(zip(plates, PLATE_ROUGHNESS)):
        builder.add_flat_mesh(f"plate_{k}", f"plate_roughness_{r}", triangles)
    for i, (x, r) in enumerate(zip(LIGHT_XS, LIGHT_RADII)):
        builder.add_flat_mesh(f"light_{i}", f"light_radius_{i}", sphere_triangles((x, 0.0, 0.0), r))
    builder.add_flat_mesh("fill_light", "fill_light", sphere_triangles(FILL_CENTRE, FILL_RADIUS))
    builder.add_camera("camera", CAMERA_POSITION, look_at_rotation(CAMERA_POSITION, CAMERA_TARGET),
                       CAMERA_YFOV, CAMERA_ASPECT, 0.01)
    return builder.document("scenes/make_veach_mis.py", "veach_mis")


def main():
    summary = write(OUTPUT, build_gltf())
    lo = ", ".join(f"{x:.3g}" for x in summary["min"])
    hi = ", ".join(f"{x:.3g}" for x in summary["max"])
    print(f"wrote {OUTPUT}: {summary['triangles']} triangles, bounds ({lo}) .. ({hi})")


if __name__ == "__main__":
    main()
