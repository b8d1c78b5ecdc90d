#!/usr/bin/env python3
"""Models in PLY, STL, glTF and GLB render as the same model in OBJ, and bad files of those
formats are refused by name.

    model_formats_test.py RAYTRACER CONVERT_MODEL REFERENCE IMAGE_DIFF OUTPUT_DIR

One model (a coarse sphere, smooth by the crease rule, beside a box with sharp edges, all
triangles) is written here as OBJ and converted by tools/convert_model.py (CONVERT_MODEL)
into ASCII and binary PLY (little- and big-endian), ASCII and binary STL, glTF (with its
.bin beside it) and GLB. Each renders as the OBJ does: 99.9% of the pixels within 2/255
(measured: every pixel equal). PLY and STL carry no material, so they are compared with the
OBJ without one; glTF's material (base colour 0.75, metallic 0, roughness 0.5) maps onto
the Phong model as the OBJ's MTL states it (Kd 0.75, Ks 0.02, Ns 30; docs/models.md). The
same model with vertex colours in PLY and GLB renders as the OBJ's `v x y z r g b`. The
CPU reference, reading the GLB, agrees. A PLY named .obj is read as PLY. Bad files (cut
short, a header claiming 2^31 faces, an index naming no vertex, a GLB chunk longer than
the file, a glTF naming a missing buffer or a device, a link to /dev/zero) exit 3 with the
file's name and what is wrong, each within a time limit. PLY triangle strips (restarted,
with a join's degenerate triangle) render as the OBJ of their triangles; an ASCII PLY
whose lines hold more values than its header declares renders as without them, with one
warning.
"""
import math
import os
import struct
import subprocess
import sys
import unittest

RAYTRACER, CONVERT, REFERENCE, IMAGE_DIFF, OUTPUT = sys.argv[1:6] if len(sys.argv) >= 6 else (None,) * 5
SIZE = ["--width", "160", "--height", "120"]
MTL = "newmtl shiny\nKd 0.75 0.75 0.75\nKs 0.02 0.02 0.02\nNs 30\nillum 2\n"
GLTF_MATERIAL = ["--base-color", "0.75,0.75,0.75", "--metallic", "0", "--roughness", "0.5"]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def model_lines(colours):
    """OBJ lines of a sphere of 8 rings and 12 sides and a box beside it, in single precision."""
    rings, sides = 8, 12
    vs = [(0.0, 1.0, 0.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(sides):
            phi = 2 * math.pi * s / sides
            vs.append((math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)))
    vs.append((0.0, -1.0, 0.0))
    faces = [(0, 1 + (s + 1) % sides, 1 + s) for s in range(sides)]
    for r in range(rings - 2):
        for s in range(sides):
            a, b = 1 + r * sides + s, 1 + r * sides + (s + 1) % sides
            faces += [(a, b, b + sides), (a, b + sides, a + sides)]
    last = len(vs) - 1
    for s in range(sides):
        faces.append((1 + (rings - 2) * sides + s, 1 + (rings - 2) * sides + (s + 1) % sides, last))
    base = len(vs)
    vs += [(1.8 + 0.5 * x, -0.5 + 0.5 * y, 0.5 * z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    for q in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
        q = [base + i for i in q]
        faces += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    lines = []
    for i, v in enumerate(vs):
        line = "v %r %r %r" % tuple(f32(c) for c in v)
        if colours:  # colours a uchar can hold exactly, as PLY stores them
            line += " %r %r %r" % ((i * 37 % 256) / 255.0, (i * 91 % 256) / 255.0, (i * 53 % 256) / 255.0)
        lines.append(line)
    return lines + ["f %d %d %d" % tuple(i + 1 for i in f) for f in faces]


def run(*args, timeout=120):
    return subprocess.run([str(a) for a in args], capture_output=True, timeout=timeout)


class EveryFormatRendersAsTheObj(unittest.TestCase):
    def write(self, name, text):
        path = os.path.join(OUTPUT, name)
        with open(path, "w") as out:
            out.write(text)
        return path

    def render(self, path, *options):
        png = path + ".png"
        drawn = run(RAYTRACER, path, "-o", png, "--validate", *SIZE, *options)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        return png

    def assert_same_image(self, expected, actual):
        compared = run(IMAGE_DIFF, expected, actual, "--tolerance", "2", "--min-match", "99.9")
        print("model formats: %s against %s: %s" % (os.path.basename(actual), os.path.basename(expected),
                                                    compared.stdout.decode().strip()))
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)

    def convert(self, source, name, *options):
        path = os.path.join(OUTPUT, name)
        converted = run(sys.executable, CONVERT, source, path, *options)
        self.assertEqual(converted.returncode, 0, converted.stderr)
        return path

    def test_plain_model(self):
        plain = self.write("plain.obj", "\n".join(model_lines(False)) + "\n")
        self.write("shiny.mtl", MTL)
        shiny = self.write("shiny.obj", "mtllib shiny.mtl\nusemtl shiny\n" + "\n".join(model_lines(False)) + "\n")
        plain_png, shiny_png = self.render(plain), self.render(shiny)
        for name, options in (("ascii.ply", ["--ascii"]), ("little.ply", []), ("big.ply", ["--big-endian"]),
                              ("ascii.stl", ["--ascii"]), ("binary.stl", [])):
            with self.subTest(format=name):
                self.assert_same_image(plain_png, self.render(self.convert(plain, name, *options)))
        # A binary STL whose 80-byte header starts with "solid" and names a facet, as some
        # CAD exporters write it, is still binary: its size adds up.
        with open(os.path.join(OUTPUT, "binary.stl"), "rb") as source:
            data = source.read()
        solid = self.write("solid_header.stl", "")
        with open(solid, "wb") as out:
            out.write(b"solid part facet normal".ljust(80, b" ") + data[80:])
        self.assert_same_image(plain_png, self.render(solid))
        for name in ("model.gltf", "model.glb"):
            with self.subTest(format=name):
                self.assert_same_image(shiny_png, self.render(self.convert(plain, name, *GLTF_MATERIAL)))
        # A PLY model behind an .obj name is read by its first bytes.
        with open(os.path.join(OUTPUT, "little.ply"), "rb") as source:
            misnamed = os.path.join(OUTPUT, "misnamed_ply.obj")
            with open(misnamed, "wb") as out:
                out.write(source.read())
        self.assert_same_image(plain_png, self.render(misnamed))
        # The CPU reference reads the GLB by the same rules and agrees.
        reference = os.path.join(OUTPUT, "model.glb.reference.png")
        drawn = run(REFERENCE, os.path.join(OUTPUT, "model.glb"), "-o", reference, *SIZE, timeout=300)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        self.assert_same_image(reference, os.path.join(OUTPUT, "model.glb.png"))

    def test_vertex_colours(self):
        coloured = self.write("coloured.obj", "\n".join(model_lines(True)) + "\n")
        self.write("coloured_shiny.mtl", MTL)
        shiny = self.write("coloured_shiny.obj",
                           "mtllib coloured_shiny.mtl\nusemtl shiny\n" + "\n".join(model_lines(True)) + "\n")
        coloured_png, shiny_png = self.render(coloured), self.render(shiny)
        for name, options in (("coloured_ascii.ply", ["--ascii"]), ("coloured.ply", [])):
            with self.subTest(format=name):
                self.assert_same_image(coloured_png, self.render(self.convert(coloured, name, *options)))
        self.assert_same_image(shiny_png, self.render(self.convert(coloured, "coloured.glb", *GLTF_MATERIAL)))

    def test_ascii_lines_with_more_values_than_declared(self):
        # Some exporters write more values on a line than the header declares: an element
        # is a line, the extra values are ignored, and one warning counts the lines.
        plain = self.write("extra.obj", "\n".join(model_lines(False)) + "\n")
        ascii_ply = self.convert(plain, "extra_plain.ply", "--ascii")
        with open(ascii_ply) as source:
            head, body = source.read().split("end_header\n")
        lines = body.splitlines()
        extra = self.write("extra.ply", head + "end_header\n" + "\n".join(
            line + (" 9 1 1" if line.startswith("3 ") else "") for line in lines) + "\n")
        drawn = run(RAYTRACER, extra, "-o", extra + ".png", *SIZE)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        first = 1 + head.count("\n") + 1 + sum(1 for line in lines if not line.startswith("3 "))
        self.assertIn("%s:%d: warning: 180 line(s) hold more values than the header's properties; the extra "
                      "values are ignored" % (extra, first), drawn.stderr.decode())
        self.assert_same_image(self.render(ascii_ply), extra + ".png")

    def test_triangle_strips(self):
        # A PLY strip of 8 vertices, restarted once (-1), with a join's degenerate triangle:
        # the triangles alternate their winding as strips do, and render as the OBJ's faces.
        vertices = [(x * 0.5, y * 0.5, (x % 2) * 0.1) for x in range(4) for y in (0, 1)]
        header = ("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                  "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                  % len(vertices))
        strip = [0, 1, 2, 3, 3, -1, 4, 5, 6, 7]
        ply = self.write("strips.ply", header + "".join("%r %r %r\n" % v for v in vertices)
                         + "%d %s\n" % (len(strip), " ".join(str(i) for i in strip)))
        faces = [(0, 1, 2), (2, 1, 3), (4, 5, 6), (6, 5, 7)]
        obj = self.write("strips.obj", "".join("v %r %r %r\n" % v for v in vertices)
                         + "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in faces))
        checked = run(RAYTRACER, ply, "--check", "--no-ground")
        self.assertIn(b"\ntriangles: 4\n", checked.stdout)
        self.assert_same_image(self.render(obj), self.render(ply))


class BadFilesAreRefusedByName(unittest.TestCase):
    def test_bad_files(self):
        folder = os.path.join(OUTPUT, "bad")
        os.makedirs(folder, exist_ok=True)
        source = os.path.join(folder, "model.obj")
        with open(source, "w") as out:
            out.write("\n".join(model_lines(False)) + "\n")
        good = {}
        for name in ("model.ply", "ascii.ply", "model.glb", "model.gltf", "ascii.stl", "model.stl"):
            path = os.path.join(folder, name)
            options = ["--ascii"] if name.startswith("ascii") else []
            self.assertEqual(run(sys.executable, CONVERT, source, path, *options).returncode, 0)
            with open(path, "rb") as handle:
                good[name] = handle.read()
        bad = {}
        bad["cut.ply"] = (good["model.ply"][:2000], ": error: the file is cut short in face 51 of 180 (its list claims 3 values)")
        bad["cut_ascii.ply"] = (good["ascii.ply"][:len(good["ascii.ply"]) // 2],
                                ":72: error: the file is cut short in vertex 62 of 94")
        bad["huge.ply"] = (good["model.ply"].replace(b"element face 180", b"element face 2147483648"),
                           ": error: the PLY header claims 2147483648 face element(s), more than the ")
        glb = bytearray(good["model.glb"])
        glb[12:16] = struct.pack("<I", 99999999)
        bad["chunk.glb"] = (bytes(glb), ": error: the GLB chunk at byte 12 claims 99999999 bytes; ")
        bad["missing.gltf"] = (good["model.gltf"].replace(b'"model.bin"', b'"gone.bin"'),
                               ": error: cannot read the model: GLTF: could not open referenced file \"gone.bin\"")
        bad["device.gltf"] = (good["model.gltf"].replace(b'"model.bin"', b'"/dev/zero"'),
                              ": error: cannot read the model: GLTF: could not open referenced file \"/dev/zero\"")
        bad["cut_ascii.stl"] = (good["ascii.stl"][:1000], ":23: error: the file is cut short inside this facet")
        bad["cut.stl"] = (good["model.stl"][:-7], ": error: a binary STL file holds 84 bytes and 50 a triangle: this one's "
                          "header claims 180 triangle(s), and it has 9077 bytes")
        bad["word.stl"] = (good["ascii.stl"].replace(b"vertex 0.0", b"vertex zero", 1),
                           ":4: error: vertex expects 3 finite numbers, got 'zero'")
        bad["index.ply"] = (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            b"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                            b"end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                            ":13: error: the index 7 of face 1 of 1 names no vertex (there are 3)")
        for name, (data, message) in bad.items():
            with open(os.path.join(folder, name), "wb") as out:
                out.write(data)
        zero = os.path.join(folder, "zero.ply")
        if os.path.lexists(zero):
            os.remove(zero)
        os.symlink("/dev/zero", zero)
        bad["zero.ply"] = (None, ": error: a device, not a file: it would be read without end")
        for name, (_data, message) in bad.items():
            with self.subTest(file=name):
                path = os.path.join(folder, name)
                refused = run(RAYTRACER, path, "--check", timeout=60)
                self.assertEqual(refused.returncode, 3, refused.stderr)
                self.assertTrue(refused.stderr.decode().startswith(path + message), refused.stderr)


if __name__ == "__main__":
    if None in (RAYTRACER, CONVERT, REFERENCE, IMAGE_DIFF, OUTPUT):
        sys.exit(__doc__)
    os.makedirs(OUTPUT, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
