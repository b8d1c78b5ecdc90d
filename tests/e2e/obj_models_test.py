#!/usr/bin/env python3
"""OBJ models read by Raytracer itself: the scene it builds (--save-scene) is the very text
tools/obj_to_scene.py --fit --ground --rig writes, byte for byte, for models written here
(quads, negative indices, given and missing normals, vertex colours, MTL materials, a
missing library, degenerate faces, a z-up model, sharp edges), with and without the
options that change it; a malformed model gets the same FILE:LINE: error as from the tool,
with exit 3; a binary file is refused with a message; the model renders as
the saved scene does; the framing fills 80% of the view; the ground shows the model's
shadow; --crease 0 gives flat normals, 180 smooth ones; the light rig follows the camera
(from behind, from the side, in every frame of a --turntable), while a saved scene's lights
stay where that run's camera put them.

    obj_models_test.py RAYTRACER TOOL OUTPUT_DIR REFERENCE_RENDER IMAGE_DIFF
"""

import collections
import math
import os
import shutil
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "lib"))
from png_read import read_png  # noqa: E402

RAYTRACER, TOOL, OUTPUT, REFERENCE, IMAGE_DIFF = sys.argv[1:6] if len(sys.argv) >= 6 else (None,) * 5

CUBE = """# cube of quads, no normals; the last face uses negative indices
v -1 -1 -1
v  1 -1 -1
v  1  1 -1
v -1  1 -1
v -1 -1  1
v  1 -1  1
v  1  1  1
v -1  1  1
f 1 4 3 2
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
f -4 -3 -2 -1
"""

MTL = "newmtl shiny\nKd 0.8 0.1 1.7\nKs 0.25\nNs 5000\nnewmtl plain\nKd 0.2 0.3 0.4\n"

MODELS = {
    "cube": (CUBE, None),
    # a z-up model far off the origin, with per-vertex colours and a pentagon of given normals
    "colours": ("v 10 20 30 1 0 0\nv 12 20 30 0 1 0\nv 11 22 31 0 0 1.5\nv 11 20 34\nvn 0 0 2\n"
                "vt 0.5 0.5\nf 1/1/1 2/1/1 3//1\nf 1 2 4\nf 2 3 4\ng side\ns 1\nf 3 1 4\n", None),
    "materials": ("mtllib mats.mtl\nv 0 0 -3\nv 1 0 -3\nv 0 1 -3\nv 1 1 -2\nusemtl shiny\nf 1 2 3\n"
                  "usemtl plain\nf 2 4 3\nusemtl nosuch\nf 1 4 2\n", MTL),
    "no_library": ("mtllib gone.mtl\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", None),
    # coordinates near the largest double: smooth normals without overflow (no nan)
    "huge": ("v 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nv 1e300 1e300 -1e300\nf 1 2 3\nf 2 4 3\n", None),
    # two degenerate faces (a repeated corner, three corners on a line) and a continued line
    "degenerate": ("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 1 2\nf 1 2 3\nf 1 \\\n 2 4\n"
                   "curv 0 1\n", None),
    "crlf": ("v 0 0 0\r\nv 1 0 0\r\nv 0 1 1\r\nf 1 2 3\r\n", None),
    "cylinder": (None, None),  # filled in below: smooth sides, sharp rims
    # a stray vertex far beyond the rest, on a face with the model's own: left out and named
    "far_vertex": ("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 -2e30 7\nf 1 2 3 4\nf 2 5 3\nf 1 3 4\n", None),
}

# An 8-sided prism, z-up (2 tall, 1 across): sides 45 degrees apart, caps at 90.
def prism(sides=8):
    lines = []
    for k in range(sides):
        a = 2 * math.pi * k / sides
        lines += ["v %.6f %.6f 0" % (0.5 * math.cos(a), 0.5 * math.sin(a)),
                  "v %.6f %.6f 2" % (0.5 * math.cos(a), 0.5 * math.sin(a))]
    for k in range(sides):
        b0, t0, b1, t1 = 2 * k + 1, 2 * k + 2, 2 * ((k + 1) % sides) + 1, 2 * ((k + 1) % sides) + 2
        lines.append("f %d %d %d %d" % (b0, b1, t1, t0))
    lines.append("f " + " ".join(str(2 * k + 2) for k in range(sides)))
    lines.append("f " + " ".join(str(2 * k + 1) for k in reversed(range(sides))))
    return "\n".join(lines) + "\n"


MODELS["cylinder"] = (prism(), None)


# A fan of triangles about one edge, each tilted from the flat first one by the default
# crease angle (60 degrees) give or take a few nanoradians: whether a face's normal counts at
# a corner is decided in the last bits of the dot product of the two unit normals (their
# float roundings alone decide some of them otherwise). The far corners spread along and
# away from the edge, so that none is far beyond the rest.
def near_crease(tilts=16):
    lines = ["v 0 0 0", "v 1 0 0", "v 0 1 0"]
    for k in range(tilts):
        theta, reach = math.radians(60) + (k - tilts // 2) * 3e-9, 1 + k / tilts
        lines.append("v %.17g %.17g %.17g" % (k / tilts, reach * math.cos(theta), reach * math.sin(theta)))
    lines.append("f 1 2 3")
    lines += ["f 1 2 %d" % (4 + k) for k in range(tilts)]
    return "\n".join(lines) + "\n"


MODELS["near_crease"] = (near_crease(), None)

# MTL's illumination models on one prism each: glossy (illum 2: a highlight, no mirror),
# mirror (illum 3), matte (illum 1), and Ns 0, which is read as 1.
ILLUM_MTL = ("newmtl glossy\nKd 0.7 0.2 0.1\nKs 0.8\nNs 40\nillum 2\n"
             "newmtl mirror\nKd 0.7 0.2 0.1\nKs 0.8\nNs 40\nillum 3\n"
             "newmtl matte\nKd 0.7 0.2 0.1\nKs 0.8\nillum 1\nnewmtl broad\nKs 0.5\nNs 0\n")
def illum_model(material):
    return "mtllib mats.mtl\nusemtl %s\n" % material + prism(8)


# A box with a glowing top (MTL Ke): a light of its own, above the top's centre.
MODELS["lamp"] = ("mtllib mats.mtl\nv -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\n"
                  "v -1 1 1\nusemtl body\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 4 1 5 8\nusemtl glow\n"
                  "f 4 8 7 3\n", "newmtl body\nKd 0.5 0.5 0.6\nnewmtl glow\nKd 1 1 1\nKe 2 1.5 0.5\n")

def room_model():
    """(OBJ, MTL) of a closed room 6 x 3 x 8 whose faces turn their fronts inwards, a blue box
    on its floor and a lamp: an open quad under the ceiling, facing down, glowing (Ke)."""
    walls, _ = box_model((3.0, 1.5, 4.0))
    faces = [(3, 4, 2, 1), (6, 8, 7, 5), (2, 6, 5, 1), (7, 8, 4, 3), (5, 7, 3, 1), (4, 8, 6, 2)]  # inwards
    box_vs, box_fs = box_model((0.4, 0.4, 0.4), (0.8, -1.1, -1.5), first=9)
    lamp = ["v -0.6 1.45 -0.6", "v 0.6 1.45 -0.6", "v 0.6 1.45 0.6", "v -0.6 1.45 0.6"]
    obj = "\n".join(["mtllib mats.mtl"] + walls + box_vs + lamp + ["usemtl walls"] +
                    ["f %d %d %d %d" % f for f in faces] + ["usemtl box"] + box_fs +
                    ["usemtl lamp", "f 17 18 19 20"]) + "\n"
    mtl = ("newmtl walls\nKd 0.8 0.75 0.7\nnewmtl box\nKd 0.2 0.4 0.8\nKs 0.3\nNs 40\n"
           "newmtl lamp\nKd 1 1 1\nKe 1 0.95 0.8\n")
    return obj, mtl


MODELS["illum"] = ("mtllib mats.mtl\nusemtl glossy\n" + prism(6) + "usemtl mirror\nf 1 3 5\nusemtl matte\n"
                   "f 2 4 6\nusemtl broad\nf 7 9 11\n", ILLUM_MTL)


# A washer as one polygon of 66 corners (two circles of 32 joined by a bridge): concave,
# split by ear clipping; bent, the same ring is fanned with one warning.
def ring(bend=0.0, k=32):
    points = [(math.cos(2 * math.pi * i / k), math.sin(2 * math.pi * i / k), 0.0) for i in range(k)]
    points += [(0.5 * x, 0.5 * y, 0.0) for x, y, _z in points]
    if bend:
        points[3] = (points[3][0], points[3][1], bend)
    corners = list(range(1, k + 1)) + [1, k + 1] + [k + 1 + (k - i) % k for i in range(1, k)] + [k + 1]
    return "".join("v %.9g %.9g %.9g\n" % p for p in points) + "f " + " ".join(map(str, corners)) + "\n"


MODELS["ring"] = (ring(), None)
MODELS["bent_ring"] = (ring(bend=0.2), None)
# Faces that name a position twice, beside faces in other planes: the ring's 66 corners, and a
# pentagon's five, each count once in the smooth normals there.
MODELS["named_twice"] = (ring() + "v 1.3 0 0.2\nv 1.3 0.4 0.15\nf 1 65 66\n"
                         "v 3 0 0\nv 4 0 0\nv 4 1 0\nv 3 1 0.2\nv 3.5 -0.6 0.3\n"
                         "f 67 68 69 67 70\nf 67 71 68\n", None)

# Raytracer's options for a model, and the tool's that build the same scene.
VARIANTS = [
    ([], ["--fit", "--ground", "--rig"]),
    (["--no-ground", "--up", "z", "--crease", "0"], ["--fit", "--rig", "--up", "z", "--crease", "0"]),
    (["--up", "-x", "--crease", "180", "--fov", "40", "--width", "300", "--height", "500"],
     ["--fit", "--ground", "--rig", "--up", "-x", "--crease", "180", "--fov", "40", "--width", "300",
      "--height", "500"]),
    # the rig placed for a moved camera: the tool is given the same camera options
    (["--camera-pos", "3,1,-1", "--camera-target", "0,0,-2.6"],
     ["--fit", "--ground", "--rig", "--camera-pos", "3,1,-1", "--camera-target", "0,0,-2.6"]),
    (["--camera-pos", "-0.5,2,-6", "--camera-up", "0.1,1,0.3", "--no-ground"],
     ["--fit", "--rig", "--camera-pos", "-0.5,2,-6", "--camera-up", "0.1,1,0.3"]),
]

MALFORMED = {
    "v 1 2\n": ":1: error: v expects 3 to 7 numbers, got 2",
    "v 1 2 x\n": ":1: error: v: 'x' is not a number",
    "v 0 0 0 1 1\n": ":1: error: v expects 3, 4, 6 or 7 numbers (x y z [w], or x y z r g b), got 5",
    "v 1 2 1e999\n": ":1: error: v: '1e999' is not a finite number",
    "v 0 0 0\nv 1 0 0\nf 1 2\n": ":3: error: a face needs at least 3 corners, got 2",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n": ":5: error: vertex index 4 is out of range: 3 vertex positions defined so far",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n": ":4: error: vertex index -4 is out of range: 3 vertex positions defined so far",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n": ":4: error: vertex index 0: OBJ indices start at 1 (or -1 for the last)",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2 3\n": ":4: error: normal index 1 is out of range: 0 normals defined so far",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n": ":4: error: vertex index '3x' is not a whole number",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/a 2 3\n": ":4: error: texture coordinate index 'a' is not a whole number",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n":
        ":5: error: texture coordinate index 2 is out of range: 1 texture coordinates defined so far",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0 0 0\nf 1 2 3\n": ":4: error: vt expects 1 to 3 numbers, got 4",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n": ":4: error: face corner '1/2/3/4' is not v, v/vt, v/vt/vn or v//vn",
    "# nothing\n": ": error: no faces (f) found",
    "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n": ": error: every one of the model's 2 triangles is "
    "degenerate (two corners at one position, or no area): nothing is left to render",
    "v 0 0 0\x00\n": ": error: not an OBJ file: it is binary (NUL byte at offset 7)",
    "v 0 0 0\nv \x1b\n": ": error: not an OBJ file: it is binary (control byte 0x1b at offset 10)",
    # a byte that is not UTF-8 is text in an OBJ (names come in any encoding), here a bad number
    "v 0 0 0\nv \xff 0 0\n": ":2: error: v: '\ufffd' is not a number",
}

# A wrong line of a material library is a warning: its material falls back to the default
# one, and the model renders on.
BAD_MTL = {
    "Kd 1 1 1\nnewmtl a\n": "mats.mtl:1: warning: Kd before any newmtl; the line is left out",
    "newmtl\nKd 1 1 1\n": "mats.mtl:1: warning: newmtl needs a name; the lines up to the next "
                          "newmtl are left out",
    "newmtl a\nKs 1 1\nKd 1 0 0\n": "mats.mtl:2: warning: Ks expects 1 or 3 numbers, got 2; "
                                    "material 'a' is the default one",
    "newmtl a\nKd spectral x.spd\n": "mats.mtl:2: warning: Kd spectral colours are not supported; "
                                     "use r g b; material 'a' is the default one",
    "newmtl a\nNs\n": "mats.mtl:2: warning: Ns expects 1 numbers, got 0; material 'a' is the "
                      "default one",
}


def write_model(name, obj, mtl=None, binary=False):
    folder = os.path.join(OUTPUT, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    path = os.path.join(folder, name + ".obj")
    with open(path, "wb") as handle:
        handle.write(obj if isinstance(obj, bytes) else obj.encode("latin-1") if binary else obj.encode("utf-8"))
    if mtl is not None:
        with open(os.path.join(folder, "mats.mtl"), "wb") as handle:
            handle.write(mtl if isinstance(mtl, bytes) else mtl.encode("utf-8"))
    return path


def run(*args):
    return subprocess.run(list(args), capture_output=True, timeout=300)


def read(path):
    with open(path, "rb") as handle:
        return handle.read()


def warnings(stderr):
    return sorted(line for line in stderr.decode(errors="surrogateescape").splitlines() if ": warning: " in line
                  and "degenerate" not in line)


class NativeModels(unittest.TestCase):
    def test_native_scene_is_the_tools_scene_byte_for_byte(self):
        for name, (obj, mtl) in MODELS.items():
            path = write_model(name, obj, mtl)
            for number, (ours_options, tool_options) in enumerate(VARIANTS):
                with self.subTest(model=name, options=ours_options):
                    native, converted = path[:-4] + ".native%d.scene" % number, path[:-4] + ".tool%d.scene" % number
                    ours = run(RAYTRACER, path, "--save-scene", native, *ours_options)
                    self.assertEqual(ours.returncode, 0, ours.stderr)
                    self.assertEqual(ours.stderr.decode().splitlines()[-1], "Wrote " + native)
                    tool = run(sys.executable, TOOL, path, "-o", converted, *tool_options)
                    self.assertEqual(tool.returncode, 0, tool.stderr)
                    self.assertEqual(read(native), read(converted))
                    self.assertEqual(warnings(ours.stderr), warnings(tool.stderr))

    def test_a_saved_scene_reads_back_whatever_the_coordinates(self):
        path = write_model("huge_back", *MODELS["huge"])
        scene = path + ".scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene, "--check").returncode, 0)
        self.assertNotIn(b"nan", read(scene))
        back = run(RAYTRACER, scene, "--check")
        self.assertEqual(back.returncode, 0, back.stderr)

    def test_names_and_comments_are_any_bytes(self):
        # A Latin-1 material name in the OBJ and its MTL, and Latin-1 and UTF-16-looking bytes
        # in a comment: the names match as bytes, nothing is called binary.
        obj = (b"mtllib mats.mtl\n# r\xe9sum\xe9 \xff\xfe\nusemtl caf\xe9\n"
               b"v 0 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\nusemtl caf\xc3\xa9\nf 1 3 2\n")
        mtl = b"newmtl caf\xe9\nKd 0.9 0.1 0.1\nnewmtl caf\xc3\xa9\nKd 0.1 0.9 0.1\n"
        path = write_model("any_bytes", obj, mtl)
        native, converted = path[:-4] + ".native.scene", path[:-4] + ".tool.scene"
        ours = run(RAYTRACER, path, "--save-scene", native)
        self.assertEqual(ours.returncode, 0, ours.stderr)
        self.assertEqual(warnings(ours.stderr), [])
        tool = run(sys.executable, TOOL, path, "-o", converted, "--fit", "--ground", "--rig")
        self.assertEqual(tool.returncode, 0, tool.stderr)
        self.assertEqual(read(native), read(converted))
        text = read(native).decode()
        self.assertIn("dif: 0.9 0.1 0.1", text)  # the Latin-1 name found its material
        self.assertIn("dif: 0.1 0.9 0.1", text)  # and the UTF-8 one its own
        # An unknown Latin-1 name is named in the warning in the file's own bytes.
        path = write_model("any_bytes_unknown", obj.replace(b"usemtl caf\xe9", b"usemtl na\xefve"), mtl)
        ours = run(RAYTRACER, path, "--check")
        tool = run(sys.executable, TOOL, path, "--fit")
        self.assertIn(b"unknown material 'na\xefve'", ours.stderr)
        self.assertEqual(warnings(ours.stderr), warnings(tool.stderr))

    def test_a_concave_face_keeps_its_hole(self):
        # The washer seen face on, without a floor: its middle shows the background.
        path = write_model("ring_hole", *MODELS["ring"])
        png = path + ".png"
        drawn = run(RAYTRACER, path, "--no-ground", "--width", "64", "--height", "48", "-o", png)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        _width, _height, rows = pixels(png)
        self.assertEqual(rows[24][32], (255, 255, 255))  # the background, through the hole
        self.assertNotEqual(rows[24][32 + 15], (255, 255, 255))  # the ring itself
        bent = write_model("ring_bent", *MODELS["bent_ring"])
        ours = run(RAYTRACER, bent, "--check")
        self.assertIn(bent + ":65: warning: 1 concave face(s) not in one plane, or crossing "
                      "themselves, split as fans from their first corner", ours.stderr.decode())

    def test_degenerate_faces_are_counted(self):
        path = write_model("degenerate_count", *MODELS["degenerate"])
        ours = run(RAYTRACER, path, "--save-scene", path + ".scene")
        self.assertIn(path + ": warning: 2 degenerate triangle(s) left out (two corners at one "
                      "position, or no area)", ours.stderr.decode())
        self.assertIn(path + ":9: warning: 'curv' statements are ignored", ours.stderr.decode())

    def test_malformed_models_name_file_and_line_as_the_tool_does(self):
        for number, (obj, message) in enumerate(MALFORMED.items()):
            with self.subTest(obj=obj):
                path = write_model("bad%d" % number, obj, binary=True)
                ours = run(RAYTRACER, path, "--check")
                self.assertEqual(ours.returncode, 3, ours.stderr)
                self.assertEqual(ours.stderr.decode(errors="replace"), path + message + "\n")
                tool = run(sys.executable, TOOL, path, "--fit")
                self.assertEqual(tool.returncode, 1)
                self.assertEqual(tool.stderr.decode(errors="replace"), path + message + "\n")

    def test_malformed_material_libraries_are_warnings_naming_their_own_file_and_line(self):
        for number, (mtl, message) in enumerate(BAD_MTL.items()):
            with self.subTest(mtl=mtl):
                path = write_model("badmtl%d" % number,
                                   "mtllib mats.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n", mtl)
                expected = os.path.join(os.path.dirname(path), message)
                native, converted = path[:-4] + ".native.scene", path[:-4] + ".tool.scene"
                ours = run(RAYTRACER, path, "--save-scene", native)
                self.assertEqual(ours.returncode, 0, ours.stderr)
                self.assertIn(expected, warnings(ours.stderr))
                tool = run(sys.executable, TOOL, path, "-o", converted, "--fit", "--ground", "--rig")
                self.assertEqual(tool.returncode, 0, tool.stderr)
                self.assertEqual(warnings(ours.stderr), warnings(tool.stderr))
                self.assertEqual(read(native), read(converted))
                # The material that fell back is the default one: light grey.
                self.assertIn("dif: 0.75 0.75 0.75", read(native).decode())

    def test_a_library_that_is_no_file_is_refused_at_once(self):
        # /dev/zero, and a link to it, would be read without end.
        folder = os.path.join(OUTPUT, "device_library")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        os.symlink("/dev/zero", os.path.join(folder, "zero.mtl"))
        os.makedirs(os.path.join(folder, "folder.mtl"))
        for library in ("/dev/zero", "zero.mtl", "folder.mtl"):
            with self.subTest(library=library):
                path = os.path.join(folder, "model.obj")
                with open(path, "w") as handle:
                    handle.write("mtllib %s\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" % library)
                named = library if library.startswith("/") else os.path.join(folder, library)
                expected = (named + ": error: not a regular file (a device, a pipe or a folder): a "
                            "material library must be a file\n")
                ours = run(RAYTRACER, path, "--check")
                self.assertEqual(ours.returncode, 3, ours.stderr)
                self.assertEqual(ours.stderr.decode(), expected)
                tool = run(sys.executable, TOOL, path, "--fit")
                self.assertEqual(tool.returncode, 1)
                self.assertEqual(tool.stderr.decode(), expected)

    def test_other_formats_behind_an_obj_name_are_named(self):
        # UTF-16 text is named by both. A PLY model behind an .obj name is read as PLY by
        # Raytracer, which tells formats by their first bytes (this one's header is cut
        # short), and named by the tool, which reads OBJ alone.
        ply = b"ply\nformat ascii 1.0\nelement vertex 3\n"
        cases = {
            ply: ("the file ends before the PLY header's end_header line",
                  "not an OBJ model: this is a PLY model, which is not read; convert it to OBJ first (for "
                  "example with assimp export, Debian's assimp-utils)"),
            "v 0 0 0\n".encode("utf-16"): ("the file is UTF-16 text, and an OBJ model is read as UTF-8; "
                                          "convert it first: iconv -f UTF-16 -t UTF-8 '{path}' > converted.obj",) * 2,
        }
        for number, (data, (message, tool_message)) in enumerate(cases.items()):
            with self.subTest(message=message):
                path = write_model("other%d" % number, data, binary=True)
                ours = run(RAYTRACER, path, "--check")
                self.assertEqual(ours.returncode, 3, ours.stderr)
                where = ":3: error: " if data == ply else ": error: "  # the header's last line
                self.assertEqual(ours.stderr.decode(), path + where + message.replace("{path}", path) + "\n")
                tool = run(sys.executable, TOOL, path, "--fit")
                self.assertEqual(tool.returncode, 1)
                self.assertEqual(tool.stderr.decode(),
                                 path + ": error: " + tool_message.replace("{path}", path) + "\n")

    def test_illum_2_is_a_highlight_without_a_mirror(self):
        # A glossy model (illum 2) reflects nothing: its pixels do not change when the sky
        # (the background) turns from white to black, while the illum 3 model's do. Each
        # renders as its saved scene (the scene format's mir: 0) and as the reference does.
        size = ["--width", "120", "--height", "90", "--up", "z"]
        changed = {}
        for material in ("glossy", "mirror"):
            path = write_model("illum_" + material, illum_model(material), ILLUM_MTL)
            scene, direct, via_scene = path + ".scene", path + ".png", path + ".scene.png"
            self.assertEqual(run(RAYTRACER, path, "--save-scene", scene, *size).returncode, 0)
            self.assertEqual(b"mir: 0\n" in read(scene), material == "glossy")
            drawn = run(RAYTRACER, path, "-o", direct, "--validate", *size)
            self.assertEqual(drawn.returncode, 0, drawn.stderr)
            self.assertEqual(run(RAYTRACER, scene, "-o", via_scene, *size[:4]).returncode, 0)
            self.assertEqual(read(direct), read(via_scene))
            # The reference has no --up: it renders the scene Raytracer built.
            reference = path + ".reference.png"
            self.assertEqual(run(REFERENCE, scene, "-o", reference, *size[:4]).returncode, 0)
            compared = run(IMAGE_DIFF, direct, reference, "--tolerance", "2", "--min-match", "99.9")
            self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
            # A black sky: pixels that showed the sky change, and those that reflect it.
            dark = path + ".dark.png"
            self.assertEqual(run(RAYTRACER, scene, "-o", dark, "--background", "0,0,0", *size[:4]).returncode, 0)
            _w, _h, a = pixels(direct)
            _w, _h, b = pixels(dark)
            changed[material] = sum(1 for y in range(90) for x in range(120)
                                    if a[y][x] != b[y][x] and a[y][x] != (255, 255, 255))
        self.assertEqual(changed["glossy"], 0)
        self.assertGreater(changed["mirror"], 50)

    def test_an_emitting_material_is_a_light_above_its_surface(self):
        path = write_model("lamp_light", *MODELS["lamp"])
        scene = path + ".scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene, "--view", "front").returncode, 0)
        header, objects = scene_objects(scene)
        lights = [lines for lines in objects if lines[0] == "light"]
        self.assertEqual(len(lights), 4)
        emitter = [float(v) for v in lights[3][1].split()[1:]]
        self.assertEqual(lights[3][2], "col: 1 1 0.5")  # Ke 2 1.5 0.5 clamped to [0, 1]
        positions = [c[0] for t in scene_triangles(scene)[:12] for c in t]
        top = max(p[1] for p in positions)
        centre = [(max(p[a] for p in positions) + min(p[a] for p in positions)) / 2 for a in range(3)]
        self.assertAlmostEqual(emitter[0], centre[0], places=5)
        self.assertAlmostEqual(emitter[2], centre[2], places=5)
        self.assertAlmostEqual(emitter[1] - top, 0.01 * 1.5, places=5)  # lifted 1% of the fitted size

    def test_the_model_renders_as_its_saved_scene(self):
        path = write_model("render", CUBE)
        scene, direct, via_scene = path + ".scene", path + ".png", path + ".scene.png"
        size = ["--width", "96", "--height", "72", "--validate"]
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene).returncode, 0)
        drawn = run(RAYTRACER, path, "-o", direct, *size)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        again = run(RAYTRACER, scene, "-o", via_scene, *size)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertEqual(read(direct), read(via_scene))
        check = run(RAYTRACER, path, "--check")
        self.assertEqual(check.returncode, 0, check.stderr)
        self.assertIn(b"\ntriangles: 14\n", check.stdout)  # and the ground's two


def scene_objects(path):
    """The header's two lines, and each object's lines (its keyword first), of a scene file
    as --save-scene writes it: one key and its numbers a line."""
    lines = read(path).decode().split("\n")
    header, objects = lines[:2], []
    for line in lines[2:]:
        if line in ("light", "sphere", "triangle"):
            objects.append([line])
        elif line:
            objects[-1].append(line)
    return header, objects


def scene_triangles(path):
    """[(3 positions, 3 normals)] of a scene file as --save-scene writes it."""
    result = []
    for lines in scene_objects(path)[1]:
        if lines[0] != "triangle":
            continue
        fields = [line.split() for line in lines[1:]]
        positions = [tuple(float(t) for t in f[1:]) for f in fields if f[0] == "pos:"]
        normals = [tuple(float(t) for t in f[1:]) for f in fields if f[0] == "nor:"]
        result.append(list(zip(positions, normals)))
    return result


def pixels(png):
    """(width, height, rows of (r, g, b)) of a PNG Raytracer wrote."""
    return read_png(png)


class WhatAModelIsGiven(unittest.TestCase):
    def test_the_framing_fills_80_percent_of_the_view(self):
        # A cube seen face on: its front corners are the outermost, symmetric about the
        # centre of the view, so the silhouette is 80% of the height (the 4:3 width is
        # not the limit for a square).
        path = write_model("framing", CUBE)
        png = path + ".png"
        drawn = run(RAYTRACER, path, "--no-ground", "--view", "front", "-o", png)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        width, height, rows = pixels(png)
        covered = [y for y in range(height) if any(p != (255, 255, 255) for p in rows[y])]
        share = (covered[-1] - covered[0] + 1) / height
        self.assertAlmostEqual(share, 0.8, delta=2 / height)

    def test_the_ground_shows_the_models_shadow(self):
        path = write_model("shadow", CUBE)
        scene = path + ".scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene).returncode, 0)
        # The same lights and ground without the cube: the ground alone, unshadowed.
        header, objects = scene_objects(scene)
        lights = [line for lines in objects[:3] for line in lines]
        ground = [line for lines in objects[-2:] for line in lines]
        self.assertEqual(len(objects), 3 + 12 + 2)
        bare = path + ".bare.scene"
        with open(bare, "w") as handle:
            handle.write("\n".join(["5", header[1]] + lights + ground) + "\n")
        with_model, without = path + ".png", path + ".bare.png"
        for source, png in ((scene, with_model), (bare, without)):
            drawn = run(RAYTRACER, source, "-o", png, "--width", "160", "--height", "120")
            self.assertEqual(drawn.returncode, 0, drawn.stderr)
        _w, _h, a = pixels(with_model)
        _w, _h, b = pixels(without)
        # Below the cube's silhouette, ground pixels the cube darkens: its shadow.
        darker = sum(1 for y in range(120) for x in range(160)
                     if a[y][x] != (255, 255, 255) and b[y][x] != (255, 255, 255) and sum(a[y][x]) + 30 < sum(b[y][x])
                     and y > 60)
        self.assertGreater(darker, 100)

    def test_crease_0_gives_flat_normals_and_180_smooth_ones(self):
        path = write_model("crease", prism(8))
        for crease, flat in (("0", True), ("60", False), ("180", False)):
            with self.subTest(crease=crease):
                scene = path + ".%s.scene" % crease
                self.assertEqual(run(RAYTRACER, path, "--crease", crease, "--up", "z", "--no-ground",
                                     "--view", "front", "--save-scene", scene).returncode, 0)
                triangles = scene_triangles(scene)
                corners_alike = all(t[0][1] == t[1][1] == t[2][1] for t in triangles)
                self.assertEqual(corners_alike, flat)
        # At 60 degrees the sides (45 apart) are smooth but the rims (90) stay sharp: the
        # caps' corners all point straight up or down (the prism stands upright, --up z).
        triangles = scene_triangles(path + ".60.scene")
        caps = [t for t in triangles if len({c[0][1] for c in t}) == 1]
        self.assertTrue(caps)
        for t in caps:
            for _position, normal in t:
                self.assertEqual((normal[0], normal[2]), (0.0, 0.0))

    def test_a_model_renders_as_the_reference_renders_it(self):
        # The double-precision CPU reference builds the model by the same rules for the same
        # view (here not 4:3, so the framing's aspect counts), and the images agree as the
        # classic scenes do (99.9% of the pixels within 2 levels).
        path = write_model("conformance", prism(8))
        size = ["--width", "200", "--height", "120", "--fov", "50"]
        ours, reference = path + ".png", path + ".reference.png"
        drawn = run(RAYTRACER, path, "--up", "z", "-o", ours, "--validate", *size)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        # The reference has no --up: give it the scene Raytracer built.
        scene = path + ".scene"
        self.assertEqual(run(RAYTRACER, path, "--up", "z", "--save-scene", scene, *size).returncode, 0)
        drawn = run(REFERENCE, scene, "-o", reference, *size)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        compared = run(IMAGE_DIFF, ours, reference, "--tolerance", "2", "--min-match", "99.9")
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
        # And the reference reading the OBJ file itself builds the same scene for that view.
        direct = path + ".reference-direct.png"
        plain = run(RAYTRACER, path, "-o", path + ".plain.png", "--validate", *size)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertEqual(run(REFERENCE, path, "-o", direct, *size).returncode, 0)
        compared = run(IMAGE_DIFF, path + ".plain.png", direct, "--tolerance", "2", "--min-match", "99.9")
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)

    def test_up_z_stands_a_z_up_model_upright(self):
        path = write_model("z_up", prism(8))  # 2 tall along z, 1 across
        for up, tallest in (("y", 2), ("z", 1), ("Z", 1), ("+z", 1), ("+Y", 2), ("-z", 1)):
            with self.subTest(up=up):
                scene = path + ".%s.scene" % up
                self.assertEqual(run(RAYTRACER, path, "--up", up, "--no-ground", "--view", "front",
                                     "--save-scene", scene).returncode, 0)
                positions = [c[0] for t in scene_triangles(scene) for c in t]
                extents = [max(p[a] for p in positions) - min(p[a] for p in positions) for a in range(3)]
                self.assertEqual(extents.index(max(extents)), tallest)
        # Read as y-up, the z-up prism lies on its back: one note says so, unless --up is given
        # (even as y); a flat model is left alone.
        note = b"warning: the model is longest along z and shallowest along y"
        self.assertIn(note, run(RAYTRACER, path, "--check").stderr)
        for options in (["--up", "y"], ["--up", "z"]):
            self.assertNotIn(note, run(RAYTRACER, path, "--check", *options).stderr)
        flat = write_model("flat_star", "v 0 0 0\nv 1 0 3\nv -1 0 3\nf 1 2 3\n")
        self.assertNotIn(note, run(RAYTRACER, flat, "--check").stderr)
        for wrong in ("w", "zz", "+-z", ""):
            refused = run(RAYTRACER, path, "--up", wrong, "--check")
            self.assertEqual(refused.returncode, 2, refused.stderr)
            self.assertIn(b"--up expects an axis, x, y or z in either case with an optional sign (z, Z, +z, -y), "
                          b"got '" + wrong.encode() + b"'", refused.stderr)

    def test_a_vertex_far_beyond_the_rest_is_named_and_left_out(self):
        # A cube and one more face through a vertex at 1e38 (an exporter's stray vertex):
        # the fit ignores it, the face is left out, one warning names its line and the
        # cube's extent, and the image is the plain cube's, byte for byte.
        far = write_model("far_vertex", CUBE + "v 0.5 1e38 0.5\nf 1 2 -1\n")
        plain = write_model("far_vertex_plain", CUBE)
        size = ["--width", "96", "--height", "72"]
        drawn = run(RAYTRACER, far, "-o", far + ".png", *size)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        line = CUBE.count("\n") + 1
        self.assertIn(("far_vertex.obj:%d: warning: 1 vertex(es) far beyond the rest of the model (the first here, "
                       "at 0.5 1e+38 0.5: more than 1000 times the model's spread from its median) are left out, "
                       "with the faces that use them (1 triangle(s)); without them the model spans x -1..1, "
                       "y -1..1, z -1..1" % line).encode(), drawn.stderr)
        self.assertEqual(run(RAYTRACER, plain, "-o", plain + ".png", *size).returncode, 0)
        self.assertEqual(read(far + ".png"), read(plain + ".png"))
        # A model of nothing but faces through far vertices is an error naming the first.
        lone = write_model("far_only", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nv 9e37 0 0\nf 1 2 6\n")
        refused = run(RAYTRACER, lone, "--check")
        self.assertEqual(refused.returncode, 3, refused.stderr)
        self.assertIn(b"far_only.obj:6: error: 1 vertex(es) far beyond", refused.stderr)
        self.assertIn(b": nothing is left to render", refused.stderr)


def box_model(half, centre=(0.0, 0.0, 0.0), first=1):
    """(v lines, f lines) of a box of half sizes half about centre, its indices from first."""
    vs = ["v %r %r %r" % tuple(centre[a] + half[a] * s[a] for a in range(3))
          for s in [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]]
    faces = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]
    return vs, ["f " + " ".join(str(first - 1 + i) for i in face) for face in faces]


MODELS["room"] = room_model()  # after box_model, which it uses


def corpus():
    """The framing corpus, made here: {name: OBJ text}."""
    models = {"flat_up": "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 4 3 2\n",
              "flat_facing": "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n"}
    for axis, half in (("x", (4, 0.1, 0.1)), ("y", (0.1, 4, 0.1)), ("z", (0.1, 0.1, 4))):
        vs, fs = box_model(half)
        models["long_" + axis] = "\n".join(vs + fs) + "\n"
    cube_vs, cube_fs = box_model((0.3, 0.3, 0.3), (0.0, 0.3, 0.0))  # on a slab of its own
    slab_vs, slab_fs = box_model((2.0, 0.02, 2.0), (0.0, -0.02, 0.0), first=9)
    models["own_floor"] = "\n".join(cube_vs + slab_vs + cube_fs + slab_fs) + "\n"
    return models


# The framing corpus's rules: the silhouette (without the floor) spans this share of the
# frame's width or height, whichever is larger; no more than this share of the pixels are
# isolated (each 48 levels or more from all 8 neighbours in some channel: the speckle of a
# floor in the plane of a face), and none is the background's white (the floor fills the
# three-quarter view, with no horizon).
SPAN = (0.60, 0.95)
ISOLATED = 0.005


def isolated_share(rows):
    height, width, count = len(rows), len(rows[0]), 0
    for y in range(1, height - 1):
        for x in range(1, width - 1):
            p = rows[y][x]
            if all(max(abs(p[c] - rows[y + dy][x + dx][c]) for c in range(3)) >= 48
                   for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy):
                count += 1
    return count / (width * height)


class TheDefaultViewShowsTheModel(unittest.TestCase):
    def test_every_model_of_the_corpus_is_framed_and_clean(self):
        size = ["--width", "160", "--height", "120"]
        for name, obj in corpus().items():
            with self.subTest(model=name):
                path = write_model("corpus_" + name, obj)
                bare, full, reference = path + ".bare.png", path + ".png", path + ".reference.png"
                for png, options in ((bare, ["--no-ground"]), (full, [])):
                    drawn = run(RAYTRACER, path, "-o", png, "--validate", *size, *options)
                    self.assertEqual(drawn.returncode, 0, drawn.stderr)
                width, height, rows = pixels(bare)
                seen = [(x, y) for y in range(height) for x in range(width) if rows[y][x] != (255, 255, 255)]
                xs, ys = [x for x, _y in seen], [y for _x, y in seen]
                span = max((max(xs) - min(xs) + 1) / width, (max(ys) - min(ys) + 1) / height)
                _w, _h, rows = pixels(full)
                noise = isolated_share(rows)
                white = sum(1 for row in rows for p in row if p == (255, 255, 255))
                print("corpus: %s: silhouette span %.2f, isolated pixels %.3f%%, white %d"
                      % (name, span, 100 * noise, white))
                self.assertTrue(SPAN[0] <= span <= SPAN[1], span)
                self.assertLess(noise, ISOLATED)
                self.assertEqual(white, 0)
                # The reference builds the model by the same rules and agrees.
                self.assertEqual(run(REFERENCE, path, "-o", reference, *size).returncode, 0)
                compared = run(IMAGE_DIFF, full, reference, "--tolerance", "2", "--min-match", "99.9")
                self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)

    def test_named_views_show_the_sides_they_name(self):
        # A box wider (x) than deep (z) than tall (y): each view's silhouette has the
        # proportions of the side it names; a flat quad seen from the top shows its face.
        vs, fs = box_model((1.0, 0.25, 0.5))
        path = write_model("views", "\n".join(vs + fs) + "\n")
        expected = {"front": (1.0, 0.25), "back": (1.0, 0.25), "left": (0.5, 0.25), "right": (0.5, 0.25),
                    "top": (1.0, 0.5), "bottom": (1.0, 0.5)}
        for view, (across, up) in expected.items():
            with self.subTest(view=view):
                png = path + ".%s.png" % view
                drawn = run(RAYTRACER, path, "--view", view, "--no-ground", "-o", png, "--width", "160",
                            "--height", "160")
                self.assertEqual(drawn.returncode, 0, drawn.stderr)
                _w, _h, rows = pixels(png)
                seen = [(x, y) for y in range(160) for x in range(160) if rows[y][x] != (255, 255, 255)]
                w = max(x for x, _y in seen) - min(x for x, _y in seen) + 1
                h = max(y for _x, y in seen) - min(y for _x, y in seen) + 1
                self.assertAlmostEqual(h / w, up / across, delta=0.15 * up / across)
        refused = run(RAYTRACER, path, "--view", "top", "--no-fit", "--check")
        self.assertEqual(refused.returncode, 2)
        self.assertIn(b"--view turns a model fitted to the view", refused.stderr)

    def test_check_names_the_model_and_the_floor_apart(self):
        vs, fs = box_model((2.0, 0.5, 1.0), (10.0, 20.0, 30.0))
        path = write_model("check_bounds", "\n".join(vs + fs) + "\n")
        check = run(RAYTRACER, path, "--check")
        self.assertEqual(check.returncode, 0, check.stderr)
        lines = dict(line.split(": ", 1) for line in check.stdout.decode().splitlines()[1:])
        self.assertEqual(lines["model as read"], "8,19.5,29 to 12,20.5,31")
        placed = [[float(c) for c in corner.split(",")] for corner in lines["model as placed"].split(" to ")]
        floor = [[float(c) for c in corner.split(",")] for corner in lines["floor"].split(" to ")]
        self.assertLess(max(placed[1][a] - placed[0][a] for a in range(3)), 3.0)  # about 1.5 across, turned
        self.assertGreater(floor[1][0] - floor[0][0], 50.0)  # a hundred model sizes
        no_floor = run(RAYTRACER, path, "--check", "--no-ground", "--no-fit")
        lines = dict(line.split(": ", 1) for line in no_floor.stdout.decode().splitlines()[1:])
        self.assertEqual(lines["floor"], "none (--no-ground)")
        self.assertEqual(lines["model as placed"], "8,19.5,29 to 12,20.5,31 (--no-fit: as read, its up axis turned)")
        self.assertEqual(lines["not rendered"], "nothing")

    def test_check_names_what_the_materials_hold_that_is_not_rendered(self):
        mtl = ("newmtl lamp\nKd 1 1 1\nKe 4 4 3\nmap_Kd lamp.png\n"
               "newmtl glass\nKd 0.9 0.9 1\nd 0.3\nmap_Kd glass.png\nbump glass_n.png\n"
               "newmtl opaque\nd 1\nTr 0\nKe 0 0 0\n")
        path = write_model("not_rendered", "mtllib mats.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n",
                           mtl)
        check = run(RAYTRACER, path, "--check")
        self.assertEqual(check.returncode, 0, check.stderr)
        self.assertIn(b"\nnot rendered: other maps (bump, map_Ks, ...) in 1 material; "
                      b"transparency (d, Tr) in 1 material\n", check.stdout)
        self.assertIn(b"\nlights: 4\n", check.stdout)  # the rig's three and the lamp's Ke
        # A render names it once, in one line; --save-scene and the tool say that the scene
        # format holds no textures.
        drawn = run(RAYTRACER, path, "-o", path + ".png", "--width", "40", "--height", "30")
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        lines = [line for line in drawn.stderr.decode().splitlines() if "not rendered" in line]
        self.assertEqual(lines, [path + ": note: not rendered: other maps (bump, map_Ks, ...) in 1 material; "
                                 "transparency (d, Tr) in 1 material"])
        unwritten = (path + ": note: the scene format holds no textures: the texture maps of 2 material(s) are "
                     "not written")
        saved = run(RAYTRACER, path, "--save-scene", path + ".scene")
        self.assertEqual(saved.returncode, 0, saved.stderr)
        self.assertIn(unwritten, saved.stderr.decode().splitlines())
        tool = run(sys.executable, TOOL, path, "--fit", "-o", path + ".tool.scene")
        self.assertEqual(tool.returncode, 0, tool.stderr)
        self.assertIn(unwritten, tool.stderr.decode().splitlines())


def coarse_sphere(rings=6, sides=8):
    """A UV sphere of few faces, its normals left to the smooth rule: the shadow terminator's
    classic victim."""
    vs = ["v 0 1 0"]
    for i in range(1, rings):
        t = math.pi * i / rings
        vs += ["v %r %r %r" % (math.sin(t) * math.cos(2 * math.pi * j / sides), math.cos(t),
                               math.sin(t) * math.sin(2 * math.pi * j / sides)) for j in range(sides)]
    vs.append("v 0 -1 0")
    faces = ["f 1 %d %d" % (2 + (j + 1) % sides, 2 + j) for j in range(sides)]
    for i in range(rings - 2):
        for j in range(sides):
            a, b = 2 + i * sides + j, 2 + i * sides + (j + 1) % sides
            faces.append("f %d %d %d %d" % (a, b, b + sides, a + sides))
    last = len(vs)
    faces += ["f %d %d %d" % (2 + (rings - 2) * sides + j, 2 + (rings - 2) * sides + (j + 1) % sides, last)
              for j in range(sides)]
    return "\n".join(vs + faces) + "\n"


class ARoomIsSeenFromInside(unittest.TestCase):
    def test_a_closed_room_with_a_lamp_opens_inside_lit_and_varied(self):
        path = write_model("room_inside", *room_model())
        check = run(RAYTRACER, path, "--check")
        self.assertEqual(check.returncode, 0, check.stderr)
        lines = dict(line.split(": ", 1) for line in check.stdout.decode().splitlines()[1:])
        self.assertTrue(lines["model as placed"].endswith("(a room: seen from inside)"), lines)
        self.assertEqual(lines["floor"], "none (a room has its own)")
        self.assertEqual(lines["lights"], "4")  # the rig's three inside, and the lamp
        self.assertNotIn(b"give --up z", check.stderr)  # a room is often longer than tall
        png = path + ".png"
        drawn = run(RAYTRACER, path, "-o", png, "--validate", "--width", "160", "--height", "120")
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        _w, _h, rows = pixels(png)
        values = [sum(p) / 3.0 for row in rows for p in row]
        mean = sum(values) / len(values)
        spread = math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))
        commonest = max(collections.Counter(p for row in rows for p in row).values()) / len(values)
        print("room: mean %.1f, deviation %.1f, commonest colour %.1f%% of the pixels" % (mean, spread, 100 * commonest))
        self.assertEqual(sum(1 for row in rows for p in row if p == (255, 255, 255)), 0)  # no sky: inside
        self.assertGreater(mean, 60)  # lit, not the ambient grey (26) of lights outside the walls
        self.assertGreater(spread, 10)
        self.assertLess(commonest, 0.3)
        reference = path + ".reference.png"
        self.assertEqual(run(REFERENCE, path, "-o", reference, "--width", "160", "--height", "120").returncode, 0)
        compared = run(IMAGE_DIFF, png, reference, "--tolerance", "2", "--min-match", "99.9")
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
        # Asked for a view, or a closed solid (its faces turned away from its centre): outside.
        for options, model in ((["--view", "three-quarter"], path), ([], write_model("solid_cube", CUBE))):
            check = run(RAYTRACER, model, "--check", *options)
            self.assertNotIn(b"seen from inside", check.stdout)


class TheShadowTerminator(unittest.TestCase):
    def test_a_coarse_smooth_sphere_loses_its_polygonal_shadow_patches(self):
        # Without the fix, faces next to the lit side shadow points whose smooth normal still
        # faces the light: hard polygonal patches, pixels far darker than with the fix. The
        # fix changes nothing else (the floor's flat normals move no shadow ray), and the
        # reference, which shifts the same way, agrees.
        path = write_model("terminator", coarse_sphere())
        size = ["--width", "160", "--height", "120"]
        images = {}
        for setting in ("on", "off"):
            png = path + ".%s.png" % setting
            drawn = run(RAYTRACER, path, "--terminator", setting, "-o", png, "--validate", *size)
            self.assertEqual(drawn.returncode, 0, drawn.stderr)
            images[setting] = pixels(png)[2]
        default = path + ".default.png"
        self.assertEqual(run(RAYTRACER, path, "-o", default, *size).returncode, 0)
        self.assertEqual(read(default), read(path + ".on.png"))  # on for a model by default
        on, off = images["on"], images["off"]
        # Measured: 142 pixels (of the sphere's about 5,000) 6 levels or more darker without
        # the fix, 9 of them 16 or more; none brighter.
        patches = sum(1 for y in range(120) for x in range(160) if sum(on[y][x]) - sum(off[y][x]) >= 18)
        brighter = sum(1 for y in range(120) for x in range(160) if sum(off[y][x]) - sum(on[y][x]) >= 18)
        print("terminator: %d pixels at least 6 levels darker without the fix, %d brighter" % (patches, brighter))
        self.assertGreater(patches, 60)
        self.assertEqual(brighter, 0)
        reference = path + ".reference.png"
        self.assertEqual(run(REFERENCE, path, "-o", reference, *size).returncode, 0)
        compared = run(IMAGE_DIFF, path + ".on.png", reference, "--tolerance", "2", "--min-match", "99.9")
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
        # A scene file keeps the classic model unless asked; asked, the reference agrees too.
        scene = path + ".scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene).returncode, 0)
        for setting, same in (("on", True), ("off", False)):
            png = path + ".scene.%s.png" % setting
            self.assertEqual(run(RAYTRACER, scene, "--terminator", setting, "-o", png, *size).returncode, 0)
            reference = path + ".scene.reference.%s.png" % setting
            self.assertEqual(run(REFERENCE, scene, "--terminator", setting, "-o", reference, *size).returncode, 0)
            compared = run(IMAGE_DIFF, png, reference, "--tolerance", "2", "--min-match", "99.9")
            self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)
            self.assertEqual(read(png) == read(path + ".on.png"), same)
        plain = path + ".scene.plain.png"
        self.assertEqual(run(RAYTRACER, scene, "-o", plain, *size).returncode, 0)
        self.assertEqual(read(plain), read(path + ".scene.off.png"))


def model_brightness(png):
    """(mean brightness 0..255 of the pixels that are not the white background, their count)."""
    _width, _height, rows = pixels(png)
    model = [sum(p) / 3.0 for row in rows for p in row if p != (255, 255, 255)]
    return sum(model) / len(model), len(model)


# Mean model-pixel brightness from a moved camera stays within this share of the default
# view's: the rig turns with the camera, so a cube (alike on every side) seen from behind
# or from the side is lit as from the front; what is left is the framing (the model fills
# the view differently from another distance and angle) and the shadowed faces seen.
RIG_MARGIN = 0.20


class TheRigFollowsTheCamera(unittest.TestCase):
    # The model seen face on, so that behind and the side are its other faces.
    SIZE = ["--width", "96", "--height", "72", "--no-ground", "--view", "front"]
    MODEL_ONLY = ("--no-ground", "--view", "front")

    def centre(self, path):
        scene = path + ".centre.scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", scene, *self.SIZE).returncode, 0)
        positions = [c[0] for t in scene_triangles(scene) for c in t]
        return tuple((min(p[a] for p in positions) + max(p[a] for p in positions)) / 2 for a in range(3))

    def render(self, source, png, *options):
        # A saved scene has its floor and view already: those options are for models alone.
        size = [o for o in self.SIZE if o not in self.MODEL_ONLY or source.endswith(".obj")]
        drawn = run(RAYTRACER, source, "-o", png, "--validate", *size, *options)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        return model_brightness(png)

    def test_a_moved_camera_sees_the_model_lit_as_the_default_one(self):
        path = write_model("rig_follows", CUBE)
        cx, cy, cz = self.centre(path)
        distance = -cz  # the default camera's, from the origin
        target = "%r,%r,%r" % (cx, cy, cz)
        front, _count = self.render(path, path + ".front.png")
        views = {"behind": (cx, cy, cz - distance), "side": (cx + distance, cy, cz)}
        for view, eye in views.items():
            with self.subTest(view=view):
                seen, count = self.render(path, path + ".%s.png" % view,
                                          "--camera-pos", "%r,%r,%r" % eye, "--camera-target", target)
                self.assertGreater(count, 500)
                print("rig: %s: mean model brightness %.1f, default view %.1f (%+.1f%%)"
                      % (view, seen, front, 100 * (seen / front - 1)))
                self.assertLess(abs(seen / front - 1), RIG_MARGIN)
        # The scene saved for the default camera keeps its lights in the world: seen from
        # behind, the model faces away from its key and fill lights and is much darker,
        # which is what the rig's following avoids.
        saved = path + ".default.scene"
        self.assertEqual(run(RAYTRACER, path, "--save-scene", saved, *self.SIZE).returncode, 0)
        fixed, _count = self.render(saved, path + ".fixed_behind.png", "--camera-pos",
                                    "%r,%r,%r" % views["behind"], "--camera-target", target)
        print("rig: behind, lights fixed in the world: %.1f (%+.1f%%)" % (fixed, 100 * (fixed / front - 1)))
        self.assertLess(fixed / front - 1, -RIG_MARGIN)

    def test_the_rig_follows_each_frame_of_a_turntable(self):
        path = write_model("rig_turntable", CUBE)
        folder = os.path.join(OUTPUT, "rig_turntable", "frames")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        drawn = run(RAYTRACER, path, "--turntable", "4", "-o", os.path.join(folder, "{frame}.png"), "--validate",
                    *self.SIZE)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        first, _count = model_brightness(os.path.join(folder, "0.png"))
        for frame in (1, 2, 3):
            with self.subTest(frame=frame):
                seen, _count = model_brightness(os.path.join(folder, "%d.png" % frame))
                print("rig: turntable frame %d of 4: %.1f, frame 0 %.1f (%+.1f%%)"
                      % (frame, seen, first, 100 * (seen / first - 1)))
                self.assertLess(abs(seen / first - 1), RIG_MARGIN)
        # Frame 0 is the plain render: the batch places the rig as the single image does.
        single = path + ".single.png"
        self.render(path, single)
        self.assertEqual(read(single), read(os.path.join(folder, "0.png")))


if __name__ == "__main__":
    if None in (RAYTRACER, TOOL, OUTPUT, REFERENCE, IMAGE_DIFF):
        sys.exit(__doc__)
    os.makedirs(OUTPUT, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
