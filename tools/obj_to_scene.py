#!/usr/bin/env python3
"""Convert a Wavefront OBJ model to a Raytracer scene.

    python3 tools/obj_to_scene.py model.obj -o model.scene --fit

Reads v, vn, f and usemtl/mtllib statements. Faces may be triangles or convex
polygons (fan-triangulated from their first corner), with corners written as
v, v/vt, v/vt/vn or v//vn, and with positive or negative (relative) indices.
A corner without a normal gets a smooth one: the area-weighted average of the
normals of the faces around its position that meet its own face within
--crease degrees (default 60; 0 gives flat faces). Texture coordinates are read
and ignored. `v x y z r g b` vertex colours become the corner's diffuse colour.
--up turns the model's up axis onto +y.

Materials (from the MTL files that mtllib names, looked up beside the OBJ):
Kd becomes dif, Ks spe and Ns shi; colours are clamped to [0, 1] and Ns to
[1, 1000]. illum 0 and 1 have no highlight (spe 0), 2 a highlight and no mirror
(mir: 0), 3 and above Ks as the mirror weight too (no mir: line); a material
without illum is taken as illum 2. Faces without a known material get a light
grey default with a faint highlight and no mirror.

The scene's camera sits at the origin looking down -z. --fit turns the model to
show that camera the side --view names (default three-quarter: from the front
right, above the horizon), scales it (uniformly) to 1.5 units across and puts it
straight ahead, as far away as makes it fill 80% of the view. --ground adds a matte floor under it; --rig
places key, fill and rim lights around it for the camera of --camera-pos,
--camera-target and --camera-up (Raytracer's options, default the origin
looking down -z); otherwise one white light sits above the camera unless
--light is given (it may be repeated).

Raytracer reads OBJ files itself by the same rules (`Raytracer model.obj`, and
`--save-scene` writes the scene it built: by default the same text as this
tool's with --fit --ground --rig; docs/models.md).

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

MAX_MTL_BYTES = 64 << 20  # the largest material library read (Raytracer's kMaxMtlBytes)
DEFAULT_MATERIAL = {"dif": (0.75, 0.75, 0.75), "spe": (0.1, 0.1, 0.1), "shi": 30.0, "mir": 0.0, "emi": (0.0, 0.0, 0.0)}
MIN_SHININESS, MAX_SHININESS = 1.0, 1000.0


class ConversionError(Exception):
    """A problem with the input, with the place it was found."""

    def __init__(self, path, line, message):
        super().__init__("%s:%d: error: %s" % (path, line, message) if line else "%s: error: %s" % (path, message))
        self.path, self.line, self.message = path, line, message


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
        # Bytes that are not UTF-8 are kept as they are (surrogate escapes), and written so.
        with open(path, "r", encoding="utf-8-sig", errors="surrogateescape") as handle:
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


WHITESPACE_BYTES = b" \t\n\v\f\r"


def binary_reason(path):
    """Why the file is not text at all (as Raytracer says it), or None: the first NUL or
    control byte other than whitespace. Any other byte is text: names and comments come in
    whatever encoding the exporter used (a Latin-1 material name), compared as bytes."""
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError:
        return None  # logical_lines reports it
    for offset, byte in enumerate(data):
        if byte == 0:
            return "NUL byte at offset %d" % offset
        if (byte < 0x20 and byte not in WHITESPACE_BYTES) or byte == 0x7F:
            return "control byte 0x%02x at offset %d" % (byte, offset)
    return None


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


def apply_illum(material, illum):
    """MTL's illumination model: 0 and 1 have no highlight, 2 a highlight and no mirror, 3
    and above (reflection, glass, Fresnel: all a mirror here) Ks as the mirror weight too."""
    if illum <= 1:
        material["spe"] = (0.0, 0.0, 0.0)
    material["mir"] = 1.0 if illum >= 3 else 0.0


def read_mtl(path, warn, textured=None):
    """{name: material} from an MTL file. A line that is wrong is a warning, not an error:
    the material it belongs to falls back to the default one (its other lines are not read),
    a line before any material is left out, and the model renders on. The names of the
    materials with a texture map (map_Kd), which a scene cannot hold, are added to textured."""
    materials, current, current_name, skipping = {}, None, None, False
    illum_of = {}  # applied at the end: a Ks may follow its illum
    for line, text in logical_lines(path):
        fields = text.split("#", 1)[0].split()
        if not fields:
            continue
        keyword, args = fields[0], fields[1:]
        if keyword != "newmtl" and skipping:
            continue
        try:
            if keyword == "newmtl":
                current, skipping = None, False
                if len(args) < 1:
                    skipping = True  # its lines belong to no material
                    raise ConversionError(path, line, "newmtl needs a name")
                current, current_name = dict(DEFAULT_MATERIAL), " ".join(args)
                materials[current_name] = current
                illum_of.pop(current_name, None)  # a material of that name read before
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
            elif keyword == "Ke":
                if current is None:
                    raise ConversionError(path, line, "Ke before any newmtl")
                rgb = numbers(path, line, args, 1, "Ke", optional=2)
                if len(rgb) == 2:
                    raise ConversionError(path, line, "Ke expects 1 or 3 numbers, got 2")
                if len(rgb) == 1:
                    rgb = rgb * 3
                current["emi"] = tuple(max(c, 0.0) for c in rgb)
            elif keyword == "Ns":
                if current is None:
                    raise ConversionError(path, line, "Ns before any newmtl")
                current["shi"] = clamp(numbers(path, line, args, 1, "Ns")[0], MIN_SHININESS, MAX_SHININESS)
            elif keyword == "illum":
                if current is None:
                    raise ConversionError(path, line, "illum before any newmtl")
                illum = numbers(path, line, args, 1, "illum")[0]
                if illum != math.floor(illum) or not 0 <= illum <= 10:
                    raise ConversionError(path, line, "illum expects an illumination model, a whole number "
                                          "0 to 10, got %s" % args[0])
                illum_of[current_name] = int(illum)
            elif keyword == "map_Kd" and current is not None and textured is not None:
                textured.add(current_name)
            # Ka, d, Tr, Ni, other maps: nothing in the scene format holds them.
        except ConversionError as error:
            consequence = "; the line is left out"
            if current is not None:
                illum_of.pop(current_name, None)
                current.clear()
                current.update(DEFAULT_MATERIAL)
                if textured is not None:
                    textured.discard(current_name)
                skipping = True
                consequence = "; material '%s' is the default one" % current_name
            elif skipping:
                consequence = "; the lines up to the next newmtl are left out"
            place = "%s:%d: " % (error.path, error.line) if error.line else "%s: " % error.path
            warn(place + "warning: " + error.message + consequence)
    for name, illum in illum_of.items():
        apply_illum(materials[name], illum)
    if not materials:
        warn("%s: warning: no materials (newmtl) found" % path)
    return materials


class Model:
    def __init__(self):
        self.textured = set()  # the names of materials with a texture map (map_Kd)
        self.positions = []  # (x, y, z)
        self.position_lines = []  # each position's v line, for messages
        self.colors = []  # (r, g, b) or None, per position
        self.normals = []  # vn, as given
        self.texcoords = 0  # how many vt lines
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
            what, index, count,
            {"vertex": "vertex positions", "normal": "normals"}.get(what, "texture coordinates")))
    return resolved


PLANAR_TOLERANCE = 1e-4  # Raytracer's kPlanarTolerance


def triangulate(corners):
    """A polygon's triangles (corner indices) and whether it was concave but fanned, as
    Raytracer's triangulatePolygon (host/model/polygon_triangulation.cpp), operation for
    operation: a fan when convex, ear clipping when concave and planar, a fan (counted)
    when concave and bent out of its plane or crossing itself."""
    n = len(corners)
    fan = lambda: [(0, i, i + 1) for i in range(1, n - 1)]
    if n <= 3:
        return fan(), False
    normal = (0.0, 0.0, 0.0)
    for i in range(1, n - 1):
        normal = add(normal, cross(sub(corners[i], corners[0]), sub(corners[i + 1], corners[0])))
    axis = 0
    for k in (1, 2):
        if abs(normal[k]) > abs(normal[axis]):
            axis = k
    if normal[axis] == 0.0:
        return fan(), False
    sign = 1.0 if normal[axis] > 0.0 else -1.0
    u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
    points = [(c[u_axis], c[v_axis]) for c in corners]

    def turn(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    if all(turn(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) * sign >= 0.0 for i in range(n)):
        return fan(), False
    length = math.sqrt(dot(normal, normal))
    reach, off_plane = 0.0, 0.0
    for corner in corners:
        d = sub(corner, corners[0])
        reach = max(reach, math.sqrt(dot(d, d)))
        off_plane = max(off_plane, abs(dot(d, normal)) / length)
    if off_plane > PLANAR_TOLERANCE * reach:
        return fan(), True
    left, triangles = list(range(n)), []
    while len(left) > 3:
        m, clipped = len(left), False
        for j in range(m):
            a, b, c = left[(j + m - 1) % m], left[j], left[(j + 1) % m]
            if turn(points[a], points[b], points[c]) * sign <= 0.0:
                continue
            empty = True
            for p in left:
                q = points[p]
                if q == points[a] or q == points[b] or q == points[c]:
                    continue
                if (turn(points[a], points[b], q) * sign >= 0.0 and turn(points[b], points[c], q) * sign >= 0.0
                        and turn(points[c], points[a], q) * sign >= 0.0):
                    empty = False
                    break
            if not empty:
                continue
            triangles.append((a, b, c))
            del left[j]
            clipped = True
            break
        if not clipped:
            triangles += [(left[0], left[i], left[i + 1]) for i in range(1, len(left) - 1)]
            return triangles, True
    triangles.append((left[0], left[1], left[2]))
    return triangles, False


def parse_corner(path, line, token, model):
    parts = token.split("/")
    if len(parts) > 3 or not parts[0]:
        raise ConversionError(path, line, "face corner '%s' is not v, v/vt, v/vt/vn or v//vn" % token)
    position = resolve(path, line, parts[0], len(model.positions), "vertex")
    if len(parts) >= 2 and parts[1]:
        resolve(path, line, parts[1], model.texcoords, "texture coordinate")
    normal = None
    if len(parts) == 3 and parts[2]:
        normal = resolve(path, line, parts[2], len(model.normals), "normal")
    return position, normal


def other_file_format(path):
    """What the file is when it is not OBJ text, told from its first bytes as Raytracer
    tells it (host/scene/file_format.cpp): another model format, or UTF-16 text; or None."""
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError:
        return None  # logical_lines reports it
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        return "UTF-16 text"
    if len(data) >= 4:
        pairs = [(data[2 * i], data[2 * i + 1]) for i in range(min(len(data) // 2, 32))]
        if all(a != 0 and a < 0x80 and b == 0 for a, b in pairs) or \
                all(a == 0 and b != 0 and b < 0x80 for a, b in pairs):
            return "UTF-16 text"
    if data.startswith(b"ply\n") or data.startswith(b"ply\r\n"):
        return "a PLY model"
    if data.startswith(b"glTF"):
        return "a binary glTF model (.glb)"
    if len(data) >= 84 and 84 + 50 * int.from_bytes(data[80:84], "little") == len(data):
        return "an STL model"
    head = data[:1024]
    if data.startswith(b"solid") and b"facet" in head:
        return "an STL model"
    if head.lstrip(b" \t\r\n").startswith(b"{") and b'"asset"' in head:
        return "a glTF model"
    return None


def read_obj(path, warn):
    other = other_file_format(path)
    if other == "UTF-16 text":
        raise ConversionError(path, 0, "the file is UTF-16 text, and an OBJ model is read as UTF-8; "
                              "convert it first: iconv -f UTF-16 -t UTF-8 '%s' > converted.obj" % path)
    if other:
        raise ConversionError(path, 0, "not an OBJ model: this is %s, which is not read; convert it "
                              "to OBJ first (for example with assimp export, Debian's assimp-utils)" % other)
    reason = binary_reason(path)
    if reason:
        raise ConversionError(path, 0, "not an OBJ file: it is binary (%s)" % reason)
    model = Model()
    materials, material = {}, DEFAULT_MATERIAL
    ignored = set()
    # Libraries not found, and the faces whose material was to come from one: one warning at
    # the end says both, in place of one for each usemtl.
    missing, missing_line, fell_back, faces_fell_back = [], 0, False, 0
    fanned_concave, first_fanned_line = 0, 0  # concave faces that could not be clipped
    for line, text in logical_lines(path):
        fields = text.split("#", 1)[0].split()
        if not fields:
            continue
        keyword, args = fields[0], fields[1:]
        if keyword == "v":
            values = numbers(path, line, args, 3, "v", optional=4)
            if len(values) == 5:
                raise ConversionError(path, line, "v expects 3, 4, 6 or 7 numbers (x y z [w], or x y z r g b), got 5")
            model.positions.append(tuple(values[:3]))
            model.position_lines.append(line)
            # x y z [w], or x y z r g b (a common extension) with a colour per vertex.
            model.colors.append(tuple(clamp(c, 0.0, 1.0) for c in values[3:6]) if len(values) >= 6 else None)
        elif keyword == "vn":
            model.normals.append(tuple(numbers(path, line, args, 3, "vn")))
        elif keyword == "vt":
            numbers(path, line, args, 1, "vt", 2)
            model.texcoords += 1  # a scene holds no textures: only their count, for the checks
        elif keyword == "f":
            if len(args) < 3:
                raise ConversionError(path, line, "a face needs at least 3 corners, got %d" % len(args))
            corners = [parse_corner(path, line, token, model) for token in args]
            model.faces.append([p for p, _n in corners])
            faces_fell_back += 1 if fell_back else 0
            split, fanned = triangulate([model.positions[p] for p, _n in corners])
            if fanned:
                if not fanned_concave:
                    first_fanned_line = line
                fanned_concave += 1
            for a, b, c in split:
                model.triangles.append(((corners[a], corners[b], corners[c]), material, line,
                                        len(model.faces) - 1))
        elif keyword == "mtllib":
            for name in args:
                mtl = os.path.join(os.path.dirname(path), name)
                if os.path.exists(mtl) and not os.path.isfile(mtl):
                    raise ConversionError(mtl, 0, "not a regular file (a device, a pipe or a folder): "
                                          "a material library must be a file")
                if os.path.exists(mtl) and os.path.getsize(mtl) > MAX_MTL_BYTES:
                    raise ConversionError(mtl, 0, "the file holds %d bytes, more than a material library "
                                          "may (%d MiB)" % (os.path.getsize(mtl), MAX_MTL_BYTES >> 20))
                if os.path.exists(mtl):
                    materials.update(read_mtl(mtl, warn, model.textured))
                else:
                    if not missing:
                        missing_line = line
                    missing.append(mtl)
        elif keyword == "usemtl":
            name = " ".join(args)
            material = materials.get(name)
            fell_back = material is None and bool(missing)
            if material is None and not missing:
                warn("%s:%d: warning: unknown material '%s'; default material used" % (path, line, name))
            if material is None:
                material = DEFAULT_MATERIAL
        elif keyword in ("vp", "o", "g", "s"):
            pass  # parameter-space vertices, object and group names, smoothing groups
        elif keyword not in ignored:
            ignored.add(keyword)
            warn("%s:%d: warning: '%s' statements are ignored" % (path, line, keyword))
    if not model.triangles:
        raise ConversionError(path, 0, "no faces (f) found")
    if fanned_concave:
        warn("%s:%d: warning: %d concave face(s) not in one plane, or crossing themselves, split as fans "
             "from their first corner" % (path, first_fanned_line, fanned_concave))
    if missing:
        libraries = missing[0] if len(missing) == 1 else ", ".join(missing[:-1]) + " and " + missing[-1]
        warn("%s:%d: warning: material %s %s not found; %d of %d faces use the default material"
             % (path, missing_line, "library" if len(missing) == 1 else "libraries", libraries,
                faces_fell_back, len(model.faces)))
    return model


# ------------------------------------------- up axis, normals, fit, ground ---
# The same rules as Raytracer's own OBJ reader (docs/models.md), operation for operation
# and in the same order, so that both write the same scene text.

FIT_SIZE = 1.5
FRAME_SHARE = 0.8
GROUND_SPAN = 100.0
GROUND_MATERIAL = {"dif": (0.7, 0.7, 0.7), "spe": (0.0, 0.0, 0.0), "shi": 1.0, "mir": 1.0, "emi": (0.0, 0.0, 0.0)}
EMITTER_LIFT = 0.01  # an emitting material's light sits this share of the model's size off it
def up_axis(text):
    """--up as users write it: an axis letter in either case, with an optional sign."""
    axis = text[1:] if text[:1] in ("+", "-") else text
    if axis.lower() not in ("x", "y", "z"):
        raise argparse.ArgumentTypeError("expects an axis, x, y or z in either case with an optional sign "
                                         "(z, Z, +z, -y), got '%s'" % text)
    return ("-" if text[:1] == "-" else "") + axis.lower()


def turn_up(v, up):
    """The up axis turned onto +y: swaps and negations only, so nothing is rounded."""
    x, y, z = v
    return {"x": (-y, x, z), "-x": (y, -x, z), "y": (x, y, z), "-y": (x, -y, -z),
            "z": (x, z, -y), "-z": (x, -z, y)}[up]


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def times(v, s):
    return (v[0] * s, v[1] * s, v[2] * s)


def newell_normal(positions, face, scale):
    """Newell's sum of cross products over a polygon: its normal scaled by twice its area,
    so adding such sums weights faces by area; per polygon, so how a quad was split does
    not tilt its corners' normals. The positions are multiplied by scale, a power of two,
    which changes no rounding."""
    n = (0.0, 0.0, 0.0)
    s = lambda p: (p[0] * scale, p[1] * scale, p[2] * scale)
    for i in range(1, len(face) - 1):
        a = s(positions[face[0]])
        n = add(n, cross(sub(s(positions[face[i]]), a), sub(s(positions[face[i + 1]]), a)))
    return n


def newell_scale(positions):
    """The power of two that brings the largest coordinate into [0.5, 1): a model at 1e300
    would overflow to infinity, while every other model rounds exactly as unscaled."""
    largest = max((abs(c) for p in positions for c in p), default=0.0)
    return math.ldexp(1.0, -math.frexp(largest)[1])


class SmoothNormals:
    """For face f and its position p: the normalised sum of the Newell normals of the
    faces around p (each face once, in file order) whose unit normal is within the crease
    angle of f's, f itself always included. Faces left out (left_out[f]) count for no corner."""

    def __init__(self, model, positions, crease, left_out):
        self.cosine = math.cos(crease * (math.pi / 180.0))
        self.everywhere = crease >= 180.0
        scale = newell_scale(positions)
        self.newell = [newell_normal(positions, face, scale) for face in model.faces]
        self.unit = [normalize(n) for n in self.newell]
        self.around = [[] for _ in positions]
        for f, face in enumerate(model.faces):
            for p in face:
                if not left_out[f] and f not in self.around[p]:
                    self.around[p].append(f)

    def at(self, face, position):
        total = (0.0, 0.0, 0.0)
        for other in self.around[position]:
            if self.everywhere or other == face or dot(self.unit[face], self.unit[other]) >= self.cosine:
                total = add(total, self.newell[other])
        return normalize(total)


FAR_BEYOND = 1000.0


def far_positions(positions):
    """[bool] per position: further than FAR_BEYOND times the model's spread from its median
    point along some axis (the median and spread of the file's positions; a median of an
    even count is the upper of the middle two; none when the spread is 0). Raytracer's
    farPositions, operation for operation."""
    count, middle = len(positions), len(positions) // 2
    if count == 0:
        return []
    median, spread = [0.0, 0.0, 0.0], 0.0
    for axis in range(3):
        median[axis] = sorted(p[axis] for p in positions)[middle]
        spread = max(spread, sorted(abs(p[axis] - median[axis]) for p in positions)[middle])
    if not spread > 0.0:
        return [False] * count
    return [max(abs(p[axis] - median[axis]) for axis in range(3)) > FAR_BEYOND * spread for p in positions]


def describe_far(model, far, left_out):
    """(line, message) of the warning for far positions, as Raytracer words it."""
    near = [p for p, f in zip(model.positions, far) if not f]
    first = far.index(True)
    short = lambda value: "%.6g" % value
    extent = ", ".join("%s %s..%s" % ("xyz"[axis], short(min(p[axis] for p in near)), short(max(p[axis] for p in near)))
                       for axis in range(3))
    p = model.positions[first]
    return model.position_lines[first], (
        "%d vertex(es) far beyond the rest of the model (the first here, at %s %s %s: more than %s times the "
        "model's spread from its median) are left out, with the faces that use them (%d "
        "triangle(s)); without them the model spans %s" % (far.count(True), short(p[0]), short(p[1]), short(p[2]), short(FAR_BEYOND), left_out,
                            extent))


VIEWS = ("three-quarter", "front", "back", "left", "right", "top", "bottom")
THREE_QUARTER_AZIMUTH = 45.0  # degrees round from the front towards the model's right (+x)
THREE_QUARTER_ELEVATION = (30.0, 60.0)  # degrees above the horizon, at least and at most
HORIZON_MARGIN = 5.0  # degrees the horizon stays above the frame's top edge
FLOOR_GAP = 0.002  # the floor's distance below the model, in model sizes


def view_turn(view, fov):
    """The turn that shows the camera a side of the model: its rows (the camera's right, up
    and backward axes in the model's coordinates), or None for the front view (no turn).
    Raytracer's viewTurn, operation for operation."""
    exact = {"back": ((-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, -1.0)),
             "right": ((0.0, 0.0, -1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)),
             "left": ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0)),
             "top": ((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0)),
             "bottom": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0))}
    if view == "front":
        return None
    if view in exact:
        return exact[view]
    elevation = min(max(fov / 2.0 + HORIZON_MARGIN, THREE_QUARTER_ELEVATION[0]), THREE_QUARTER_ELEVATION[1])
    a, e = THREE_QUARTER_AZIMUTH * (math.pi / 180.0), elevation * (math.pi / 180.0)
    ca, sa, ce, se = math.cos(a), math.sin(a), math.cos(e), math.sin(e)
    return ((ca, 0.0, -sa), (-sa * se, ce, -ca * se), (sa * ce, se, ca * ce))


def apply_turn(turn, v):
    if turn is None:
        return v
    return tuple(r[0] * v[0] + r[1] * v[1] + r[2] * v[2] for r in turn)


FRAME_LIMIT = 0.95  # no position nearer the frame's edge than this share of the way to it
FIT_STEPS = 40


def distance_for_share(turned, tan_y, tan_x, share):
    """The distance at which the outermost turned position lies share of the way from the
    centre of the view to its edge."""
    vertical, horizontal = share * tan_y, share * tan_x
    distance = 0.0
    for v in turned:
        distance = max(distance, v[2] + max(abs(v[1]) / vertical, abs(v[0]) / horizontal))
    return distance


def half_span(turned, tan_y, tan_x, distance):
    """Half the larger of the silhouette's width and height as shares of the frame's."""
    left = right = bottom = top = 0.0
    for v in turned:
        depth = distance - v[2]
        if not depth > 0.0:
            return math.inf
        x, y = v[0] / (depth * tan_x), v[1] / (depth * tan_y)
        left, right, bottom, top = min(left, x), max(right, x), min(bottom, y), max(top, y)
    return max(right - left, top - bottom) / 2.0


def fit_distance(turned, tan_y, tan_x):
    """Where the silhouette spans FRAME_SHARE of the frame, by bisection, no nearer than where
    the outermost position lies FRAME_LIMIT of the way to the edge (Raytracer's fitDistance)."""
    nearest = distance_for_share(turned, tan_y, tan_x, FRAME_LIMIT)
    farthest = distance_for_share(turned, tan_y, tan_x, FRAME_SHARE)
    if half_span(turned, tan_y, tan_x, nearest) <= FRAME_SHARE:
        return nearest
    for _ in range(FIT_STEPS):
        middle = (nearest + farthest) / 2.0
        if half_span(turned, tan_y, tan_x, middle) > FRAME_SHARE:
            nearest = middle
        else:
            farthest = middle
    return farthest


def lying_down(positions):
    """The note for a model read as y-up that looks like a z-up one on its back (longest along
    z, shallowest along y, at most 0.6 of its length; a flat model is left alone), or None."""
    extent = [max(p[a] for p in positions) - min(p[a] for p in positions) for a in range(3)]
    if not (extent[1] > 0.0 and extent[2] >= extent[0] and extent[1] <= extent[0] and extent[1] <= 0.6 * extent[2]):
        return None
    return ("the model is longest along z and shallowest along y, as a z-up model (Blender, most "
            "CAD and scanning tools) lies on its back when read as y-up; if it is one, give --up z")


INTERIOR_EYE_DEPTH = 0.4  # inside a room, the eye stands this share of its depth before its centre
INTERIOR_RIG_SHARE = 0.15  # and the rig's lights hang at this share of their distances


def encloses_its_centre(positions, corners, centre):
    """Whether the model encloses centre as a room does: rays towards the 26 faces, edges and
    corners of a box all meet a triangle, and at least 20 of the nearest turn their front to
    the centre (Raytracer's enclosesItsCentre, operation for operation)."""
    facing = away = 0
    for i in (-1, 0, 1):
        for j in (-1, 0, 1):
            for k in (-1, 0, 1):
                if i == 0 and j == 0 and k == 0:
                    continue
                d = normalize((float(i), float(j), float(k)))
                nearest, front = math.inf, False
                for ia, ib, ic in corners:
                    a = positions[ia]
                    e1, e2 = sub(positions[ib], a), sub(positions[ic], a)
                    p = cross(d, e2)
                    det = dot(e1, p)
                    if det == 0.0:
                        continue
                    s = sub(centre, a)
                    u = dot(s, p) / det
                    if u < 0.0 or u > 1.0:
                        continue
                    q = cross(s, e1)
                    v = dot(d, q) / det
                    if v < 0.0 or u + v > 1.0:
                        continue
                    distance = dot(e2, q) / det
                    if 0.0 < distance < nearest:
                        nearest, front = distance, dot(cross(e1, e2), d) < 0.0
                if nearest == math.inf:
                    return False
                if front:
                    facing += 1
                else:
                    away += 1
                    if away > 6:
                        return False
    return facing >= 20


class Placement:
    """p -> turn(p - centre) * scale + offset: the model turned to show the camera the side
    its view names, scaled to FIT_SIZE across and put straight ahead of the default camera,
    as far away as makes its outermost position lie FRAME_SHARE of the way from the centre of
    the view to its edge (without fit, p); inside, a room unturned with the eye
    INTERIOR_EYE_DEPTH of its depth before its centre. low and high: the box around the
    positions, unplaced."""

    def __init__(self, positions, fit, fov, aspect, view, inside=False):
        self.low = tuple(min(p[i] for p in positions) for i in range(3))
        self.high = tuple(max(p[i] for p in positions) for i in range(3))
        low, high = self.low, self.high
        self.centre, self.scale, self.offset, self.turn = (0.0, 0.0, 0.0), 1.0, (0.0, 0.0, 0.0), None
        self.inside = inside
        if inside:
            self.centre = tuple((low[i] + high[i]) / 2.0 for i in range(3))
            size = max(high[i] - low[i] for i in range(3))
            self.scale = FIT_SIZE / size if size > 0.0 else 1.0
            self.offset = (0.0, 0.0, -(INTERIOR_EYE_DEPTH * (high[2] - low[2])) * self.scale)
        elif fit:
            self.centre = tuple((low[i] + high[i]) / 2.0 for i in range(3))
            self.turn = view_turn(view, fov)
            size = max(high[i] - low[i] for i in range(3))
            self.scale = FIT_SIZE / size if size > 0.0 else 1.0
            turned = [times(apply_turn(self.turn, sub(p, self.centre)), self.scale) for p in positions]
            tan_y = math.tan(fov * (math.pi / 180.0) / 2.0)
            self.offset = (0.0, 0.0, -fit_distance(turned, tan_y, tan_y * aspect))

    def place(self, p):
        return tuple(c * self.scale + self.offset[i] for i, c in enumerate(apply_turn(self.turn, sub(p, self.centre))))

    def anchor(self):
        """(centre, radius) of the light rig: the box's centre placed, half its diagonal scaled."""
        centre = tuple((self.low[i] + self.high[i]) / 2.0 for i in range(3))
        radius = length(times(sub(self.high, self.low), self.scale)) / 2.0
        return self.place(centre), radius * INTERIOR_RIG_SHARE if self.inside else radius

    def camera(self):
        """(eye, target, up) of the camera a fitted model is seen from when none is given."""
        up = apply_turn(self.turn, (0.0, 1.0, 0.0))
        return (0.0, 0.0, 0.0), self.anchor()[0], up if (up[0] != 0.0 or up[1] != 0.0) else (0.0, 1.0, 0.0)


def light_rig(placement, eye, target, up_hint):
    """Key (front left, high), fill (front right, low, dim) and rim (behind, high) lights,
    at distances in units of the model's radius from its centre along the camera's right,
    up and backward axes as seen from the camera (eye, target, up_hint) looking at the
    centre: back from the centre to the eye, right perpendicular to back and up_hint."""
    centre, radius = placement.anchor()
    back = normalize(sub(eye, centre))
    if back == (0.0, 0.0, 0.0):  # the eye at the centre: the camera's own backward axis
        back = normalize(sub(eye, target))
    # level with the camera's up: the rig keeps its height above the model
    up_axis = normalize(up_hint)
    level = normalize(sub(back, times(up_axis, dot(back, up_axis))))
    if level != (0.0, 0.0, 0.0):
        back = level
    right = normalize(cross(up_hint, back))
    if right == (0.0, 0.0, 0.0):  # seen along up: the camera's own right
        right = normalize(cross(sub(target, eye), up_hint))
    up = cross(back, right)
    lights = []
    for r, u, b, brightness in ((-2.0, 2.5, 2.5, 0.8), (2.5, 0.5, 2.0, 0.3), (0.5, 3.0, -3.0, 0.5)):
        offset = tuple(right[i] * (radius * r) + up[i] * (radius * u) + back[i] * (radius * b) for i in range(3))
        lights.append((add(centre, offset), (brightness, brightness, brightness)))
    return lights


def ground(placement):
    """A floor under the model: a square GROUND_SPAN model sizes across, centred below it,
    FLOOR_GAP model sizes below its lowest position, matte grey, facing the model's up;
    placed with the model. Its two triangles, and its normal."""
    low, high = placement.low, placement.high
    centre = tuple((low[i] + high[i]) / 2.0 for i in range(3))
    size = max(high[i] - low[i] for i in range(3))
    half = GROUND_SPAN * size / 2.0
    y = low[1] - FLOOR_GAP * size
    corners = [placement.place(c) for c in ((centre[0] - half, y, centre[2] - half), (centre[0] + half, y, centre[2] - half),
                                            (centre[0] + half, y, centre[2] + half), (centre[0] - half, y, centre[2] + half))]
    return [[corners[k] for k in triangle] for triangle in ((0, 3, 2), (0, 2, 1))], apply_turn(placement.turn, (0.0, 1.0, 0.0))


# ------------------------------------------------------------------ writing ---


def fmt(x):
    s = FMT % x
    return "0" if s == "-0" else s


def vec(v):
    return "%s %s %s" % (fmt(v[0]), fmt(v[1]), fmt(v[2]))


def emitter_lights(triangles, lift):
    """A point light for each emitting material (Ke), in the order the triangles first use
    them: at the area-weighted centroid of its triangles, lifted by lift along the sum of
    their winding normals, its colour Ke clamped to [0, 1] (Raytracer's emitterLights)."""
    order, sums = [], {}
    for triangle in triangles:
        material = triangle[0][3]
        if material["emi"] == (0.0, 0.0, 0.0):
            continue
        a, b, c = (corner[0] for corner in triangle)
        normal = cross(sub(b, a), sub(c, a))
        area = length(normal)
        if id(material) not in sums:
            order.append(material)
            sums[id(material)] = [0.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)]
        entry = sums[id(material)]
        entry[0] += area
        entry[1] = add(entry[1], times(add(add(a, b), c), area / 3.0))
        entry[2] = add(entry[2], normal)
    lights = []
    for material in order:
        area, weighted, normal = sums[id(material)]
        if not area > 0.0:
            continue
        position = add((weighted[0] / area, weighted[1] / area, weighted[2] / area), times(normalize(normal), lift))
        lights.append((position, tuple(clamp(c, 0.0, 1.0) for c in material["emi"])))
    return lights


def degenerate(positions, corners):
    """Two corners at one position, or no area."""
    corner_positions = [positions[p] for p, _n in corners]
    return len({p for p, _n in corners}) < 3 or length(cross(sub(corner_positions[1], corner_positions[0]),
                                                             sub(corner_positions[2], corner_positions[0]))) == 0.0


def write_scene(out, model, settings, warn):
    """settings: up, crease, fit, fov, aspect, ground, rig, camera_pos, camera_target,
    camera_up, lights, ambient."""
    positions = [turn_up(p, settings.up) for p in model.positions]
    normals = [turn_up(n, settings.up) for n in model.normals]
    # The fit, the floor and the rig are for the model without positions far beyond it.
    far = far_positions(model.positions)
    far_faces = [any(far[p] for p in face) for face in model.faces]  # the faces that use one, left out
    kept = [p for p, f in zip(positions, far) if not f]
    # A room (it encloses its centre) is seen from inside unless a view was asked for.
    inside = False
    if settings.fit and not settings.view_given:
        corners = [tuple(p for p, _n in t[0]) for t in model.triangles if not far_faces[t[3]] and not degenerate(
            positions, t[0])]
        low = tuple(min(p[i] for p in kept) for i in range(3))
        high = tuple(max(p[i] for p in kept) for i in range(3))
        inside = encloses_its_centre(positions, corners, tuple((low[i] + high[i]) / 2.0 for i in range(3)))
    placement = Placement(kept, settings.fit, settings.fov, settings.aspect, settings.view, inside)
    smooth = SmoothNormals(model, positions, settings.crease, far_faces)
    # The rig's camera: the one given, else a fitted model's own (Raytracer's modelCamera).
    camera = ((settings.camera_pos, settings.camera_target, settings.camera_up)
              if settings.camera_given or not settings.fit else placement.camera())
    lights = light_rig(placement, *camera) if settings.rig else settings.lights

    triangles, far_triangles = [], 0
    for corners, material, _line, face in model.triangles:
        if far_faces[face]:
            far_triangles += 1
            continue
        if degenerate(positions, corners):
            model.skipped += 1
            continue
        triangles.append([(placement.place(positions[p]),
                           apply_turn(placement.turn, normals[n] if n is not None else smooth.at(face, p)),
                           model.colors[p] if model.colors[p] is not None else material["dif"], material)
                          for p, n in corners])
    if not settings.up_given and not placement.inside:  # a room is often longer than it is tall
        lying = lying_down([p for p, f in zip(model.positions, far) if not f])
        if lying:
            warn("%s: warning: %s" % (settings.obj, lying))
    if True in far:
        line, message = describe_far(model, far, far_triangles)
        if not triangles:
            raise ConversionError(settings.obj, line, message + ": nothing is left to render")
        warn("%s:%d: warning: %s" % (settings.obj, line, message))
    if not triangles:
        raise ConversionError(settings.obj, 0, "every one of the model's %d triangles is degenerate (two "
                              "corners at one position, or no area): nothing is left to render"
                              % len(model.triangles))
    size = max(placement.high[i] - placement.low[i] for i in range(3))
    lights = lights + emitter_lights(triangles, EMITTER_LIFT * size * placement.scale)
    if settings.ground and not placement.inside:  # a room has a floor of its own
        floor, normal = ground(placement)
        triangles += [[(corner, normal, GROUND_MATERIAL["dif"], GROUND_MATERIAL) for corner in triangle]
                      for triangle in floor]

    out.write("%d\n" % (len(lights) + len(triangles)))
    out.write("amb: %s\n" % vec(settings.ambient))
    for position, color in lights:
        out.write("light\npos: %s\ncol: %s\n" % (vec(position), vec(color)))
    for triangle in triangles:
        out.write("triangle\n")
        for position, normal, dif, material in triangle:
            out.write("pos: %s\nnor: %s\ndif: %s\nspe: %s\nshi: %s\n" % (
                vec(position), vec(normal), vec(dif), vec(material["spe"]), fmt(material["shi"])))
            if material["mir"] != 1.0:  # the classic model's share goes unsaid
                out.write("mir: %s\n" % fmt(material["mir"]))
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


def crease_angle(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("expected degrees from 0 to 180, got '%s'" % text)
    if not 0.0 <= value <= 180.0:
        raise argparse.ArgumentTypeError("expected degrees from 0 to 180, got '%s'" % text)
    return value


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
                        help="scale the model to %g units across and put it straight ahead of the camera, "
                             "filling %d%%%% of the view (of --fov, --width and --height)" % (FIT_SIZE, FRAME_SHARE * 100))
    parser.add_argument("--view", choices=VIEWS,
                        help="with --fit, the side the model is seen from (default three-quarter: front "
                             "right, from above)")
    parser.add_argument("--up", type=up_axis, metavar="AXIS",
                        help="the model's axis that is up, turned onto +y: x, y or z in either case with an "
                             "optional sign (z, Z, +z, -y; default y)")
    parser.add_argument("--crease", type=crease_angle, default=60.0, metavar="DEG",
                        help="a corner without a normal averages the faces around it within DEG degrees of "
                             "its own (0: flat, 180: smooth everywhere; default 60)")
    parser.add_argument("--ground", action="store_true", help="a matte floor under the model, for its shadow")
    parser.add_argument("--rig", action="store_true",
                        help="key, fill and rim lights around the model instead of --light's")
    parser.add_argument("--camera-pos", type=triple, metavar="X,Y,Z",
                        help="the camera --rig is placed for, as Raytracer's option (default: with --fit, the "
                             "model's own camera, at 0,0,0 looking at its centre; else 0,0,0)")
    parser.add_argument("--camera-target", type=triple, metavar="X,Y,Z",
                        help="the point it looks at (default 0,0,-1 from the eye)")
    parser.add_argument("--camera-up", type=triple, metavar="X,Y,Z",
                        help="its up direction (default 0,1,0)")
    parser.add_argument("--fov", type=float, default=60.0, help="the view --fit fills: vertical degrees (default 60)")
    parser.add_argument("--width", type=int, default=640, help="the view --fit fills: width (default 640)")
    parser.add_argument("--height", type=int, default=480, help="the view --fit fills: height (default 480)")
    # "--light -1,5,0" would read as an unknown option "-1,5,0" to argparse: glue
    # each triple to its option ("--light=-1,5,0") first.
    argv = list(sys.argv[1:] if argv is None else argv)
    glued = []
    while argv:
        arg = argv.pop(0)
        glued.append(arg + "=" + argv.pop(0) if arg in ("--light", "--light-color", "--light-colour", "--ambient", "--up",
                                                   "--camera-pos", "--camera-target", "--camera-up") and argv else arg)
    args = parser.parse_args(glued)
    args.up_given, args.up = args.up is not None, args.up or "y"
    if args.view and not args.fit:
        parser.error("--view turns a model fitted with --fit")
    args.view_given, args.view = args.view is not None, args.view or "three-quarter"
    if args.rig and args.light:
        parser.error("--rig places its own lights: give --rig or --light, not both")
    if not (0.0 < args.fov < 180.0) or args.width < 1 or args.height < 1:
        parser.error("--fov must lie strictly between 0 and 180, --width and --height be at least 1")

    sys.stderr.reconfigure(errors="surrogateescape")  # names in the file's own bytes
    warn = lambda message: print(message, file=sys.stderr)
    try:
        model = read_obj(args.obj, warn)
        args.lights = [(p, args.light_color) for p in (args.light or [(0.0, 4.0, 0.0)])]
        args.aspect = args.width / args.height
        # As Raytracer: a camera option given places the rig for that camera (the target
        # straight down -z from the eye unless given); none places it for the model's own.
        args.camera_given = not (args.camera_pos is None and args.camera_target is None and args.camera_up is None)
        args.camera_pos = args.camera_pos or (0.0, 0.0, 0.0)
        args.camera_up = args.camera_up or (0.0, 1.0, 0.0)
        if args.camera_target is None:
            args.camera_target = add(args.camera_pos, (0.0, 0.0, -1.0))
        if args.out:
            temporary = args.out + ".tmp"
            try:
                with open(temporary, "w", encoding="ascii", newline="\n") as out:
                    count = write_scene(out, model, args, warn)
            except ConversionError:
                os.remove(temporary)  # never a half-written scene
                raise
            os.replace(temporary, args.out)  # never a half-written scene
        else:
            count = write_scene(sys.stdout, model, args, warn)
        if model.textured:
            warn("%s: note: the scene format holds no textures: the texture maps of %d material(s) are not "
                 "written" % (args.obj, len(model.textured)))
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
