#!/usr/bin/env python3
"""Write the stress scenes: one per numerical failure mode of a ray tracer.

    python3 tools/make_stress_scenes.py                 write scenes/stress/ (the committed set)
    python3 tools/make_stress_scenes.py --out DIR       the same set into DIR
    python3 tools/make_stress_scenes.py --check         exit 1 if scenes/stress/ differs from the output
    python3 tools/make_stress_scenes.py --family NAME --values V... --out DIR
                                                        one family at chosen parameter values

Every scene comes with a line in the folder's index.txt (the sidecar that the
stability test and tools/stability read), because several scenes need their own
field of view or image size: a camera aimed at pixel-centre rays only works at
the resolution it was designed for.

Families (the parameter each one varies, then what it stresses):
  far_sphere   distance/radius    a small sphere seen from far away through a narrow field
                                  of view: the textbook quadratic's b^2 - ac cancels
  far_sphere_scaled  scene scale  far_sphere at distance/radius 1e3, every length times s
  edge_mesh    scene scale        a closed mesh whose shared edges and vertices lie exactly on
                                  pixel-centre rays (in exact arithmetic): Moller-Trumbore cracks
  grazing      scene scale        a ground plane seen near the horizon, hit points thousands of
                                  units away: a fixed offset is below their rounding error (acne)
  mirrors      scene scale        two facing mirrors, many bounces: secondary-ray origins
  degenerate   scene scale        zero-area triangles and zero-length vertex normals, with
                                  pixel-centre rays through the zero-area lines and zero normals
  inside_sphere scene scale       the camera inside a sphere: the far root, inward normals
  ground*      ground extent      scales mixed: a huge ground quad with small objects on it and
                                  lights low over it (grazing shadows); variants: small objects
                                  seen from close, large ones from high up, an overhead light,
                                  a mirror ground

Every coordinate written is exactly representable in binary32 (rounded to float
first, then printed with 17 significant digits), so the fp32 kernel, the fp64
kernel and the double-precision reference all see the same geometry: any
difference between them comes from arithmetic, not from reading the file.

index.txt: one scene per line, `key=value` fields separated by spaces:
  file, family, parameter (what value measures), value, width, height, fov (degrees),
  depth, axes (the method options worth varying for this scene, comma-separated; the
  others stay at their defaults), must_fail (combinations that must show failures,
  ';'-separated, each a '+'-joined list of option:value; '-' for none).

Deterministic (no randomness, no clock), standard library only.
"""

import argparse
import math
import pathlib
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
STRESS_DIR = ROOT / "scenes" / "stress"
INDEX_NAME = "index.txt"
WIDTH, HEIGHT = 160, 120  # the stability suite's image size; edge_mesh and degenerate are designed for it


# ------------------------------------------------------------------ numbers ---

def f32(x):
    """x rounded to the nearest binary32 value (as a Python float, exactly)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def num(x):
    """x rounded to binary32, written so that a double parser reads that float exactly."""
    x = f32(x)
    if x == 0.0:
        return "0"
    text = "%.17g" % x
    return text


def vec(v):
    return " ".join(num(c) for c in v)


def short(x):
    """A colour or normal component: the shortest text that reads back as x's binary32 value
    (those need not be exact in double: they are not geometry)."""
    x = f32(x)
    for digits in range(1, 10):
        text = "%.*g" % (digits, x)
        if f32(float(text)) == x:
            return "0" if float(text) == 0.0 else text
    return "%.9g" % x


def svec(v):
    return " ".join(short(c) for c in v)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(s, v):
    return (s * v[0], s * v[1], s * v[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    n = math.sqrt(dot(v, v))
    return mul(1.0 / n, v)


def pixel_ray(i, j, width, height, fov):
    """the default camera: the unnormalised direction (x, y, -1) through pixel (i, j)'s point (i, j)
    (pass i + 0.5 for the centre)."""
    ty = math.tan(math.radians(fov) / 2)
    tx = width / height * ty
    return ((2.0 * i / width - 1.0) * tx, (1.0 - 2.0 * j / height) * ty, -1.0)


# ------------------------------------------------------------------- writer ---

class Scene:
    """Objects in the scene format (docs/model.md); lengths multiplied by `scale` as they are written."""

    def __init__(self, ambient, scale=1.0):
        self.ambient = ambient
        self.scale = scale
        self.objects = []

    def light(self, pos, col):
        self.objects.append("light\npos: %s\ncol: %s\n" % (vec(mul(self.scale, pos)), svec(col)))

    def sphere(self, pos, rad, dif, spe=(0, 0, 0), shi=1):
        self.objects.append("sphere\npos: %s\nrad: %s\ndif: %s\nspe: %s\nshi: %s\n" % (
            vec(mul(self.scale, pos)), num(self.scale * rad), svec(dif), svec(spe), short(shi)))

    def triangle(self, corners, normals, dif, spe=(0, 0, 0), shi=1):
        """corners: three positions; normals: three normals or one for all; dif/spe: one colour
        or three (per vertex)."""
        if len(normals) != 3 or not isinstance(normals[0], (tuple, list)):
            normals = (normals,) * 3
        difs = dif if isinstance(dif[0], (tuple, list)) else (dif,) * 3
        spes = spe if isinstance(spe[0], (tuple, list)) else (spe,) * 3
        text = "triangle\n"
        for p, n, d, s in zip(corners, normals, difs, spes):
            text += "pos: %s\nnor: %s\ndif: %s\nspe: %s\nshi: %s\n" % (
                vec(mul(self.scale, p)), svec(n), svec(d), svec(s), short(shi))
        self.objects.append(text)

    def quad(self, a, b, c, d, normal, dif, spe=(0, 0, 0), shi=1):
        self.triangle((a, b, c), normal, dif, spe, shi)
        self.triangle((a, c, d), normal, dif, spe, shi)

    def text(self):
        return "%d\namb: %s\n%s" % (len(self.objects), svec(self.ambient), "".join(self.objects))


# ------------------------------------------------------------------ families ---
# Each builder returns (scene text, settings) for one parameter value; settings holds
# width, height, fov, depth, axes and must_fail for the index.

ALL_AXES = ("sphere-test", "triangle-test", "offset", "precision")


def fixed_offset_failures(scale, small, large):
    """Where the fixed 1e-4 offset is measured to break (tools/stability): at or below the
    scale `small` it is large against the scene and moves secondary rays past what they
    should see, in any precision; at or above `large` it is below binary32's rounding error
    of the coordinates (acne, self-reflection), in fp32 only."""
    if scale <= small:
        return [{"offset": "fixed"}]
    if scale >= large:
        return [{"offset": "fixed", "precision": "fp32"}]
    return []


def far_sphere(ratio, scale=1.0):
    """A sphere of radius 1 at distance `ratio` (times `scale`), matte, lit from the upper
    left front, the field of view narrowed so that its radius is a quarter of the image
    height. The textbook quadratic computes b^2 - ac from two numbers near distance^2 whose
    difference is radius^2: in binary32 it has (r/d)^2 / 2^-24 significant units left, none
    from d/r of about 4e3. Alone in the scene (no ground under it): the scale-relative
    offset lifts a point's secondary rays by 256 ulps of its coordinates (2 radii at d/r =
    1e5), which would erase a contact shadow that fp32 can no longer place anyway."""
    d = float(ratio)
    scene = Scene(ambient=(0.1, 0.1, 0.12), scale=scale)
    scene.light((0.6 * d, 0.8 * d, 0.2 * d), (0.9, 0.9, 0.85))
    scene.sphere((0.0, 0.0, -d), 1.0, dif=(0.75, 0.35, 0.2))
    fov = math.degrees(2 * math.atan(1.0 / (0.5 * math.sqrt(d * d - 1.0))))
    must_fail = [{"sphere-test": "naive", "precision": "fp32"}] if ratio >= 1e3 else []
    if scale * ratio >= 1e4:  # coordinates whose rounding error exceeds the fixed 1e-4
        must_fail.append({"offset": "fixed", "precision": "fp32"})
    return scene.text(), dict(fov=fov, depth=5, axes=("sphere-test", "offset", "precision"),
                              must_fail=must_fail)


def edge_mesh(scale=1.0, width=WIDTH, height=HEIGHT, fov=60.0):
    """A closed slab: its front face, a plane tilted towards the upper left, is a grid of
    quads whose inner corners lie on pixel-centre rays, every 6th pixel; each quad is split
    along a diagonal (alternating in a checkerboard), which then passes through the pixel
    centres on that diagonal (except in the quads along the border, which lies on pixel
    boundaries). In exact arithmetic every row of pixel centres between two corners of
    a grid row lies on their shared edge (the rays of a row of pixels span a plane through
    the eye, which meets the face's plane in the edge's line), and so does every column and
    every diagonal: about half of the pixels on the face are aimed at a shared edge or
    vertex. The face is flat and one colour, so across an edge the colour is continuous and
    a crack (the ray sees the inside of the back face, in shadow) cannot pass for a
    knife-edge. Back face and side walls close the mesh."""
    step = 6
    i0, j0 = 20, 15
    cols, rows = 20, 15  # quads
    normal = normalize((0.25, 0.3, 1.0))
    anchor = (0.0, 0.0, -4.0)
    c = dot(normal, anchor)
    thickness = 0.6

    # Grid lines through pixel centres, except the border, which lies on pixel boundaries:
    # a ray exactly along the silhouette would meet the front face and a side wall at the
    # same point, a tie with no right answer (and the reference's rays moved off it see
    # only the face or the background, never the wall seen edge-on).
    def line(k, count, first):
        return first + step * k + 0.5 + (-0.5 if k == 0 else 0.5 if k == count else 0.0)

    def front(a, b):
        ray = pixel_ray(line(a, cols, i0), line(b, rows, j0), width, height, fov)
        return mul(c / dot(normal, ray), ray)

    grid = [[front(a, b) for b in range(rows + 1)] for a in range(cols + 1)]
    back = [[sub(p, mul(thickness, normal)) for p in column] for column in grid]
    back_normal = mul(-1.0, normal)
    scene = Scene(ambient=(0.08, 0.08, 0.1), scale=scale)
    scene.light((-3.0, 4.0, 2.0), (0.95, 0.95, 0.9))
    face = (0.3, 0.65, 0.85)
    wall = (0.8, 0.75, 0.5)
    for a in range(cols):
        for b in range(rows):
            p00, p10, p11, p01 = grid[a][b], grid[a + 1][b], grid[a + 1][b + 1], grid[a][b + 1]
            if (a + b) % 2 == 0:  # diagonal from (a, b) to (a+1, b+1)
                scene.triangle((p00, p10, p11), normal, face)
                scene.triangle((p00, p11, p01), normal, face)
            else:  # diagonal from (a+1, b) to (a, b+1)
                scene.triangle((p00, p10, p01), normal, face)
                scene.triangle((p10, p11, p01), normal, face)
    # Side walls along the border: each border edge of the front face joined to the back,
    # and the back face (never seen unless through a crack) a fan around its centre that
    # shares the side walls' back edges.
    border = ([(a, 0) for a in range(cols)] + [(cols, b) for b in range(rows)] +
              [(a, rows) for a in range(cols, 0, -1)] + [(0, b) for b in range(rows, 0, -1)])
    back_centre = mul(0.5, add(back[0][0], back[cols][rows]))
    for k, (a, b) in enumerate(border):
        a2, b2 = border[(k + 1) % len(border)]
        p, q = grid[a][b], grid[a2][b2]
        pb, qb = back[a][b], back[a2][b2]
        side = normalize(cross(sub(q, p), sub(pb, p)))
        scene.triangle((p, q, qb), side, wall)
        scene.triangle((p, qb, pb), side, wall)
        scene.triangle((pb, qb, back_centre), back_normal, wall)
    return scene.text(), dict(width=width, height=height, fov=fov, depth=0,
                              axes=("triangle-test", "offset", "precision"),
                              must_fail=[{"triangle-test": "mt", "precision": "fp32"}] +
                              fixed_offset_failures(scale, 0.0, 1e3))


def grazing(scale=1.0):
    """A ground plane y = -1 (a quad 2e4 across, vertex colours varying) seen through a 2
    degree field of view centred on the horizon: the rows below it hit the ground from 58 to
    6900 units away, and three spheres of radius 20 stand on it 2000 to 4500 units away.
    Everything seen is far from the eye, where binary32 coordinates are coarse (ulp(4096 ..
    8192) = 5e-4, five times the fixed offset of 1e-4): with a fixed offset the spheres'
    lit sides and the ground near the horizon shadow themselves (acne). The ground itself
    is mostly spared: its large coordinates (x, z) lie in its plane, and its y is exact,
    so its points' rounding error runs along it, not across. The scaled offset (256 ulps of
    the coordinates, about 0.25 units there) must keep every shadow."""
    scene = Scene(ambient=(0.1, 0.1, 0.1), scale=scale)
    scene.light((-400.0, 600.0, -1500.0), (0.9, 0.9, 0.85))
    e = 1.0e4
    up = (0.0, 1.0, 0.0)
    near_l, near_r, far_r, far_l = (-e, -1.0, 0.0), (e, -1.0, 0.0), (e, -1.0, -e), (-e, -1.0, -e)
    scene.triangle((near_l, near_r, far_r), up,
                   ((0.8, 0.5, 0.3), (0.3, 0.8, 0.5), (0.4, 0.5, 0.9)))
    scene.triangle((near_l, far_r, far_l), up,
                   ((0.8, 0.5, 0.3), (0.4, 0.5, 0.9), (0.85, 0.8, 0.3)))
    for x, z in ((-60.0, -3000.0), (50.0, -4500.0), (-10.0, -2000.0)):
        scene.sphere((x, 19.0, z), 20.0, dif=(0.85, 0.85, 0.85))
    must_fail = [{"offset": "fixed", "precision": "fp32"}] if scale >= 1.0 else []
    return scene.text(), dict(fov=2.0, depth=0, axes=ALL_AXES, must_fail=must_fail)


def mirrors(scale=1.0):
    """A corridor between two facing mirrors (x = +-1.2, 90% reflective), a matte floor, a
    red sphere and a blue one between them and a light above: reflected rays bounce up to 10
    times, each leaving a mirror from a point that must not see that mirror again."""
    scene = Scene(ambient=(0.08, 0.08, 0.08), scale=scale)
    scene.light((0.3, 1.4, -3.0), (0.9, 0.9, 0.9))
    m = 1.2
    mirror_dif, mirror_spe = (0.05, 0.05, 0.06), (0.9, 0.9, 0.9)
    for x, n in ((-m, (1.0, 0.0, 0.0)), (m, (-1.0, 0.0, 0.0))):
        scene.quad((x, -1.0, -1.5), (x, -1.0, -12.0), (x, 1.6, -12.0), (x, 1.6, -1.5), n,
                   mirror_dif, mirror_spe, 200)
    scene.quad((-m, -1.0, -1.5), (m, -1.0, -1.5), (m, -1.0, -12.0), (-m, -1.0, -12.0),
               (0.0, 1.0, 0.0), (0.7, 0.7, 0.65))
    scene.sphere((-0.35, -0.55, -4.5), 0.45, dif=(0.85, 0.2, 0.15), spe=(0.2, 0.2, 0.2), shi=40)
    scene.sphere((0.55, -0.7, -6.5), 0.3, dif=(0.2, 0.3, 0.85))
    return scene.text(), dict(fov=60.0, depth=10, axes=ALL_AXES,
                              must_fail=fixed_offset_failures(scale, 1e-2, 1e3))


def degenerate(scale=1.0, width=WIDTH, height=HEIGHT, fov=60.0):
    """Degenerate but legal triangles in front of a matte backdrop, placed with pixel-centre
    rays through their trouble spots: two zero-area triangles (collinear corners, and two
    coincident corners; bright red, so a spurious hit shows) whose lines run along a row and
    a diagonal of pixel centres; a triangle with one zero-length vertex normal whose vertex
    lies on a pixel-centre ray; and a triangle whose vertex normals n, -n and 0 interpolate
    to exactly zero on the line from the zero vertex to the midpoint of the other two, along
    a column of pixel centres (there the geometric normal is used)."""
    def at(i, j, distance):  # the point at depth `distance` on pixel (i, j)'s centre ray
        return mul(distance, pixel_ray(i + 0.5, j + 0.5, width, height, fov))

    scene = Scene(ambient=(0.1, 0.1, 0.1), scale=scale)
    scene.light((1.0, 3.0, 1.0), (0.9, 0.9, 0.9))
    # Backdrop: a quad at z = -6 covering the view.
    z = -6.0
    scene.quad((-6.0, -5.0, z), (6.0, -5.0, z), (6.0, 5.0, z), (-6.0, 5.0, z), (0.0, 0.0, 1.0),
               (0.6, 0.6, 0.55))
    red = (1.0, 0.0, 0.0)
    # Zero-area: corners on the pixel-centre rays of row 30, columns 20, 50, 80, at one depth
    # (collinear in exact arithmetic, and in binary32: they differ only in x).
    scene.triangle((at(20, 30, 3.0), at(50, 30, 3.0), at(80, 30, 3.0)), (0.0, 0.0, 1.0), red)
    # Zero-area: two coincident corners, the third along a diagonal of pixel centres.
    scene.triangle((at(100, 20, 3.0), at(100, 20, 3.0), at(130, 50, 3.0)), (0.0, 0.0, 1.0), red)
    # The vertex normals of these two are parallel to the geometric normal (0, 0, 1) (the
    # triangles lie in the plane z = -4), so the geometric fallback where the interpolated
    # normal is exactly zero shades like the points around it: a renderer that produces NaN
    # there, or that normalises each vertex normal before interpolating (NaN over the whole
    # triangle), is caught, and one that follows the model cannot be told apart from the
    # reference by an answer at a single point that has no neighbours to agree with.
    # One zero-length vertex normal (and one of length 2), that vertex on the ray of pixel
    # (40, 80); per-vertex colours.
    scene.triangle((at(40, 80, 4.0), at(10, 110, 4.0), at(70, 110, 4.0)),
                   ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, 2.0)),
                   ((0.3, 0.8, 0.4), (0.2, 0.4, 0.9), (0.9, 0.8, 0.3)))
    # Normals n, -n, 0: zero on the median from the third vertex, which follows column 120.
    scene.triangle((at(95, 100, 4.0), at(145, 100, 4.0), at(120, 65, 4.0)),
                   ((0.0, 0.0, 1.0), (0.0, 0.0, -1.0), (0.0, 0.0, 0.0)), (0.9, 0.7, 0.2))
    return scene.text(), dict(width=width, height=height, fov=fov, depth=5,
                              axes=("triangle-test", "offset", "precision"),
                              must_fail=fixed_offset_failures(scale, 1e-3, 1e3))


def inside_sphere(scale=1.0):
    """The eye inside a sphere of radius 10 centred at z = -2: every primary ray must take
    the far root, and the inner wall's normal is flipped towards the eye. A smaller sphere and a light inside cast a shadow on
    the wall; shadow rays leave the wall inwards."""
    scene = Scene(ambient=(0.1, 0.1, 0.1), scale=scale)
    scene.light((2.0, 4.0, -3.0), (0.9, 0.85, 0.8))
    scene.sphere((0.0, 0.0, -2.0), 10.0, dif=(0.7, 0.7, 0.75))
    scene.sphere((0.8, -0.5, -6.0), 1.0, dif=(0.85, 0.3, 0.2), spe=(0.3, 0.3, 0.3), shi=30)
    return scene.text(), dict(fov=60.0, depth=5, axes=("sphere-test", "offset", "precision"),
                              must_fail=fixed_offset_failures(scale, 1e-4, 1e3))


def ground(extent, size=1.0, height=1.0, light="grazing", mirror=False):
    """Scales mixed: a ground quad `extent` across (two triangles) at y = -height, the eye
    `height` above it, and objects of size `size` standing on it some way ahead: spheres of
    radius 0.3 to 1 times size and a box of triangles whose base lies in the ground's plane.
    Grazing lights stand 0.3 and 0.5 times size above the ground, hundreds of sizes away, so
    shadows are long and shadow rays skim the ground; an overhead light stands 20 sizes up.
    A point on the ground has x and z up to extent/2 but an exact y: an offset scaled by its
    largest coordinate (--offset scaled) lifts its shadow rays far above the lights, and the
    objects cast no shadow; one that follows the y coordinate's own error does not."""
    scene = Scene(ambient=(0.1, 0.1, 0.1))
    y = -float(height)
    s = float(size)
    ahead = max(8.0 * s, 3.0 * height)  # far enough ahead to be in view from the eye's height
    if light == "grazing":
        # Bright (colours above 1 are allowed): at this height dot(N, L) on the ground is
        # about 1e-3, and the shadows must show on it.
        scene.light((-300.0 * s, y + 0.3 * s, -ahead - 200.0 * s), (300.0, 290.0, 260.0))
        scene.light((250.0 * s, y + 0.5 * s, -ahead + 150.0 * s), (150.0, 160.0, 190.0))
    else:
        scene.light((0.5 * s, y + 20.0 * s, -ahead + 2.0 * s), (0.9, 0.9, 0.85))
    e = 0.5 * extent
    dif = (0.6, 0.6, 0.55) if not mirror else (0.2, 0.2, 0.2)
    spe = (0.0, 0.0, 0.0) if not mirror else (0.6, 0.6, 0.6)
    scene.quad((-e, y, e), (e, y, e), (e, y, -e), (-e, y, -e), (0.0, 1.0, 0.0), dif, spe, 50)
    for dx, dz, r, colour in ((-2.0, 0.0, 1.0, (0.8, 0.3, 0.2)), (1.5, -2.5, 0.6, (0.2, 0.6, 0.8)),
                              (0.2, 2.0, 0.3, (0.8, 0.8, 0.3))):
        scene.sphere((dx * s, y + r * s, -ahead + dz * s), r * s, dif=colour)
    # A box 1.2 sizes wide: four walls and a top, and a base in the ground's plane.
    x0, x1, z0, z1, top = 0.8 * s, 2.0 * s, -ahead + 0.2 * s, -ahead + 1.4 * s, y + 1.2 * s
    box = (0.35, 0.75, 0.35)
    corners = {(i, j, k): (x1 if i else x0, top if j else y, z1 if k else z0)
               for i in (0, 1) for j in (0, 1) for k in (0, 1)}
    faces = [((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1), (0.0, 0.0, 1.0)),
             ((1, 0, 0), (0, 0, 0), (0, 1, 0), (1, 1, 0), (0.0, 0.0, -1.0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0), (-1.0, 0.0, 0.0)),
             ((1, 0, 1), (1, 0, 0), (1, 1, 0), (1, 1, 1), (1.0, 0.0, 0.0)),
             ((0, 1, 1), (1, 1, 1), (1, 1, 0), (0, 1, 0), (0.0, 1.0, 0.0)),
             ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1), (0.0, -1.0, 0.0))]
    for a, b, c, d, n in faces:
        scene.quad(corners[a], corners[b], corners[c], corners[d], n, box)
    key = (extent, size, light, mirror)
    return scene.text(), dict(fov=60.0, depth=5 if mirror else 0, axes=("offset", "precision"),
                              must_fail=GROUND_MUST_FAIL.get(key, []))


# Where the naive offsets are measured to fail on the committed ground scenes (tools/stability,
# 160x120): the scale-relative one lifts shadow rays off huge grounds (0.47% to 6.7% of the
# pixels wrong in fp32); the fixed 1e-4 is as tall as millimetre objects (1.1%, any precision).
# Keyed by (extent, size, light, mirror).
SCALED = {"offset": "scaled", "precision": "fp32"}
FIXED = {"offset": "fixed"}
GROUND_MUST_FAIL = {
    (1e3, 1.0, "grazing", False): [SCALED],
    (2e5, 1.0, "grazing", False): [SCALED],
    (1e6, 1.0, "grazing", False): [SCALED],
    (1e1, 1e-3, "grazing", False): [SCALED, FIXED],
    (1e3, 1e-3, "grazing", False): [SCALED, FIXED],
    (1e6, 10.0, "grazing", False): [SCALED],
    (1e5, 1.0, "grazing", True): [SCALED],
}


# ------------------------------------------------------------------ the set ---

def scale_name(s):
    return "1" if s == 1 else ("%.0e" % s).replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")


# family name -> (parameter name, builder taking the parameter value)
FAMILIES = {
    "far_sphere": ("distance_over_radius", lambda v: far_sphere(v)),
    "far_sphere_scaled": ("scale", lambda v: far_sphere(1e3, scale=v)),
    "edge_mesh": ("scale", lambda v: edge_mesh(scale=v)),
    "grazing": ("scale", lambda v: grazing(scale=v)),
    "mirrors": ("scale", lambda v: mirrors(scale=v)),
    "degenerate": ("scale", lambda v: degenerate(scale=v)),
    "inside_sphere": ("scale", lambda v: inside_sphere(scale=v)),
    # Scales mixed: the ground's extent against objects of size 1 seen from height 1, ...
    "ground": ("extent", lambda v: ground(v)),
    # ... millimetre objects seen from a centimetre, ...
    "ground_small": ("extent", lambda v: ground(v, size=1e-3, height=1e-2)),
    # ... objects of size 10 seen from 100 up, ...
    "ground_high": ("extent", lambda v: ground(v, size=10.0, height=100.0)),
    # ... a light overhead, and a mirror ground (five bounces).
    "ground_overhead": ("extent", lambda v: ground(v, light="overhead")),
    "ground_mirror": ("extent", lambda v: ground(v, mirror=True)),
}

# The committed set: (family, value, file stem).
COMMITTED = [
    ("far_sphere", 1e2, "far_sphere_r1e2"),
    ("far_sphere", 1e3, "far_sphere_r1e3"),
    ("far_sphere", 1e4, "far_sphere_r1e4"),
    ("far_sphere", 1e5, "far_sphere_r1e5"),
    ("far_sphere_scaled", 1e-4, "far_sphere_r1e3_scale1e-4"),
    ("far_sphere_scaled", 1e5, "far_sphere_r1e3_scale1e5"),
    ("edge_mesh", 1.0, "edge_mesh"),
    ("grazing", 1.0, "grazing"),
    ("mirrors", 1.0, "mirrors"),
    ("degenerate", 1.0, "degenerate"),
    ("inside_sphere", 1.0, "inside_sphere"),
    # Scales where the fixed offset is measured to break (small: too big for the scene,
    # large: below the coordinates' rounding error).
    ("mirrors", 1e-2, "mirrors_scale1e-2"),
    ("mirrors", 1e4, "mirrors_scale1e4"),
    ("degenerate", 1e-3, "degenerate_scale1e-3"),
    ("degenerate", 1e3, "degenerate_scale1e3"),
    ("inside_sphere", 1e-4, "inside_sphere_scale1e-4"),
    ("inside_sphere", 1e3, "inside_sphere_scale1e3"),
    ("ground", 1e1, "ground_e1e1"),
    ("ground", 1e3, "ground_e1e3"),
    ("ground", 2e5, "ground_e2e5"),
    ("ground", 1e6, "ground_e1e6"),
    ("ground_small", 1e1, "ground_small_e1e1"),
    ("ground_small", 1e3, "ground_small_e1e3"),
    ("ground_high", 1e6, "ground_high_e1e6"),
    ("ground_overhead", 1e5, "ground_overhead_e1e5"),
    ("ground_mirror", 1e5, "ground_mirror_e1e5"),
]


def must_fail_text(entries):
    if not entries:
        return "-"
    return ";".join("+".join("%s:%s" % kv for kv in sorted(e.items())) for e in entries)


def index_line(stem, family, value, settings):
    fields = [
        ("file", stem + ".scene"), ("family", family), ("parameter", FAMILIES[family][0]),
        ("value", "%.17g" % value), ("width", settings.get("width", WIDTH)),
        ("height", settings.get("height", HEIGHT)), ("fov", "%.17g" % settings["fov"]),
        ("depth", settings["depth"]), ("axes", ",".join(settings["axes"])),
        ("must_fail", must_fail_text(settings["must_fail"])),
    ]
    return " ".join("%s=%s" % kv for kv in fields)


INDEX_HEADER = ("# Stress scenes (written by tools/make_stress_scenes.py; do not edit by hand).\n"
                "# One scene per line: file family parameter value width height fov depth axes "
                "must_fail\n")


def build(entries):
    """{file name: text} for (family, value, stem) entries, index.txt included."""
    files = {}
    lines = []
    for family, value, stem in entries:
        text, settings = FAMILIES[family][1](value)
        files[stem + ".scene"] = text
        lines.append(index_line(stem, family, value, settings))
    files[INDEX_NAME] = INDEX_HEADER + "\n".join(lines) + "\n"
    return files


def write(files, folder):
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (folder / name).write_text(text)


def check(files, folder):
    problems = []
    for name, text in files.items():
        path = folder / name
        if not path.exists():
            problems.append("%s is missing" % path)
        elif path.read_text() != text:
            problems.append("%s differs from the generator's output" % path)
    expected = set(files)
    for path in sorted(folder.glob("*")):
        if path.name not in expected and path.name != "README.md":
            problems.append("%s is not written by the generator" % path)
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, help="folder to write (default scenes/stress)")
    parser.add_argument("--check", action="store_true",
                        help="compare scenes/stress (or --out) with the output instead of writing")
    parser.add_argument("--family", choices=sorted(FAMILIES), help="write one family instead")
    parser.add_argument("--values", type=float, nargs="+",
                        help="the family's parameter values (with --family)")
    args = parser.parse_args()
    if args.family:
        if not args.values or not args.out:
            parser.error("--family needs --values and --out")
        entries = [(args.family, v, "%s_%s" % (args.family, scale_name(v))) for v in args.values]
    else:
        if args.values:
            parser.error("--values needs --family")
        entries = COMMITTED
    files = build(entries)
    folder = args.out or STRESS_DIR
    if args.check:
        problems = check(files, folder)
        for p in problems:
            print("make_stress_scenes: " + p, file=sys.stderr)
        if problems:
            print("make_stress_scenes: regenerate with: python3 tools/make_stress_scenes.py",
                  file=sys.stderr)
            return 1
        return 0
    write(files, folder)
    return 0


if __name__ == "__main__":
    sys.exit(main())
