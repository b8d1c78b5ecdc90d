#!/usr/bin/env python3
"""Convert a Wavefront OBJ model to a Raytracer scene.

    python3 tools/obj_to_scene.py model.obj -o model.scene --fit

Reads v, vn, f and usemtl/mtllib statements. Faces may be triangles or convex
polygons (fan-triangulated from their first corner), with corners written as
v, v/vt, v/vt/vn or v//vn, and with positive or negative (relative) indices.
A corner without a normal gets a smooth one: the area-weighted average of the
normals of the faces that share its position. Texture coordinates are read and
ignored. `v x y z r g b` vertex colours become the corner's diffuse colour.

Materials (from the MTL files that mtllib names, looked up beside the OBJ):
Kd becomes dif, Ks spe (the renderer also uses it as the mirror weight) and Ns
shi; colours are clamped to [0, 1] and Ns to [0, 1000]. Faces without a known
material get a light grey default.

The scene's camera sits at the origin looking down -z. --fit moves and scales
the model (uniformly) to sit centred at z = -3 with its largest side 1.5 long,
so any model shows up in view. One white light sits above the camera unless
--light is given (it may be repeated).

Triangles that are degenerate (two corners with one position, or no area)
are left out and counted on stderr. A malformed line is an error that names
the file and line ("model.obj:12: error: ..."); the exit status is then 1.
Python 3, standard library only.
"""

import argparse
import math
import os
import sys

FMT = "%.9g"

DEFAULT_MATERIAL = {"dif": (0.75, 0.75, 0.75), "spe": (0.1, 0.1, 0.1), "shi": 30.0}
FIT_CENTRE = (0.0, 0.0, -3.0)
FIT_SIZE = 1.5
MAX_SHININESS = 1000.0


class ConversionError(Exception):
    """A problem with the input, with the place it was found."""

    def __init__(self, path, line, message):
        super().__init__("%s:%d: error: %s" % (path, line, message) if line else "%s: error: %s" % (path, message))


# ------------------------------------------------------------------ vectors ---


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(v):
    return math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])


def normalize(v):
    n = length(v)
    return (v[0] / n, v[1] / n, v[2] / n) if n > 0.0 else (0.0, 0.0, 0.0)


def clamp(x, low, high):
    return min(max(x, low), high)


# ------------------------------------------------------------------ reading ---


def logical_lines(path):
    """(line number, text) of each statement; a trailing backslash continues a line."""
    try:
        with open(path, "r", encoding="utf-8", errors="replace") as handle:
            pending, start = "", 0
            for number, raw in enumerate(handle, 1):
                text = raw.rstrip("\r\n")
                if not pending:
                    start = number
                if text.endswith("\\"):
                    pending += text[:-1] + " "
                    continue
                yield start, pending + text
                pending = ""
            if pending:
                yield start, pending
    except OSError as error:
        raise ConversionError(path, 0, "cannot read: %s" % error.strerror)


def numbers(path, line, fields, count, what, optional=0):
    """The first `count` (up to count + optional) fields as floats."""
    if not count <= len(fields) <= count + optional:
        raise ConversionError(path, line, "%s expects %s numbers, got %d" % (
            what, count if not optional else "%d to %d" % (count, count + optional), len(fields)))
    values = []
    for field in fields:
        try:
            value = float(field)
        except ValueError:
            raise ConversionError(path, line, "%s: '%s' is not a number" % (what, field))
        if not math.isfinite(value):
            raise ConversionError(path, line, "%s: '%s' is not a finite number" % (what, field))
        values.append(value)
    return values


def read_mtl(path, warn):
    """{name: material} from an MTL file."""
    materials, current = {}, None
    for line, text in logical_lines(path):
        fields = text.split("#", 1)[0].split()
        if not fields:
            continue
        keyword, args = fields[0], fields[1:]
        if keyword == "newmtl":
            if len(args) < 1:
                raise ConversionError(path, line, "newmtl needs a name")
            current = dict(DEFAULT_MATERIAL)
            materials[" ".join(args)] = current
        elif keyword in ("Kd", "Ks"):
            if current is None:
                raise ConversionError(path, line, "%s before any newmtl" % keyword)
            if args and args[0] in ("spectral", "xyz"):
                raise ConversionError(path, line, "%s %s colours are not supported; use r g b" % (keyword, args[0]))
            rgb = numbers(path, line, args, 1, keyword, optional=2)
            if len(rgb) == 2:
                raise ConversionError(path, line, "%s expects 1 or 3 numbers, got 2" % keyword)
            if len(rgb) == 1:
                rgb = rgb * 3
            current["dif" if keyword == "Kd" else "spe"] = tuple(clamp(c, 0.0, 1.0) for c in rgb)
        elif keyword == "Ns":
            if current is None:
                raise ConversionError(path, line, "Ns before any newmtl")
            current["shi"] = clamp(numbers(path, line, args, 1, "Ns")[0], 0.0, MAX_SHININESS)
        # Ka, Ke, d, Tr, illum, Ni, maps: nothing in this renderer's model uses them.
    if not materials:
        warn("%s: no materials (newmtl) found" % path)
    return materials


class Model:
    def __init__(self):
        self.positions = []  # (x, y, z)
        self.colors = []  # (r, g, b) or None, per position
        self.normals = []  # vn, as given
        self.faces = []  # the position indices of each polygon, for smooth normals
        self.triangles = []  # ((position, normal or None) x 3, material, line)
        self.skipped = 0


def resolve(path, line, text, count, what):
    """An OBJ index (1-based, or negative: relative to the end) to a 0-based one."""
    try:
        index = int(text)
    except ValueError:
        raise ConversionError(path, line, "%s index '%s' is not a whole number" % (what, text))
    if index == 0:
        raise ConversionError(path, line, "%s index 0: OBJ indices start at 1 (or -1 for the last)" % what)
    resolved = index - 1 if index > 0 else count + index
    if not 0 <= resolved < count:
        raise ConversionError(path, line, "%s index %d is out of range: %d %s defined so far" % (
            what, index, count, "vertex positions" if what == "vertex" else "normals"))
    return resolved


def parse_corner(path, line, token, model):
    parts = token.split("/")
    if len(parts) > 3 or not parts[0]:
        raise ConversionError(path, line, "face corner '%s' is not v, v/vt, v/vt/vn or v//vn" % token)
    position = resolve(path, line, parts[0], len(model.positions), "vertex")
    normal = None
    if len(parts) == 3 and parts[2]:
        normal = resolve(path, line, parts[2], len(model.normals), "normal")
    return position, normal


def read_obj(path, warn):
    model = Model()
    materials, material = {}, DEFAULT_MATERIAL
    ignored = set()
    for line, text in logical_lines(path):
        fields = text.split("#", 1)[0].split()
        if not fields:
            continue
        keyword, args = fields[0], fields[1:]
        if keyword == "v":
            values = numbers(path, line, args, 3, "v", optional=4)
            model.positions.append(tuple(values[:3]))
            # x y z [w], or x y z r g b (a common extension) with a colour per vertex.
            model.colors.append(tuple(clamp(c, 0.0, 1.0) for c in values[3:6]) if len(values) >= 6 else None)
        elif keyword == "vn":
            model.normals.append(tuple(numbers(path, line, args, 3, "vn")))
        elif keyword == "f":
            if len(args) < 3:
                raise ConversionError(path, line, "a face needs at least 3 corners, got %d" % len(args))
            corners = [parse_corner(path, line, token, model) for token in args]
            model.faces.append([p for p, _n in corners])
            for i in range(1, len(corners) - 1):  # a fan from the first corner
                model.triangles.append(((corners[0], corners[i], corners[i + 1]), material, line))
        elif keyword == "mtllib":
            for name in args:
                mtl = os.path.join(os.path.dirname(path), name)
                if os.path.exists(mtl):
                    materials.update(read_mtl(mtl, warn))
                else:
                    warn("%s:%d: warning: material library %s not found; default material used" % (path, line, mtl))
        elif keyword == "usemtl":
            name = " ".join(args)
            material = materials.get(name)
            if material is None:
                warn("%s:%d: warning: unknown material '%s'; default material used" % (path, line, name))
                material = DEFAULT_MATERIAL
        elif keyword in ("vt", "vp", "o", "g", "s"):
            pass  # texture coordinates, object and group names, smoothing groups
        elif keyword not in ignored:
            ignored.add(keyword)
            warn("%s:%d: warning: '%s' statements are ignored" % (path, line, keyword))
    if not model.triangles:
        raise ConversionError(path, 0, "no faces (f) found")
    return model


# ------------------------------------------------------------ normals, fit ---


def smooth_normals(model):
    """Per position, the average of the normals of the faces around it, weighted by
    their area.

    Newell's sum of cross products over a polygon is its normal scaled by twice its
    area, so adding the unnormalised sums weights by area. It is taken per polygon,
    not per triangle, so how a quad was split does not tilt its corners' normals."""
    sums = [[0.0, 0.0, 0.0] for _ in model.positions]
    for face in model.faces:
        n = [0.0, 0.0, 0.0]
        for i in range(1, len(face) - 1):
            a, b, c = model.positions[face[0]], model.positions[face[i]], model.positions[face[i + 1]]
            e = cross(sub(b, a), sub(c, a))
            n = [n[0] + e[0], n[1] + e[1], n[2] + e[2]]
        for p in set(face):
            s = sums[p]
            s[0] += n[0]
            s[1] += n[1]
            s[2] += n[2]
    return [normalize(s) for s in sums]


def fit_transform(positions):
    """(centre, scale) that moves the bounding box's centre to FIT_CENTRE and its
    largest side to FIT_SIZE."""
    low = [min(p[i] for p in positions) for i in range(3)]
    high = [max(p[i] for p in positions) for i in range(3)]
    centre = [(low[i] + high[i]) / 2.0 for i in range(3)]
    size = max(high[i] - low[i] for i in range(3))
    return centre, (FIT_SIZE / size if size > 0.0 else 1.0)


# ------------------------------------------------------------------ writing ---


def fmt(x):
    s = FMT % x
    return "0" if s == "-0" else s


def vec(v):
    return "%s %s %s" % (fmt(v[0]), fmt(v[1]), fmt(v[2]))


def write_scene(out, model, lights, ambient, fit):
    smooth = None
    if any(n is None for corners, _m, _l in model.triangles for _p, n in corners):
        smooth = smooth_normals(model)
    place = lambda p: p
    if fit:
        centre, scale = fit_transform(model.positions)
        place = lambda p: tuple((p[i] - centre[i]) * scale + FIT_CENTRE[i] for i in range(3))

    triangles = []
    for corners, material, _line in model.triangles:
        positions = [model.positions[p] for p, _n in corners]
        if len({p for p, _n in corners}) < 3 or length(cross(sub(positions[1], positions[0]),
                                                             sub(positions[2], positions[0]))) == 0.0:
            model.skipped += 1
            continue
        triangles.append((corners, material))

    out.write("%d\n" % (len(lights) + len(triangles)))
    out.write("amb: %s\n" % vec(ambient))
    for position, color in lights:
        out.write("light\npos: %s\ncol: %s\n" % (vec(position), vec(color)))
    for corners, material in triangles:
        out.write("triangle\n")
        for p, n in corners:
            normal = model.normals[n] if n is not None else smooth[p]
            dif = model.colors[p] if model.colors[p] is not None else material["dif"]
            out.write("pos: %s\nnor: %s\ndif: %s\nspe: %s\nshi: %s\n" % (
                vec(place(model.positions[p])), vec(normal), vec(dif), vec(material["spe"]),
                fmt(material["shi"])))
    return len(triangles)


# --------------------------------------------------------------------- main ---


def triple(text):
    parts = text.split(",")
    if len(parts) != 3:
        raise argparse.ArgumentTypeError("expected three numbers X,Y,Z, got '%s'" % text)
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError("expected three numbers X,Y,Z, got '%s'" % text)
    if not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError("expected finite numbers, got '%s'" % text)
    return values


def parse_color(text):
    values = triple(text)
    if min(values) < 0.0:
        raise argparse.ArgumentTypeError("a colour cannot be negative, got '%s'" % text)
    return values


def main(argv=None):
    parser = argparse.ArgumentParser(description="Convert a Wavefront OBJ model to a Raytracer scene.")
    parser.add_argument("obj", help="the .obj file")
    parser.add_argument("-o", "--out", help="the scene file to write (default: standard output)")
    parser.add_argument("--light", type=triple, action="append", metavar="X,Y,Z",
                        help="a point light here (repeatable; default: one at 0,4,0, above the camera)")
    parser.add_argument("--light-color", "--light-colour", type=parse_color, default=(1.0, 1.0, 1.0), metavar="R,G,B",
                        help="the colour of every light (default 1,1,1)")
    parser.add_argument("--ambient", type=parse_color, default=(0.1, 0.1, 0.1), metavar="R,G,B",
                        help="the ambient colour (default 0.1,0.1,0.1)")
    parser.add_argument("--fit", action="store_true",
                        help="move and scale the model to sit centred at z = -3, %g units across" % FIT_SIZE)
    # "--light -1,5,0" would read as an unknown option "-1,5,0" to argparse: glue
    # each triple to its option ("--light=-1,5,0") first.
    argv = list(sys.argv[1:] if argv is None else argv)
    glued = []
    while argv:
        arg = argv.pop(0)
        glued.append(arg + "=" + argv.pop(0) if arg in ("--light", "--light-color", "--light-colour", "--ambient") and argv else arg)
    args = parser.parse_args(glued)

    warn = lambda message: print(message, file=sys.stderr)
    try:
        model = read_obj(args.obj, warn)
        lights = [(p, args.light_color) for p in (args.light or [(0.0, 4.0, 0.0)])]
        if args.out:
            temporary = args.out + ".tmp"
            with open(temporary, "w", encoding="ascii", newline="\n") as out:
                count = write_scene(out, model, lights, args.ambient, args.fit)
            os.replace(temporary, args.out)  # never a half-written scene
        else:
            count = write_scene(sys.stdout, model, lights, args.ambient, args.fit)
    except ConversionError as error:
        print(error, file=sys.stderr)
        return 1
    except OSError as error:
        print("%s: error: %s" % (error.filename or args.out, error.strerror), file=sys.stderr)
        return 1
    note = ", %d degenerate left out" % model.skipped if model.skipped else ""
    print("%s: %d triangles%s" % (args.obj, count, note), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
