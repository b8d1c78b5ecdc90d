#!/usr/bin/env python3
"""Make the models of docs/gallery.md and render them as a user would.

    python3 tools/make_gallery.py --raytracer build/Raytracer --models out/gallery \\
        --images docs/images

Writes six Wavefront OBJ models with their MTL materials into --models, all made
here from formulas (none copied from elsewhere): a (3,2) torus-knot tube of quads
(knot.obj), an icosahedron split once into 80 faces (gem.obj, shown with flat
facets), a vase turned from a profile, written z-up as CAD and Blender models
often are (vase.obj), a flat star (star.obj), a long pencil (pencil.obj) and a
scanned-looking stone with vertex colours (rock.obj, also written as binary PLY,
rock.ply, by tools/convert_model.py) and a banded gas giant, a sphere with texture
coordinates and a 512x256 texture of its own (planet.obj with planet.png, also written
as GLB with the texture inside it, planet.glb). Then renders each with Raytracer, straight
from the model file (framed, on a floor, lit: docs/models.md), to
--images/gallery-NAME.png, and prints each command. Deterministic; standard
library only.
"""

import argparse
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from png_write import write_png  # noqa: E402

FMT = "%.6f"


def write_model(folder, name, positions, faces, material, colours=None):
    """NAME.obj (positions, faces of 1-based indices, a colour per position when given) and
    NAME.mtl with one material."""
    with open(os.path.join(folder, name + ".mtl"), "w") as out:
        out.write("newmtl %s\nKd %s\nKs %s\nNs %g\nillum %d\n" % (
            name, " ".join(FMT % c for c in material["Kd"]), " ".join(FMT % c for c in material["Ks"]),
            material["Ns"], material.get("illum", 2)))
    with open(os.path.join(folder, name + ".obj"), "w") as out:
        out.write("# made by tools/make_gallery.py\nmtllib %s.mtl\n" % name)
        for i, p in enumerate(positions):
            colour = " " + " ".join(FMT % c for c in colours[i]) if colours else ""
            out.write("v %s%s\n" % (" ".join(FMT % c for c in p), colour))
        out.write("usemtl %s\n" % name)
        for face in faces:
            out.write("f %s\n" % " ".join(str(i + 1) for i in face))


def planet_texture(width=512, height=256):
    """Rows of a gas giant's texture: bands of cream, tan and rust by latitude, their edges
    waved by longitude, and one oval storm."""
    bands = [(0.93, 0.87, 0.74), (0.80, 0.62, 0.45), (0.91, 0.80, 0.62), (0.66, 0.42, 0.30),
             (0.95, 0.90, 0.80), (0.75, 0.55, 0.40), (0.88, 0.76, 0.60), (0.60, 0.40, 0.30),
             (0.94, 0.88, 0.76), (0.78, 0.60, 0.46), (0.90, 0.82, 0.66), (0.70, 0.50, 0.36)]
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            u, v = (x + 0.5) / width, (y + 0.5) / height
            wave = 0.006 * math.sin(2 * math.pi * (4 * u + 9 * v)) + 0.004 * math.sin(2 * math.pi * (13 * u - 3 * v))
            t = (v + wave) * len(bands)
            i, f = int(t) % len(bands), t - math.floor(t)
            a, b = bands[i], bands[(i + 1) % len(bands)]
            blend = max(0.0, min(1.0, (f - 0.8) / 0.2))
            colour = [a[k] * (1 - blend) + b[k] * blend for k in range(3)]
            du, dv = (u - 0.86) / 0.045, (v - 0.36) / 0.03
            storm = math.exp(-(du * du + dv * dv))
            colour = [colour[0] * (1 - storm) + 0.82 * storm, colour[1] * (1 - storm) + 0.24 * storm,
                      colour[2] * (1 - storm) + 0.14 * storm]
            row.append(tuple(int(round(255 * c)) for c in colour))
        rows.append(row)
    return rows


def write_planet(folder, rings=48, sides=96):
    """planet.obj: a unit sphere of rings x sides quads (triangles at the poles), each
    corner with texture coordinates (u round it, v up it; the seam's column twice, at u 0
    and 1), its material's map_Kd planet.png (planet_texture)."""
    with open(os.path.join(folder, "planet.mtl"), "w") as out:
        out.write("newmtl planet\nKd 0.8 0.8 0.8\nKs 0.05 0.05 0.05\nNs 10\nillum 2\nmap_Kd planet.png\n")
    rows = planet_texture()
    write_png(os.path.join(folder, "planet.png"), len(rows[0]), len(rows), rows)
    with open(os.path.join(folder, "planet.obj"), "w") as out:
        out.write("# made by tools/make_gallery.py\nmtllib planet.mtl\n")
        for r in range(rings + 1):
            theta = math.pi * r / rings
            for s in range(sides + 1):
                phi = 2 * math.pi * s / sides
                out.write("v %s\n" % " ".join(FMT % c for c in (
                    math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))))
                out.write("vt %s %s\n" % (FMT % (s / sides), FMT % (1 - r / rings)))
        out.write("usemtl planet\n")
        for r in range(rings):
            for s in range(sides):
                a, b = r * (sides + 1) + s + 1, (r + 1) * (sides + 1) + s + 1
                corners = [(a, a), (b, b), (b + 1, b + 1), (a + 1, a + 1)]
                if r == 0:
                    corners = corners[:3]  # a and a + 1 are the north pole
                elif r == rings - 1:
                    corners = [corners[0], corners[1], corners[3]]  # b and b + 1 the south pole
                out.write("f %s\n" % " ".join("%d/%d" % c for c in corners))


def knot(segments=240, sides=16, radius=0.35):
    """A (3,2) torus knot's tube: a ring of `sides` corners around each point of the
    curve, joined into quads."""
    def curve(t):
        r = 2.0 + math.cos(3.0 * t)
        return (r * math.cos(2.0 * t), r * math.sin(2.0 * t), -math.sin(3.0 * t))

    positions = []
    for i in range(segments):
        t = 2.0 * math.pi * i / segments
        p, q = curve(t), curve(t + 1e-4)
        tangent = [q[k] - p[k] for k in range(3)]
        n = math.sqrt(sum(c * c for c in tangent))
        tangent = [c / n for c in tangent]
        # A frame around the tangent: the normal towards the z axis, the binormal across.
        up = (0.0, 0.0, 1.0)
        b = [tangent[1] * up[2] - tangent[2] * up[1], tangent[2] * up[0] - tangent[0] * up[2],
             tangent[0] * up[1] - tangent[1] * up[0]]
        nb = math.sqrt(sum(c * c for c in b))
        b = [c / nb for c in b]
        normal = [b[1] * tangent[2] - b[2] * tangent[1], b[2] * tangent[0] - b[0] * tangent[2],
                  b[0] * tangent[1] - b[1] * tangent[0]]
        for j in range(sides):
            a = 2.0 * math.pi * j / sides
            positions.append(tuple(p[k] + radius * (math.cos(a) * normal[k] + math.sin(a) * b[k]) for k in range(3)))
    faces = []
    for i in range(segments):
        for j in range(sides):
            a, b = i * sides + j, i * sides + (j + 1) % sides
            c, d = ((i + 1) % segments) * sides + (j + 1) % sides, ((i + 1) % segments) * sides + j
            faces.append((a, b, c, d))
    return positions, faces


def gem(levels=1):
    """An icosahedron with each face split into four, pushed out onto the sphere, levels
    times."""
    g = (1.0 + math.sqrt(5.0)) / 2.0
    corners = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
               (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    positions = [tuple(c / math.sqrt(1 + g * g) for c in p) for p in corners]
    middle = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in middle:
            m = [(positions[a][k] + positions[b][k]) / 2.0 for k in range(3)]
            n = math.sqrt(sum(c * c for c in m))
            positions.append(tuple(c / n for c in m))
            middle[key] = len(positions) - 1
        return middle[key]

    for _ in range(levels):
        split = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return positions, faces


def rock():
    """A scanned-looking stone: an icosahedron split four times (5,120 triangles), its
    surface pushed in and out by a sum of sines and flattened, each vertex coloured from
    sandstone to rust by its height and bumps, as a photogrammetry scan comes."""
    positions, faces = gem(levels=4)
    shaped, colours = [], []
    for x, y, z in positions:
        bump = (0.08 * math.sin(5.0 * x + 1.3) * math.sin(4.0 * z + 0.7) + 0.05 * math.sin(11.0 * y + 3.0 * x)
                + 0.03 * math.sin(17.0 * z - 7.0 * y))
        r = 1.0 + bump
        shaped.append((1.3 * r * x, 0.75 * r * y, r * z))
        t = min(1.0, max(0.0, 0.45 + 0.2 * y + 5.0 * bump))
        colours.append((0.35 + 0.5 * t, 0.22 + 0.45 * t, 0.18 + 0.3 * t))
    return shaped, faces, colours


def vase(rings=48, sides=48):
    """A surface of revolution about z (so the model is z-up), from a profile of radius
    against height, open at the top, closed by a fan at the bottom."""
    positions, faces = [], []
    for i in range(rings + 1):
        h = 2.0 * i / rings
        r = 0.32 + 0.2 * math.sin(math.pi * h * 0.6) + 0.06 * math.cos(math.pi * h * 1.5)
        for j in range(sides):
            a = 2.0 * math.pi * j / sides
            positions.append((r * math.cos(a), r * math.sin(a), h))
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, i * sides + (j + 1) % sides
            faces.append((a, b, b + sides, a + sides))
    faces.append(tuple(reversed(range(sides))))  # the base, one polygon
    return positions, faces


def star(points=5, outer=1.0, inner=0.45):
    """A flat star lying in the y = 0 plane: one concave polygon of 2 * points corners (ear
    clipped), facing up, as a flat model (a decal, a floor tile) lies."""
    positions = []
    for k in range(2 * points):
        a = math.pi * k / points
        r = outer if k % 2 == 0 else inner
        positions.append((r * math.sin(a), 0.0, r * math.cos(a)))
    return positions, [tuple(reversed(range(2 * points)))]


def pencil(sides=6, length=8.0, radius=0.2, tip=0.6):
    """A hexagonal pencil lying along z, 20 times as long as it is wide, sharpened to a
    point at +z: a long model, which the fit must frame whole."""
    positions, faces = [], []
    for z in (-length / 2, length / 2 - tip):
        for k in range(sides):
            a = 2 * math.pi * k / sides
            positions.append((radius * math.cos(a), radius * math.sin(a), z))
    positions.append((0.0, 0.0, length / 2))
    for k in range(sides):
        n = (k + 1) % sides
        faces.append((k, n, sides + n, sides + k))
        faces.append((sides + k, sides + n, 2 * sides))
    faces.append(tuple(reversed(range(sides))))
    return positions, faces


MODELS = {
    "knot": (knot, {"Kd": (0.8, 0.42, 0.2), "Ks": (0.3, 0.3, 0.3), "Ns": 60}, []),
    "gem": (gem, {"Kd": (0.15, 0.3, 0.8), "Ks": (0.45, 0.45, 0.45), "Ns": 200, "illum": 3}, ["--crease", "10"]),
    "vase": (vase, {"Kd": (0.9, 0.88, 0.8), "Ks": (0.15, 0.15, 0.15), "Ns": 40}, ["--up", "z"]),
    "star": (star, {"Kd": (0.95, 0.75, 0.1), "Ks": (0.5, 0.5, 0.5), "Ns": 80}, []),
    "pencil": (pencil, {"Kd": (0.95, 0.6, 0.1), "Ks": (0.6, 0.6, 0.6), "Ns": 120}, ["--crease", "40"]),
    # Written as OBJ with vertex colours, then as binary PLY by tools/convert_model.py, and
    # rendered from the PLY file (which holds no material: the default one, and its colours).
    "rock": (rock, {"Kd": (0.75, 0.75, 0.75), "Ks": (0.1, 0.1, 0.1), "Ns": 30}, []),
}
# Written by its own function (with a texture), not write_model: name -> (writer, options).
TEXTURED = {"planet": (write_planet, [])}
# The models rendered from another format than their OBJ file: name -> (extension, options
# of tools/convert_model.py).
CONVERTED = {"rock": (".ply", []), "planet": (".glb", ["--texture", "planet.png"])}


def main(argv=None):
    parser = argparse.ArgumentParser(description="Make the gallery's models and render them with Raytracer.")
    parser.add_argument("--raytracer", required=True, help="the Raytracer program")
    parser.add_argument("--models", required=True, help="the folder for the OBJ and MTL files")
    parser.add_argument("--images", required=True, help="the folder for gallery-NAME.png")
    parser.add_argument("--width", type=int, default=480)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--spp", type=int, default=4)
    args = parser.parse_args(argv)
    os.makedirs(args.models, exist_ok=True)
    os.makedirs(args.images, exist_ok=True)
    models = {name: (make, material, options) for name, (make, material, options) in MODELS.items()}
    models.update({name: (None, None, options) for name, (_, options) in TEXTURED.items()})
    for name, (make, material, options) in models.items():
        if make:
            made = make()
            write_model(args.models, name, made[0], made[1], material, made[2] if len(made) > 2 else None)
        else:
            TEXTURED[name][0](args.models)
        model = os.path.join(args.models, name + ".obj")
        if name in CONVERTED:
            extension, convert_options = CONVERTED[name]
            converted = os.path.join(args.models, name + extension)
            convert = [sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "convert_model.py"),
                       model, converted,
                       *[os.path.join(args.models, o) if o.endswith(".png") else o for o in convert_options]]
            print(" ".join(convert[1:]))
            if subprocess.run(convert).returncode != 0:
                return 1
            model = converted
        command = [args.raytracer, model, *options, "--width", str(args.width),
                   "--height", str(args.height), "--spp", str(args.spp), "-o",
                   os.path.join(args.images, "gallery-%s.png" % name)]
        print(" ".join(command))
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0 or not os.path.isfile(command[-1]):
            print("make_gallery: %s failed (%d):\n%s" % (name, done.returncode, done.stderr), file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
