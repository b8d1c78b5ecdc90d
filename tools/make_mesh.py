#!/usr/bin/env python3
"""Write a Raytracer scene holding one smooth triangle mesh, or the mesh alone as OBJ.

    python3 tools/make_mesh.py --shape torus --triangles 2000 --out FILE
    python3 tools/make_mesh.py --shape knot --triangles 1000000 --out knot.obj
    python3 tools/make_mesh.py --shape knot --triangles 100000 --out knot.obj --texture checker.png

Shapes: torus, sphere (UV sphere), knot (a (p,q) torus-knot tube). Every
vertex carries its exact analytic surface normal, so the mesh shades smoothly.
By default the scene also holds a ground made of two triangles, two spheres
(one a mirror) and two coloured lights; --bare leaves only the mesh and the
lights. The triangle count is approximate: the nearest count that the shape's
grid can make (see --triangles). An --out name ending in .obj writes the mesh
alone as Wavefront OBJ (v, vn and f lines; with --color ramp each v carries
its colour as `v x y z r g b`): Raytracer then adds the floor and lights of a
model (docs/models.md), so the ground, spheres and lights are not written.
With --texture IMAGE.png (OBJ of a torus or knot only) it also writes a 1024x1024
checkerboard PNG there, NAME.mtl whose one material has it as map_Kd, and `vt`
texture coordinates (u along the shape's length, repeated so the checks stay
square, v around it) that faces name as v/vt/vn.

Deterministic (no randomness, no clock), standard library only, O(N) time and
memory in the number of vertices, and it prints nothing but errors. Numbers
are written with %.9g, enough for single precision to read them back exactly.
"""

import argparse
import math
import os
import sys

FMT = "%.9g"


def fmt(x):
    s = FMT % x
    return "0" if s == "-0" else s


def vec(v):
    return "%s %s %s" % (fmt(v[0]), fmt(v[1]), fmt(v[2]))


def normalize(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if n == 0.0:
        return (0.0, 0.0, 0.0)
    return (v[0] / n, v[1] / n, v[2] / n)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


# ---------------------------------------------------------------- shapes ---
# Each builder returns (positions, normals, params, triangles): positions and
# normals in object space (about unit size, centred on the origin, y up),
# params a value in [0,1) per vertex used for the colour ramp, triangles a
# list of vertex-index triples.


class GridTriangles:
    """The triangles of the quads of a nu x nv vertex grid that wraps in u (and in v if
    wrap_v), made as they are read: a list of 30 million tuples would take gigabytes."""

    def __init__(self, nu, nv, wrap_v):
        self.nu, self.nv, self.vcount = nu, nv, nv if wrap_v else nv - 1

    def __len__(self):
        return 2 * self.nu * self.vcount

    def __iter__(self):
        nu, nv = self.nu, self.nv
        for i in range(nu):
            i1 = (i + 1) % nu
            for j in range(self.vcount):
                j1 = (j + 1) % nv
                a, b = i * nv + j, i1 * nv + j
                c, d = i1 * nv + j1, i * nv + j1
                yield (a, b, c)
                yield (a, c, d)


def grid_triangles(nu, nv, wrap_v):
    return GridTriangles(nu, nv, wrap_v)


def torus(n, major=1.0, minor=0.4):
    # 2 * nu * nv triangles; nu / nv = major / minor keeps the quads square.
    ratio = major / minor
    nv = max(3, int(round(math.sqrt(n / (2.0 * ratio)))))
    nu = max(3, int(round(n / (2.0 * nv))))
    pos, nor, par = [], [], []
    for i in range(nu):
        u = 2.0 * math.pi * i / nu
        cu, su = math.cos(u), math.sin(u)
        for j in range(nv):
            v = 2.0 * math.pi * j / nv
            cv, sv = math.cos(v), math.sin(v)
            # Ring in the xz plane, tube around it; y is up.
            nx, ny, nz = cv * cu, sv, cv * su
            r = major + minor * cv
            pos.append((r * cu, minor * sv, r * su))
            nor.append((nx, ny, nz))
            par.append(i / nu)
    return pos, nor, par, grid_triangles(nu, nv, True), (nu, nv)


def uv_sphere(n):
    # nu longitudes, nv latitude rings between the poles (poles included):
    # 2 * nu * (nv - 2) quad triangles + 2 * nu cap triangles = 2 nu (nv - 1).
    nv = max(3, int(round(math.sqrt(n / 4.0) + 0.5)))
    nu = max(3, int(round(n / (2.0 * (nv - 1)))))
    pos, nor, par = [], [], []
    # Vertex 0: north pole, 1: south pole, then the rings 1 .. nv-2.
    pos.append((0.0, 1.0, 0.0)); nor.append((0.0, 1.0, 0.0)); par.append(0.0)
    pos.append((0.0, -1.0, 0.0)); nor.append((0.0, -1.0, 0.0)); par.append(0.999)
    rings = nv - 2
    for k in range(1, nv - 1):
        theta = math.pi * k / (nv - 1)
        st, ct = math.sin(theta), math.cos(theta)
        for i in range(nu):
            phi = 2.0 * math.pi * i / nu
            p = (st * math.cos(phi), ct, st * math.sin(phi))
            pos.append(p); nor.append(p); par.append(k / (nv - 1))

    def ring(k, i):  # k in 0 .. rings-1
        return 2 + k * nu + (i % nu)

    tris = []
    for i in range(nu):
        tris.append((0, ring(0, i + 1), ring(0, i)))
        tris.append((1, ring(rings - 1, i), ring(rings - 1, i + 1)))
    for k in range(rings - 1):
        for i in range(nu):
            a, b = ring(k, i), ring(k, i + 1)
            c, d = ring(k + 1, i + 1), ring(k + 1, i)
            tris.append((a, b, c))
            tris.append((a, c, d))
    return pos, nor, par, tris, None


def knot(n, p=2, q=3, major=0.75, amp=0.35, tube=0.16):
    """Tube of radius `tube` around the (p,q) torus knot, in the xy plane."""

    def curve(t):
        ct, st = math.cos(q * t), math.sin(q * t)
        cp, sp = math.cos(p * t), math.sin(p * t)
        rho, drho, ddrho = major + amp * ct, -amp * q * st, -amp * q * q * ct
        c = (rho * cp, rho * sp, amp * st)
        d1 = (drho * cp - rho * p * sp, drho * sp + rho * p * cp, amp * q * ct)
        d2 = (ddrho * cp - 2 * drho * p * sp - rho * p * p * cp,
              ddrho * sp + 2 * drho * p * cp - rho * p * p * sp,
              -amp * q * q * st)
        return c, d1, d2

    # Square quads: samples along the curve / around the tube = length / circumference.
    length = 0.0
    steps = 256
    for k in range(steps):
        length += math.sqrt(sum(x * x for x in curve(2 * math.pi * (k + 0.5) / steps)[1]))
    length *= 2 * math.pi / steps
    ratio = length / (2 * math.pi * tube)
    nv = max(3, int(round(math.sqrt(n / (2.0 * ratio)))))
    nu = max(3, int(round(n / (2.0 * nv))))
    pos, nor, par = [], [], []
    for i in range(nu):
        t = 2.0 * math.pi * i / nu
        c, d1, d2 = curve(t)
        T = normalize(d1)
        B = normalize(cross(d1, d2))  # Frenet frame: periodic, so no seam
        N = cross(B, T)
        for j in range(nv):
            v = 2.0 * math.pi * j / nv
            cv, sv = math.cos(v), math.sin(v)
            nrm = (cv * N[0] + sv * B[0], cv * N[1] + sv * B[1], cv * N[2] + sv * B[2])
            pos.append((c[0] + tube * nrm[0], c[1] + tube * nrm[1], c[2] + tube * nrm[2]))
            nor.append(nrm)
            par.append(i / nu)
    return pos, nor, par, grid_triangles(nu, nv, True), (nu, nv)


SHAPES = {"torus": torus, "sphere": uv_sphere, "knot": knot}
# Default tilt (degrees about x, then about y) that shows each shape well.
DEFAULT_TILT = {"torus": (35.0, 0.0), "sphere": (0.0, 0.0), "knot": (-20.0, 0.0)}


# --------------------------------------------------------------- colours ---

def ramp(t):
    """A smooth, fully saturated-ish hue ring, returned in [0.1, 0.9]."""
    out = []
    for k in range(3):
        c = 0.5 + 0.4 * math.cos(2.0 * math.pi * (t - k / 3.0))
        out.append(round(c, 3))
    return tuple(out)


# ------------------------------------------------------------------ main ---

def vector(text):
    """X,Y,Z as the scene format and Raytracer's options write a vector."""
    parts = text.split(",")
    try:
        values = tuple(float(part) for part in parts)
    except ValueError:
        values = ()
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError(f"expected three finite numbers X,Y,Z, got '{text}'")
    return values


def parse_args(argv):
    ap = argparse.ArgumentParser(description="Write a Raytracer scene with one smooth mesh.")
    ap.add_argument("--shape", choices=sorted(SHAPES), default="torus")
    ap.add_argument("--triangles", type=int, default=2000,
                    help="approximate number of mesh triangles (>= 8)")
    ap.add_argument("--out", required=True, help="scene file to write ('-' for stdout), or NAME.obj for the mesh as OBJ")
    ap.add_argument("--center", type=vector, default=(0.0, 0.0, -4.0), metavar="X,Y,Z",
                    help="mesh centre (default 0,0,-4)")
    ap.add_argument("--scale", type=float, default=1.0, help="uniform scale (default 1)")
    ap.add_argument("--rotate-x", type=float, default=None,
                    help="tilt about x in degrees (default depends on the shape)")
    ap.add_argument("--rotate-y", type=float, default=None, help="turn about y in degrees")
    ap.add_argument("--color", "--colour", choices=["ramp", "solid"], default="ramp",
                    help="per-vertex hue ramp (default) or one colour")
    ap.add_argument("--specular", type=float, default=0.25,
                    help="mesh spe (grey); also its mirror weight (default 0.25)")
    ap.add_argument("--shininess", type=float, default=40.0)
    ap.add_argument("--texture", metavar="IMAGE.png",
                    help="OBJ of a torus or knot: texture coordinates and a checkerboard map_Kd written there")
    ap.add_argument("--no-normals", action="store_true",
                    help="OBJ: no vn lines, faces of positions alone (with --color solid, the "
                         "positions-and-faces file of a scan)")
    ap.add_argument("--bare", action="store_true",
                    help="only the mesh and two lights: no ground, no extra spheres")
    a = ap.parse_args(argv)
    if a.triangles < 8:
        ap.error("--triangles must be at least 8")
    if not a.scale > 0 or not math.isfinite(a.scale):
        ap.error("--scale must be a positive number")
    if not 0.0 <= a.specular <= 1.0:
        ap.error("--specular must be within [0, 1]")
    if not a.shininess >= 0.0:
        ap.error("--shininess must not be negative")
    if a.no_normals and (a.texture or not a.out.lower().endswith(".obj")):
        ap.error("--no-normals is for an OBJ without --texture")
    if a.texture and (a.shape == "sphere" or not a.out.lower().endswith(".obj")):
        ap.error("--texture needs a torus or knot written as OBJ")
    return a


def grid_texcoords(triangles, grid):
    """vt lines of a wrapping nu x nv grid's (nu + 1) x (nv + 1) corners, the seams' twice,
    and each triangle's three vt indices (0-based): u = i / nu times the repeats that keep
    a check square, v = j / nv."""
    nu, nv = grid
    repeats = max(1, round(nu / nv))
    lines = ["vt %s %s\n" % (fmt(repeats * i / nu), fmt(j / nv)) for i in range(nu + 1) for j in range(nv + 1)]
    uvs = []
    for tri in triangles:
        ij = [(t // nv, t % nv) for t in tri]
        # A triangle across a seam names the far side's column (row) as nu (nv), not 0.
        wrap_i = max(i for i, _ in ij) - min(i for i, _ in ij) > 1
        wrap_j = max(j for _, j in ij) - min(j for _, j in ij) > 1
        uvs.append(tuple((nu if wrap_i and i == 0 else i) * (nv + 1) + (nv if wrap_j and j == 0 else j)
                         for i, j in ij))
    return lines, uvs


def write_texture(obj_path, image_path):
    """The checkerboard PNG at image_path and the MTL beside obj_path naming it; returns the
    OBJ's mtllib and usemtl lines."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
    from png_write import write_png
    size, check = 1024, 32
    rows = [[(230, 200, 120) if (x // check + y // check) % 2 else (40, 90, 160) for x in range(size)]
            for y in range(size)]
    write_png(image_path, size, size, rows)
    mtl = os.path.splitext(obj_path)[0] + ".mtl"
    with open(mtl, "w") as out:
        out.write("newmtl checker\nKd 0.8 0.8 0.8\nKs 0.25 0.25 0.25\nNs 40\nillum 2\nmap_Kd %s\n"
                  % os.path.relpath(image_path, os.path.dirname(os.path.abspath(obj_path))))
    return "mtllib %s\nusemtl checker\n" % os.path.basename(mtl)


def write_obj(path, positions, normals, colors, triangles, texcoords=None):
    """The mesh as OBJ: one v (with its colour, if any) and one vn per vertex (none when
    normals is None: the reader makes them), one f each; positions, normals and colours
    may be generators, written as they come;
    with texcoords (grid_texcoords' vt lines and indices), f's corners are v/vt/vn and the
    header names the material (write_texture's lines)."""
    with open(path, "w", newline="\n") as out:
        out.write("# %d triangles, written by tools/make_mesh.py\n" % len(triangles))
        if texcoords:
            out.write(texcoords[2])

        def lines(texts):
            chunk = []
            for text in texts:
                chunk.append(text)
                if len(chunk) >= 40000:
                    out.writelines(chunk)
                    chunk = []
            out.writelines(chunk)

        if colors is not None:
            lines("v %s %s\n" % (vec(p), vec(c)) for p, c in zip(positions, colors))
        else:
            lines("v %s\n" % vec(p) for p in positions)
        if normals is not None:
            lines("vn %s\n" % vec(n) for n in normals)
        if texcoords:
            out.writelines(texcoords[0])
        if texcoords:
            faces = ("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (i + 1, ti + 1, i + 1, j + 1, tj + 1, j + 1,
                                                       k + 1, tk + 1, k + 1)
                     for (i, j, k), (ti, tj, tk) in zip(triangles, texcoords[1]))
        elif normals is not None:
            faces = ("f %d//%d %d//%d %d//%d\n" % (i + 1, i + 1, j + 1, j + 1, k + 1, k + 1)
                     for i, j, k in triangles)
        else:
            faces = ("f %d %d %d\n" % (i + 1, j + 1, k + 1) for i, j, k in triangles)
        lines(faces)
    return 0


def main(argv):
    a = parse_args(argv)
    pos, nor, par, tris, grid = SHAPES[a.shape](a.triangles)

    rx, ry = DEFAULT_TILT[a.shape]
    if a.rotate_x is not None:
        rx = a.rotate_x
    if a.rotate_y is not None:
        ry = a.rotate_y
    cx, sx = math.cos(math.radians(rx)), math.sin(math.radians(rx))
    cy, sy = math.cos(math.radians(ry)), math.sin(math.radians(ry))

    def rot(v):
        x, y, z = v
        y, z = cx * y - sx * z, sx * y + cx * z  # about x
        x, z = cy * x + sy * z, -sy * x + cy * z  # about y
        return (x, y, z)

    s = a.scale
    ox, oy, oz = a.center
    spe = "spe: %s %s %s\nshi: %s\n" % (fmt(a.specular), fmt(a.specular), fmt(a.specular),
                                       fmt(a.shininess))
    solid = (0.85, 0.55, 0.2)
    # Each vertex is formatted once; triangles reuse the text, so emitting is O(N).

    def place(v):
        p = rot(v)
        return (ox + s * p[0], oy + s * p[1], oz + s * p[2])

    if a.out.lower().endswith(".obj"):
        texcoords = None
        if a.texture:
            texcoords = (*grid_texcoords(tris, grid), write_texture(a.out, a.texture))
        return write_obj(a.out, (place(p) for p in pos),
                         None if a.no_normals else (rot(n) for n in nor),
                         (ramp(t) for t in par) if a.color == "ramp" else None, tris, texcoords)

    blocks = []
    ymin = math.inf
    for k in range(len(pos)):
        p = place(pos[k])
        ymin = min(ymin, p[1])
        col = ramp(par[k]) if a.color == "ramp" else solid
        blocks.append("pos: %s\nnor: %s\ndif: %s\n%s" % (vec(p), vec(rot(nor[k])), vec(col), spe))

    extras = []
    lights = [
        "light\npos: %s\ncol: 0.85 0.8 0.7\n" % vec((ox - 4.0 * s, oy + 6.0 * s, oz + 3.0 * s)),
        "light\npos: %s\ncol: 0.3 0.35 0.5\n" % vec((ox + 5.0 * s, oy + 3.0 * s, oz + 4.0 * s)),
    ]
    if not a.bare:
        g = ymin - 0.35 * s  # ground a little below the mesh, so it casts a visible shadow
        x0, x1 = ox - 12.0 * s, ox + 12.0 * s
        z0, z1 = oz + 3.5 * s, oz - 16.0 * s
        ground_v = lambda x, z, d: ("pos: %s\nnor: 0 1 0\ndif: %s\nspe: 0.15 0.15 0.15\nshi: 20\n"
                                    % (vec((x, g, z)), d))
        light_grey, dark_grey = "0.75 0.75 0.72", "0.45 0.45 0.5"
        extras.append("triangle\n" + ground_v(x0, z0, light_grey) + ground_v(x1, z0, light_grey)
                      + ground_v(x1, z1, dark_grey))
        extras.append("triangle\n" + ground_v(x0, z0, light_grey) + ground_v(x1, z1, dark_grey)
                      + ground_v(x0, z1, dark_grey))
        r1, r2 = 0.55 * s, 0.35 * s
        extras.append("sphere\npos: %s\nrad: %s\ndif: 0.05 0.05 0.05\nspe: 0.9 0.9 0.9\nshi: 200\n"
                      % (vec((ox - 1.9 * s, g + r1, oz - 1.2 * s)), fmt(r1)))
        extras.append("sphere\npos: %s\nrad: %s\ndif: 0.2 0.35 0.8\nspe: 0.3 0.3 0.3\nshi: 60\n"
                      % (vec((ox + 1.8 * s, g + r2, oz + 0.2 * s)), fmt(r2)))

    count = len(lights) + len(extras) + len(tris)
    out = sys.stdout if a.out == "-" else open(a.out, "w", newline="\n")
    try:
        out.write("%d\namb: 0.08 0.08 0.09\n" % count)
        out.writelines(lights)
        out.writelines(extras)
        chunk = []
        for (i, j, k) in tris:
            chunk.append("triangle\n")
            chunk.append(blocks[i])
            chunk.append(blocks[j])
            chunk.append(blocks[k])
            if len(chunk) >= 40000:
                out.writelines(chunk)
                chunk = []
        out.writelines(chunk)
    finally:
        if out is not sys.stdout:
            out.close()
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except OSError as e:
        print("make_mesh.py: error: %s" % e, file=sys.stderr)
        sys.exit(1)
