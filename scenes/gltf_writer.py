"""gltf_writer.py -- what the scene generators in scenes/ share: small vector
helpers, materials, an icosphere, and a builder that packs meshes into one
embedded buffer and writes a self-contained glTF 2.0 file.

Determinism: nothing here depends on dict order of inputs, time or hashing of
objects; the same calls give the same bytes. Every file goes through
check_gltf.check() before it is written, so a generator cannot write a file
that fails the checks (bad bounds, NaN, degenerate triangles, winding that
disagrees with the normals, undeclared extensions).
"""

import base64
import json
import math
import struct

import check_gltf

# glTF constants
FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963

# ---------------------------------------------------------------------------
# Vectors (tuples of floats)


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(a, s):
    return tuple(s * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(v):
    return math.sqrt(dot(v, v))


def normalize(v):
    n = length(v)
    return tuple(x / n for x in v)


def centroid(points):
    return tuple(sum(p[c] for p in points) / len(points) for c in range(3))


def front_normal(triangle):
    """Unnormalized normal of the counter-clockwise (front) side."""
    a, b, c = triangle
    return cross(sub(b, a), sub(c, a))


def as_float32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


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


def box(corner_of, middle=None):
    """A closed box from its 8 corners, corner_of(i, j, k) for i, j, k in {0, 1};
    its 12 triangles face away from `middle` (the box's centre by default)."""
    corners = {(i, j, k): corner_of(i, j, k) for i in (0, 1) for j in (0, 1) for k in (0, 1)}
    middle = middle or centroid(list(corners.values()))
    triangles = []
    for axis in range(3):
        for side in (0, 1):
            quad = []
            for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                key = [0, 0, 0]
                key[axis], key[(axis + 1) % 3], key[(axis + 2) % 3] = side, a, b
                quad.append(corners[tuple(key)])
            triangles += facing(quad, sub(centroid(quad), middle))
    return triangles


def look_at_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Unit quaternion [x, y, z, w] turning a glTF camera (looking down -Z,
    +Y up) at `eye` to look at `target`."""
    back = normalize(sub(eye, target))
    right = normalize(cross(up, back))
    true_up = cross(back, right)
    # Rotation matrix with columns right, true_up, back; to a quaternion.
    m = [[right[r], true_up[r], back[r]] for r in range(3)]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s)
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2])
        q = (0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s)
    elif m[1][1] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2])
        q = ((m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1])
        q = ((m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s)
    return list(normalize(q))

# ---------------------------------------------------------------------------
# Icosphere


def icosphere(subdivisions):
    """(unit vertices, triangles as index triples) of an icosahedron split
    `subdivisions` times, each new vertex pushed out to the unit sphere; every
    triangle is counter-clockwise seen from outside."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    vertices = [normalize(v) for v in [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
        (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(i, j):
            key = (min(i, j), max(i, j))
            if key not in midpoints:
                vertices.append(normalize(scale(add(vertices[i], vertices[j]), 0.5)))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    for face in faces:
        triangle = [vertices[i] for i in face]
        assert dot(front_normal(triangle), centroid(triangle)) > 0, face
    return vertices, faces

# ---------------------------------------------------------------------------
# Materials


def material(name, base_color, metallic=0.0, roughness=1.0, emission=None,
             transmission=None, ior=None, thickness=None):
    """A metallic-roughness material. `emission` is the radiance (RGB, any
    scale): the factor stays in [0, 1] as glTF requires and
    KHR_materials_emissive_strength carries the scale. `thickness` (scene
    units) makes a transmissive material a solid volume through
    KHR_materials_volume; without it glTF's transmission is a thin wall."""
    entry = {
        "name": name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [float(c) for c in base_color] + [1.0],
            "metallicFactor": float(metallic),
            "roughnessFactor": float(roughness),
        },
    }
    extensions = {}
    if emission is not None:
        strength = max(emission)
        entry["emissiveFactor"] = [c / strength for c in emission]
        extensions["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
    if ior is not None:
        extensions["KHR_materials_ior"] = {"ior": float(ior)}
    if transmission is not None:
        extensions["KHR_materials_transmission"] = {"transmissionFactor": float(transmission)}
    if thickness is not None:
        extensions["KHR_materials_volume"] = {"thicknessFactor": float(thickness)}
    if extensions:
        entry["extensions"] = extensions
    return entry

# ---------------------------------------------------------------------------
# Meshes


def flat_mesh(triangles):
    """Positions and normals with three vertices per triangle, so each carries
    its triangle's flat normal."""
    positions = [corner for triangle in triangles for corner in triangle]
    normals = [normalize(front_normal(t)) for t in triangles for _ in range(3)]
    return positions, normals


class Builder:
    """Collects materials, meshes (one node each) and cameras, packing every
    array into one buffer, and turns them into a glTF document."""

    def __init__(self, materials):
        self.materials = list(materials)
        self.material_index = {m["name"]: i for i, m in enumerate(self.materials)}
        assert len(self.material_index) == len(self.materials), "material names repeat"
        self.blob = bytearray()
        self.buffer_views, self.accessors, self.meshes, self.nodes, self.cameras = [], [], [], [], []

    def _view(self, data, target):
        while len(self.blob) % 4:  # every view starts 4-byte aligned
            self.blob.append(0)
        self.buffer_views.append({"buffer": 0, "byteOffset": len(self.blob),
                                  "byteLength": len(data), "target": target})
        self.blob.extend(data)
        return len(self.buffer_views) - 1

    def vec3_accessor(self, vectors, with_bounds):
        data = b"".join(struct.pack("<3f", *v) for v in vectors)
        accessor = {"bufferView": self._view(data, ARRAY_BUFFER), "componentType": FLOAT,
                    "count": len(vectors), "type": "VEC3"}
        if with_bounds:
            accessor["min"] = [min(as_float32(v[c]) for v in vectors) for c in range(3)]
            accessor["max"] = [max(as_float32(v[c]) for v in vectors) for c in range(3)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def index_accessor(self, indices):
        wide = max(indices) > 0xFFFF
        data = struct.pack(f"<{len(indices)}{'I' if wide else 'H'}", *indices)
        self.accessors.append({"bufferView": self._view(data, ELEMENT_ARRAY_BUFFER),
                               "componentType": UNSIGNED_INT if wide else UNSIGNED_SHORT,
                               "count": len(indices), "type": "SCALAR",
                               "min": [min(indices)], "max": [max(indices)]})
        return len(self.accessors) - 1

    def add_mesh(self, name, material_name, positions, normals, triangles=None):
        """One mesh and its node. Without `triangles` (index triples) the
        vertices are taken three at a time."""
        assert len(positions) == len(normals)
        primitive = {
            "attributes": {"POSITION": self.vec3_accessor(positions, True),
                           "NORMAL": self.vec3_accessor(normals, False)},
        }
        if triangles is not None:
            primitive["indices"] = self.index_accessor([i for t in triangles for i in t])
        primitive["material"] = self.material_index[material_name]
        self.meshes.append({"name": name, "primitives": [primitive]})
        self.nodes.append({"name": name, "mesh": len(self.meshes) - 1})

    def add_flat_mesh(self, name, material_name, triangles):
        self.add_mesh(name, material_name, *flat_mesh(triangles))

    def add_camera(self, name, position, rotation, yfov, aspect_ratio, znear):
        self.cameras.append({"name": name, "type": "perspective",
                             "perspective": {"yfov": yfov, "aspectRatio": aspect_ratio,
                                             "znear": znear}})
        self.nodes.append({"name": name, "camera": len(self.cameras) - 1,
                           "translation": list(position), "rotation": list(rotation)})

    def document(self, generator, scene_name):
        used = sorted({name for m in self.materials for name in m.get("extensions", {})})
        gltf = {"asset": {"version": "2.0", "generator": generator}}
        if used:
            gltf["extensionsUsed"] = used
        gltf.update({
            "scene": 0,
            "scenes": [{"name": scene_name, "nodes": list(range(len(self.nodes)))}],
            "nodes": self.nodes,
        })
        if self.cameras:
            gltf["cameras"] = self.cameras
        gltf.update({
            "meshes": self.meshes,
            "materials": self.materials,
            "accessors": self.accessors,
            "bufferViews": self.buffer_views,
            "buffers": [{"byteLength": len(self.blob),
                         "uri": "data:application/octet-stream;base64,"
                                + base64.b64encode(bytes(self.blob)).decode("ascii")}],
        })
        return gltf


def write(path, gltf):
    """Check the document, then write it as indented ASCII JSON; returns the
    checker's summary (triangles, bounds)."""
    summary = check_gltf.check(gltf)
    with open(path, "w", encoding="ascii", newline="\n") as out:
        json.dump(gltf, out, indent=1)
        out.write("\n")
    return summary
