#!/usr/bin/env python3
"""make_teapot.py -- writes scenes/cornell-teapot.gltf: the Utah teapot in
gold-like GGX metal standing on the floor of the Cornell box (the box, light,
materials and camera of make_cornell_box.py, without its two blocks).

The teapot is Newell's (1975) public-domain data: 32 bicubic Bezier patches
over 306 control points (rim 4, body 8, handle 4, spout 4, lid 8, bottom 4),
typed in below as published in the teaset data, with no changes (not Blinn's
vertical squash, not the lid refitted).

Tessellation: each patch is evaluated on a 13 x 13 grid (12 x 12 quads, two
triangles each) with the normal from the patch derivatives, Pu x Pv. Where
that vanishes -- at the lid's top and the bottom's centre, where a whole patch
edge collapses to one point -- the derivatives are taken a little way inside
the patch instead (1e-4, 1e-3 or 1e-2 of the parameter range towards its
middle; both poles are flat there, so this is the limit normal). No normal is
ever zero or NaN; the script asserts it. Positions that agree to 1e-9 units
are welded into one, so patches meet without cracks and the triangles that
collapse at the poles have exactly zero area; those are dropped (8 patches x
12 = 96 of them).

Orientation: the published patches are not trusted to face outward. Patches
that share a seam must cross it in opposite directions when both are wound
counter-clockwise seen from outside; that splits the 32 into four parts (body
with rim and bottom, handle, spout, lid), each oriented consistently (a seam
that cannot be is an error). Each part's side then follows from its flux, the
sum over its triangles of a . (b x c) / 2 measured from the part's centroid:
3 times the volume it encloses, positive when the normals point out (the
open ends -- the body's mouth, the lid's underside, the tubes' ends -- take
too little of it to change the sign; it must exceed 0.05 cubic units). With
this data all 32 patches turn out to have Pu x Pv pointing in, so all are
flipped; the script prints the count.

Placement: Newell's z-up turns to glTF's y-up ((x, y, z) -> (x, z, -y)), the
teapot turns TEAPOT_TURN_DEGREES about the vertical so its spout points
towards the front-left of the picture, is scaled by TEAPOT_SCALE (mm per
Newell unit; the teapot is then about 189 mm tall), and is centred over the
floor's middle with its flat bottom 0.1 mm above the floor (the two never
share a plane).

Material: "gold", base colour (1.0, 0.71, 0.29), metallic 1, roughness 0.25.
The file passes scenes/check_gltf.py's checks before it is written; running
the script again reproduces it byte for byte.

Usage: python3 scenes/make_teapot.py   (from any directory)
"""

import math
import os

import make_cornell_box as cornell
from gltf_writer import Builder, add, cross, dot, length, material, normalize, scale, sub, write

SCENES_DIR = os.path.dirname(os.path.abspath(__file__))
OUTPUT = os.path.join(SCENES_DIR, "cornell-teapot.gltf")

SEGMENTS = 12                  # quads along each side of a patch
TEAPOT_SCALE = 60.0            # mm per Newell unit
TEAPOT_TURN_DEGREES = 30.0     # about +y, after turning z-up into y-up
FLOOR_GAP = 0.1                # mm between the teapot's bottom and the floor
GOLD = material("gold", (1.0, 0.71, 0.29), metallic=1.0, roughness=0.25)
WELD = 1e-9                    # Newell units
POLE_STEPS = (1e-4, 1e-3, 1e-2)

# Newell's teapot (1975), as published in the teaset data: 32 bicubic Bezier
# patches, each 16 one-based indices (4 rows of 4) into 306 control points.
# Public domain. Units as published, z up.
PATCHES = """
1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16
4 17 18 19 8 20 21 22 12 23 24 25 16 26 27 28
19 29 30 31 22 32 33 34 25 35 36 37 28 38 39 40
31 41 42 1 34 43 44 5 37 45 46 9 40 47 48 13
13 14 15 16 49 50 51 52 53 54 55 56 57 58 59 60
16 26 27 28 52 61 62 63 56 64 65 66 60 67 68 69
28 38 39 40 63 70 71 72 66 73 74 75 69 76 77 78
40 47 48 13 72 79 80 49 75 81 82 53 78 83 84 57
57 58 59 60 85 86 87 88 89 90 91 92 93 94 95 96
60 67 68 69 88 97 98 99 92 100 101 102 96 103 104 105
69 76 77 78 99 106 107 108 102 109 110 111 105 112 113 114
78 83 84 57 108 115 116 85 111 117 118 89 114 119 120 93
121 122 123 124 125 126 127 128 129 130 131 132 133 134 135 136
124 137 138 121 128 139 140 125 132 141 142 129 136 143 144 133
133 134 135 136 145 146 147 148 149 150 151 152 69 153 154 155
136 143 144 133 148 156 157 145 152 158 159 149 155 160 161 69
162 163 164 165 166 167 168 169 170 171 172 173 174 175 176 177
165 178 179 162 169 180 181 166 173 182 183 170 177 184 185 174
174 175 176 177 186 187 188 189 190 191 192 193 194 195 196 197
177 184 185 174 189 198 199 186 193 200 201 190 197 202 203 194
204 204 204 204 207 208 209 210 211 211 211 211 212 213 214 215
204 204 204 204 210 217 218 219 211 211 211 211 215 220 221 222
204 204 204 204 219 224 225 226 211 211 211 211 222 227 228 229
204 204 204 204 226 230 231 207 211 211 211 211 229 232 233 212
212 213 214 215 234 235 236 237 238 239 240 241 242 243 244 245
215 220 221 222 237 246 247 248 241 249 250 251 245 252 253 254
222 227 228 229 248 255 256 257 251 258 259 260 254 261 262 263
229 232 233 212 257 264 265 234 260 266 267 238 263 268 269 242
270 270 270 270 279 280 281 282 275 276 277 278 271 272 273 274
270 270 270 270 282 289 290 291 278 286 287 288 274 283 284 285
270 270 270 270 291 298 299 300 288 295 296 297 285 292 293 294
270 270 270 270 300 305 306 279 297 303 304 275 294 301 302 271
"""

POINTS = """
1.4,0.0,2.4 1.4,-0.784,2.4 0.784,-1.4,2.4 0.0,-1.4,2.4
1.3375,0.0,2.53125 1.3375,-0.749,2.53125 0.749,-1.3375,2.53125 0.0,-1.3375,2.53125
1.4375,0.0,2.53125 1.4375,-0.805,2.53125 0.805,-1.4375,2.53125 0.0,-1.4375,2.53125
1.5,0.0,2.4 1.5,-0.84,2.4 0.84,-1.5,2.4 0.0,-1.5,2.4
-0.784,-1.4,2.4 -1.4,-0.784,2.4 -1.4,0.0,2.4
-0.749,-1.3375,2.53125 -1.3375,-0.749,2.53125 -1.3375,0.0,2.53125
-0.805,-1.4375,2.53125 -1.4375,-0.805,2.53125 -1.4375,0.0,2.53125
-0.84,-1.5,2.4 -1.5,-0.84,2.4 -1.5,0.0,2.4
-1.4,0.784,2.4 -0.784,1.4,2.4 0.0,1.4,2.4
-1.3375,0.749,2.53125 -0.749,1.3375,2.53125 0.0,1.3375,2.53125
-1.4375,0.805,2.53125 -0.805,1.4375,2.53125 0.0,1.4375,2.53125
-1.5,0.84,2.4 -0.84,1.5,2.4 0.0,1.5,2.4
0.784,1.4,2.4 1.4,0.784,2.4
0.749,1.3375,2.53125 1.3375,0.749,2.53125
0.805,1.4375,2.53125 1.4375,0.805,2.53125
0.84,1.5,2.4 1.5,0.84,2.4
1.75,0.0,1.875 1.75,-0.98,1.875 0.98,-1.75,1.875 0.0,-1.75,1.875
2.0,0.0,1.35 2.0,-1.12,1.35 1.12,-2.0,1.35 0.0,-2.0,1.35
2.0,0.0,0.9 2.0,-1.12,0.9 1.12,-2.0,0.9 0.0,-2.0,0.9
-0.98,-1.75,1.875 -1.75,-0.98,1.875 -1.75,0.0,1.875
-1.12,-2.0,1.35 -2.0,-1.12,1.35 -2.0,0.0,1.35
-1.12,-2.0,0.9 -2.0,-1.12,0.9 -2.0,0.0,0.9
-1.75,0.98,1.875 -0.98,1.75,1.875 0.0,1.75,1.875
-2.0,1.12,1.35 -1.12,2.0,1.35 0.0,2.0,1.35
-2.0,1.12,0.9 -1.12,2.0,0.9 0.0,2.0,0.9
0.98,1.75,1.875 1.75,0.98,1.875
1.12,2.0,1.35 2.0,1.12,1.35
1.12,2.0,0.9 2.0,1.12,0.9
2.0,0.0,0.45 2.0,-1.12,0.45 1.12,-2.0,0.45 0.0,-2.0,0.45
1.5,0.0,0.225 1.5,-0.84,0.225 0.84,-1.5,0.225 0.0,-1.5,0.225
1.5,0.0,0.15 1.5,-0.84,0.15 0.84,-1.5,0.15 0.0,-1.5,0.15
-1.12,-2.0,0.45 -2.0,-1.12,0.45 -2.0,0.0,0.45
-0.84,-1.5,0.225 -1.5,-0.84,0.225 -1.5,0.0,0.225
-0.84,-1.5,0.15 -1.5,-0.84,0.15 -1.5,0.0,0.15
-2.0,1.12,0.45 -1.12,2.0,0.45 0.0,2.0,0.45
-1.5,0.84,0.225 -0.84,1.5,0.225 0.0,1.5,0.225
-1.5,0.84,0.15 -0.84,1.5,0.15 0.0,1.5,0.15
1.12,2.0,0.45 2.0,1.12,0.45
0.84,1.5,0.225 1.5,0.84,0.225
0.84,1.5,0.15 1.5,0.84,0.15
-1.6,0.0,2.025 -1.6,-0.3,2.025 -1.5,-0.3,2.25 -1.5,0.0,2.25
-2.3,0.0,2.025 -2.3,-0.3,2.025 -2.5,-0.3,2.25 -2.5,0.0,2.25
-2.7,0.0,2.025 -2.7,-0.3,2.025 -3.0,-0.3,2.25 -3.0,0.0,2.25
-2.7,0.0,1.8 -2.7,-0.3,1.8 -3.0,-0.3,1.8 -3.0,0.0,1.8
-1.5,0.3,2.25 -1.6,0.3,2.025 -2.5,0.3,2.25 -2.3,0.3,2.025
-3.0,0.3,2.25 -2.7,0.3,2.025 -3.0,0.3,1.8 -2.7,0.3,1.8
-2.7,0.0,1.575 -2.7,-0.3,1.575 -3.0,-0.3,1.35 -3.0,0.0,1.35
-2.5,0.0,1.125 -2.5,-0.3,1.125 -2.65,-0.3,0.9375 -2.65,0.0,0.9375
-2.0,-0.3,0.9 -1.9,-0.3,0.6 -1.9,0.0,0.6
-3.0,0.3,1.35 -2.7,0.3,1.575 -2.65,0.3,0.9375 -2.5,0.3,1.125
-1.9,0.3,0.6 -2.0,0.3,0.9
1.7,0.0,1.425 1.7,-0.66,1.425 1.7,-0.66,0.6 1.7,0.0,0.6
2.6,0.0,1.425 2.6,-0.66,1.425 3.1,-0.66,0.825 3.1,0.0,0.825
2.3,0.0,2.1 2.3,-0.25,2.1 2.4,-0.25,2.025 2.4,0.0,2.025
2.7,0.0,2.4 2.7,-0.25,2.4 3.3,-0.25,2.4 3.3,0.0,2.4
1.7,0.66,0.6 1.7,0.66,1.425 3.1,0.66,0.825 2.6,0.66,1.425
2.4,0.25,2.025 2.3,0.25,2.1 3.3,0.25,2.4 2.7,0.25,2.4
2.8,0.0,2.475 2.8,-0.25,2.475 3.525,-0.25,2.49375 3.525,0.0,2.49375
2.9,0.0,2.475 2.9,-0.15,2.475 3.45,-0.15,2.5125 3.45,0.0,2.5125
2.8,0.0,2.4 2.8,-0.15,2.4 3.2,-0.15,2.4 3.2,0.0,2.4
3.525,0.25,2.49375 2.8,0.25,2.475 3.45,0.15,2.5125 2.9,0.15,2.475
3.2,0.15,2.4 2.8,0.15,2.4
0.0,0.0,3.15 0.0,-0.002,3.15 0.002,0.0,3.15
0.8,0.0,3.15 0.8,-0.45,3.15 0.45,-0.8,3.15 0.0,-0.8,3.15
0.0,0.0,2.85
0.2,0.0,2.7 0.2,-0.112,2.7 0.112,-0.2,2.7 0.0,-0.2,2.7
-0.002,0.0,3.15 -0.45,-0.8,3.15 -0.8,-0.45,3.15 -0.8,0.0,3.15
-0.112,-0.2,2.7 -0.2,-0.112,2.7 -0.2,0.0,2.7
0.0,0.002,3.15 -0.8,0.45,3.15 -0.45,0.8,3.15 0.0,0.8,3.15
-0.2,0.112,2.7 -0.112,0.2,2.7 0.0,0.2,2.7
0.45,0.8,3.15 0.8,0.45,3.15
0.112,0.2,2.7 0.2,0.112,2.7
0.4,0.0,2.55 0.4,-0.224,2.55 0.224,-0.4,2.55 0.0,-0.4,2.55
1.3,0.0,2.55 1.3,-0.728,2.55 0.728,-1.3,2.55 0.0,-1.3,2.55
1.3,0.0,2.4 1.3,-0.728,2.4 0.728,-1.3,2.4 0.0,-1.3,2.4
-0.224,-0.4,2.55 -0.4,-0.224,2.55 -0.4,0.0,2.55
-0.728,-1.3,2.55 -1.3,-0.728,2.55 -1.3,0.0,2.55
-0.728,-1.3,2.4 -1.3,-0.728,2.4 -1.3,0.0,2.4
-0.4,0.224,2.55 -0.224,0.4,2.55 0.0,0.4,2.55
-1.3,0.728,2.55 -0.728,1.3,2.55 0.0,1.3,2.55
-1.3,0.728,2.4 -0.728,1.3,2.4 0.0,1.3,2.4
0.224,0.4,2.55 0.4,0.224,2.55
0.728,1.3,2.55 1.3,0.728,2.55
0.728,1.3,2.4 1.3,0.728,2.4
0.0,0.0,0.0
1.5,0.0,0.15 1.5,0.84,0.15 0.84,1.5,0.15 0.0,1.5,0.15
1.5,0.0,0.075 1.5,0.84,0.075 0.84,1.5,0.075 0.0,1.5,0.075
1.425,0.0,0.0 1.425,0.798,0.0 0.798,1.425,0.0 0.0,1.425,0.0
-0.84,1.5,0.15 -1.5,0.84,0.15 -1.5,0.0,0.15
-0.84,1.5,0.075 -1.5,0.84,0.075 -1.5,0.0,0.075
-0.798,1.425,0.0 -1.425,0.798,0.0 -1.425,0.0,0.0
-1.5,-0.84,0.15 -0.84,-1.5,0.15 0.0,-1.5,0.15
-1.5,-0.84,0.075 -0.84,-1.5,0.075 0.0,-1.5,0.075
-1.425,-0.798,0.0 -0.798,-1.425,0.0 0.0,-1.425,0.0
0.84,-1.5,0.15 1.5,-0.84,0.15
0.84,-1.5,0.075 1.5,-0.84,0.075
0.798,-1.425,0.0 1.425,-0.798,0.0
"""

# ---------------------------------------------------------------------------
# Bezier patches


def control_points():
    points = [tuple(float(x) for x in triple.split(",")) for triple in POINTS.split()]
    patches = [[points[int(i) - 1] for i in line.split()] for line in PATCHES.strip().splitlines()]
    assert len(points) == 306 and len(patches) == 32 and all(len(p) == 16 for p in patches)
    return patches


def bernstein(t):
    s = 1.0 - t
    return (s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t)


def bernstein_derivative(t):
    s = 1.0 - t
    return (-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t)


def evaluate(patch, u, v):
    """Point and derivatives (P, Pu, Pv); u runs across the patch's four rows
    of control points, v along each row."""
    bu, bv, du, dv = bernstein(u), bernstein(v), bernstein_derivative(u), bernstein_derivative(v)
    p, pu, pv = [0.0] * 3, [0.0] * 3, [0.0] * 3
    for i in range(4):
        for j in range(4):
            point = patch[4 * i + j]
            for c in range(3):
                p[c] += bu[i] * bv[j] * point[c]
                pu[c] += du[i] * bv[j] * point[c]
                pv[c] += bu[i] * dv[j] * point[c]
    return tuple(p), tuple(pu), tuple(pv)


def patch_normal(patch, u, v):
    """Unit Pu x Pv at (u, v); where it vanishes (a collapsed patch edge),
    the same a little way towards the patch's middle."""
    _, pu, pv = evaluate(patch, u, v)
    n = cross(pu, pv)
    for step in POLE_STEPS:
        if length(n) > 1e-12:
            break
        u2, v2 = u + step * (0.5 - u), v + step * (0.5 - v)
        _, pu, pv = evaluate(patch, u2, v2)
        n = cross(pu, pv)
    assert length(n) > 1e-12, ("no normal", u, v)
    n = normalize(n)
    assert all(math.isfinite(c) for c in n)
    return n


def tessellate(patches):
    """Per patch: a (SEGMENTS+1)^2 grid of (welded position, unit Pu x Pv)."""
    welded = {}
    grids = []
    for patch in patches:
        grid = []
        for i in range(SEGMENTS + 1):
            for j in range(SEGMENTS + 1):
                u, v = i / SEGMENTS, j / SEGMENTS
                p, _, _ = evaluate(patch, u, v)
                p = welded.setdefault(tuple(round(c / WELD) for c in p), p)
                grid.append((p, patch_normal(patch, u, v)))
        grids.append(grid)
    return grids


def quads(grid):
    """Corner indices (00, 10, 11, 01) of each quad; the triangles (00, 10,
    11) and (00, 11, 01) wind counter-clockwise around Pu x Pv."""
    n = SEGMENTS + 1
    for i in range(SEGMENTS):
        for j in range(SEGMENTS):
            yield (i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1)

# ---------------------------------------------------------------------------
# Which side is out


def patch_triangles(grid):
    """Index triples into the grid, counter-clockwise around Pu x Pv."""
    for q00, q10, q11, q01 in quads(grid):
        yield (q00, q10, q11)
        yield (q00, q11, q01)


def outward_signs(grids):
    """+1 for each patch whose Pu x Pv points out of the teapot, -1 where it
    points in (see the module docstring)."""
    # Directed edges, in the Pu x Pv winding, between patches.
    edges = {}
    for index, grid in enumerate(grids):
        for triangle in patch_triangles(grid):
            corners = [grid[k][0] for k in triangle]
            if len(set(corners)) < 3:
                continue  # collapsed at a pole
            for k in range(3):
                a, b = corners[k], corners[(k + 1) % 3]
                edges.setdefault((min(a, b), max(a, b)), []).append((index, a < b))
    relation = {}  # (patch, patch) -> +1 where their Pu x Pv sides agree, -1 where not
    for uses in edges.values():
        for i, forward_i in uses:
            for j, forward_j in uses:
                if i != j:
                    sign = -1 if forward_i == forward_j else 1
                    assert relation.setdefault((i, j), sign) == sign, ("twisted seam", i, j)
    # Consistent signs within each connected part, then each part's flux.
    signs = [0] * len(grids)
    parts = []
    for seed in range(len(grids)):
        if signs[seed]:
            continue
        signs[seed], part, todo = 1, [seed], [seed]
        while todo:
            i = todo.pop()
            for j in range(len(grids)):
                if (i, j) in relation:
                    wanted = signs[i] * relation[(i, j)]
                    if not signs[j]:
                        signs[j] = wanted
                        part.append(j)
                        todo.append(j)
                    assert signs[j] == wanted, ("patches disagree round a loop", i, j)
        parts.append(sorted(part))
    for part in parts:
        points = [p for i in part for p, _ in grids[i]]
        middle = tuple(sum(p[c] for p in points) / len(points) for c in range(3))
        flux = 0.0  # 3 x the volume the part's surface bounds, seen from its middle
        for i in part:
            grid = grids[i]
            for triangle in patch_triangles(grid):
                a, b, c = (sub(grid[k][0], middle) for k in triangle)
                flux += signs[i] * dot(a, cross(b, c)) / 2.0
        assert abs(flux) > 0.05, ("no clear outside", part, flux)
        if flux < 0:
            for i in part:
                signs[i] = -signs[i]
    return signs, parts


# ---------------------------------------------------------------------------
# The mesh


def teapot_mesh():
    """(positions, normals, triangles as index triples, counts) in the box's
    millimetres, placed as the module docstring says."""
    patches = control_points()
    grids = tessellate(patches)
    signs, parts = outward_signs(grids)

    turn = math.radians(TEAPOT_TURN_DEGREES)
    cos_t, sin_t = math.cos(turn), math.sin(turn)

    def orient(v):
        x, y, z = v[0], v[2], -v[1]            # z up -> y up
        return (cos_t * x + sin_t * z, y, -sin_t * x + cos_t * z)

    all_points = [orient(p) for grid in grids for p, _ in grid]
    lo = [min(p[c] for p in all_points) for c in range(3)]
    hi = [max(p[c] for p in all_points) for c in range(3)]
    floor_middle = [sum(corner[c] for corner in cornell.FLOOR) / 4 for c in range(3)]
    offset = (floor_middle[0] - TEAPOT_SCALE * (lo[0] + hi[0]) / 2,
              FLOOR_GAP - TEAPOT_SCALE * lo[1],
              floor_middle[2] - TEAPOT_SCALE * (lo[2] + hi[2]) / 2)

    positions, normals, triangles, index_of = [], [], [], {}
    dropped = 0
    for grid, sign in zip(grids, signs):
        def vertex(k):
            p, n = grid[k]
            key = (p, n if sign > 0 else scale(n, -1.0))
            if key not in index_of:
                index_of[key] = len(positions)
                positions.append(add(offset, scale(orient(p), TEAPOT_SCALE)))
                normals.append(orient(key[1]))
            return index_of[key]

        for q00, q10, q11, q01 in quads(grid):
            for t in ((q00, q10, q11), (q00, q11, q01)):
                if sign < 0:
                    t = t[::-1]
                corners = [grid[k][0] for k in t]
                if length(cross(sub(corners[1], corners[0]), sub(corners[2], corners[0]))) == 0.0:
                    dropped += 1
                    continue
                triangles.append(tuple(vertex(k) for k in t))
    for n in normals:
        assert abs(length(n) - 1.0) < 1e-9 and all(math.isfinite(c) for c in n)
    return positions, normals, triangles, {"dropped": dropped, "flipped": signs.count(-1),
                                           "parts": parts}


def build_gltf():
    positions, normals, triangles, counts = teapot_mesh()
    builder = Builder(cornell.room_materials(cornell.FULL_LIGHT) + [GOLD])
    for name, material_name, room_triangles in cornell.room_surfaces(cornell.FULL_LIGHT):
        builder.add_flat_mesh(name, material_name, room_triangles)
    builder.add_mesh("teapot", "gold", positions, normals, triangles)
    cornell.add_camera(builder)
    return builder.document("scenes/make_teapot.py", "cornell_teapot"), positions, triangles, counts


def main():
    gltf, positions, triangles, counts = build_gltf()
    summary = write(OUTPUT, gltf)
    lo = ", ".join(f"{min(p[c] for p in positions):.1f}" for c in range(3))
    hi = ", ".join(f"{max(p[c] for p in positions):.1f}" for c in range(3))
    print(f"teapot: {len(triangles)} triangles ({counts['dropped']} zero-area dropped), "
          f"{len(positions)} vertices, {counts['flipped']} of 32 patches had Pu x Pv pointing in, "
          f"parts {counts['parts']}; "
          f"bounds ({lo}) .. ({hi}) mm")
    print(f"wrote {OUTPUT}: {summary['triangles']} triangles")


if __name__ == "__main__":
    main()
