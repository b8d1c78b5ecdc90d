#!/usr/bin/env python3
"""Textured models render as the CPU reference samples them, and bad textures are one warning.

    textures_test.py RAYTRACER REFERENCE IMAGE_DIFF CONVERT_MODEL OUTPUT_DIR

A quad seen face on (--view front) carries a 64x64 texture of four coloured quarters: each
quarter of the quad shows its quarter's colour where the texture's layout puts it (v up, the
image's top row at the top). The same quad with a checkerboard of 8x8 texels, and a UV
sphere with a texture that wraps around it (u from 0 to 1, seam shared), each match the
reference's image (99.9% of pixels within 2/255). The checkerboard as BMP and TGA renders
the PNG's image byte for byte. The checkerboard quad as glTF (the PNG beside it) and as GLB
(the PNG inside it), written by tools/convert_model.py (CONVERT_MODEL), renders as its OBJ. A texture that is missing, cut short, a device, or whose PNG
header claims 100000x100000 pixels, is one warning naming it, and the model renders as
without the texture (byte for byte); so does a model without texture coordinates.
"""
import math
import os
import struct
import subprocess
import sys
import unittest
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "lib"))
from png_read import read_png  # noqa: E402
from png_write import png_bytes  # noqa: E402

RAYTRACER, REFERENCE, IMAGE_DIFF, CONVERT, OUTPUT = sys.argv[1:6] if len(sys.argv) >= 6 else (None,) * 5
SIZE = ["--width", "160", "--height", "120"]
QUAD = ("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
        "f 1/1/1 2/2/1 3/3/1 4/4/1\n")
RED, GREEN, BLUE, WHITE = (230, 20, 20), (20, 230, 20), (20, 20, 230), (240, 240, 240)


def run(*args, timeout=120):
    return subprocess.run([str(a) for a in args], capture_output=True, timeout=timeout)


def quarters(size):
    """Rows of a texture: top left red, top right green, bottom left blue, bottom right white."""
    half = size // 2
    return [[(RED if x < half else GREEN) if y < half else (BLUE if x < half else WHITE) for x in range(size)]
            for y in range(size)]


def checkerboard(size, check):
    return [[(200, 60, 30) if (x // check + y // check) % 2 else (30, 90, 200) for x in range(size)]
            for y in range(size)]


def bmp_bytes(rows):
    """A 24-bit BMP of rows (top first), stored bottom-up as BMP has it."""
    width, height = len(rows[0]), len(rows)
    stride = (3 * width + 3) // 4 * 4
    pixels = b"".join(bytes(c for r, g, b in row for c in (b, g, r)).ljust(stride, b"\0") for row in reversed(rows))
    header = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    return b"BM" + struct.pack("<IHHI", 14 + len(header) + len(pixels), 0, 0, 14 + len(header)) + header + pixels


def tga_bytes(rows):
    """An uncompressed 24-bit TGA of rows, top row first (descriptor bit 5)."""
    width, height = len(rows[0]), len(rows)
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, width, height, 24, 0x20)
    return header + b"".join(bytes(c for r, g, b in row for c in (b, g, r)) for row in rows)


def uv_sphere(rings, sides):
    """OBJ lines of a unit sphere with texture coordinates: u round it, v up it."""
    lines = []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(sides + 1):  # the seam's column twice, at u = 0 and u = 1
            phi = 2 * math.pi * s / sides
            lines.append("v %r %r %r" % (math.sin(theta) * math.cos(phi), math.cos(theta),
                                         -math.sin(theta) * math.sin(phi)))
            lines.append("vt %r %r" % (s / sides, 1 - r / rings))
    for r in range(rings):
        for s in range(sides):
            a, b = r * (sides + 1) + s + 1, (r + 1) * (sides + 1) + s + 1
            if r < rings - 1:  # the last ring's (a, b, b + 1) has b and b + 1 at the pole
                lines.append("f %d/%d %d/%d %d/%d" % (a, a, b, b, b + 1, b + 1))
            if r > 0:  # likewise the first ring's (a, b + 1, a + 1)
                lines.append("f %d/%d %d/%d %d/%d" % (a, a, b + 1, b + 1, a + 1, a + 1))
    return "\n".join(lines) + "\n"


class TexturesRenderAsTheReferenceSamplesThem(unittest.TestCase):
    def write(self, name, data):
        path = os.path.join(OUTPUT, name)
        with open(path, "wb") as out:
            out.write(data.encode() if isinstance(data, str) else data)
        return path

    def model(self, name, texture, geometry=QUAD):
        """name.obj with one material whose map_Kd is texture (None: no map_Kd)."""
        self.write(name + ".mtl", "newmtl skin\nKd 0.3 0.3 0.3\nKs 0.1 0.1 0.1\nNs 20\nillum 2\n" +
                   ("map_Kd %s\n" % texture if texture else ""))
        return self.write(name + ".obj", "mtllib %s.mtl\nusemtl skin\n" % name + geometry)

    def render(self, path, *options, warnings=0):
        png = path + (".%s.png" % "_".join(o.strip("-") for o in options) if options else ".png")
        drawn = run(RAYTRACER, path, "-o", png, "--validate", *SIZE, *options)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        said = [line for line in drawn.stderr.decode().splitlines() if "warning" in line]
        self.assertEqual(len(said), warnings, drawn.stderr)
        self.said = said
        return png

    def assert_matches_reference(self, path):
        gpu = self.render(path)
        reference = path + ".reference.png"
        drawn = run(REFERENCE, path, "-o", reference, *SIZE, timeout=300)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        compared = run(IMAGE_DIFF, reference, gpu, "--tolerance", "2", "--min-match", "99.9")
        print("textures: %s against the reference: %s" % (os.path.basename(path), compared.stdout.decode().strip()))
        self.assertEqual(compared.returncode, 0, compared.stdout + compared.stderr)

    def assert_same_bytes(self, expected, actual):
        self.assertEqual(read_png(expected), read_png(actual), "%s differs from %s" % (actual, expected))

    def test_quarters_land_where_the_layout_puts_them(self):
        self.write("quarters.png", png_bytes(64, 64, quarters(64)))
        png = self.render(self.model("quarters", "quarters.png"), "--view", "front", "--no-ground")
        width, height, rows = read_png(png)
        # The quad fills most of the frame, centred: sample each quarter half way to its corner.
        for (fx, fy), colour in (((0.4, 0.4), RED), ((0.6, 0.4), GREEN), ((0.4, 0.6), BLUE), ((0.6, 0.6), WHITE)):
            pixel = rows[int(fy * height)][int(fx * width)]
            strongest = max(range(3), key=lambda c: pixel[c])
            with self.subTest(colour=colour):
                if colour == WHITE:
                    self.assertLess(max(pixel) - min(pixel), 30, pixel)
                else:
                    self.assertEqual(strongest, colour.index(max(colour)), pixel)
                    self.assertGreater(pixel[strongest], 2 * sorted(pixel)[1], pixel)

    def test_checkerboard_and_sphere_match_the_reference(self):
        self.write("checker.png", png_bytes(64, 64, checkerboard(64, 8)))
        self.assert_matches_reference(self.model("checker", "checker.png"))
        check = run(RAYTRACER, os.path.join(OUTPUT, "checker.obj"), "--check")
        self.assertIn(b"\ntextures: 1 (16384 bytes of texels)\n", check.stdout)
        # --save-scene cannot write the texture: the material keeps its Kd there, as the
        # untextured model's does.
        scenes = []
        for name in ("checker", "plain_checker"):
            if name == "plain_checker":
                self.model(name, None)
            saved = run(RAYTRACER, os.path.join(OUTPUT, name + ".obj"), "--save-scene",
                        os.path.join(OUTPUT, name + ".scene"))
            self.assertEqual(saved.returncode, 0, saved.stderr)
            with open(os.path.join(OUTPUT, name + ".scene")) as text:
                scenes.append(text.read())
        self.assertEqual(scenes[0], scenes[1])
        self.write("globe.png", png_bytes(32, 16, checkerboard(32, 4)[:16]))
        self.assert_matches_reference(self.model("globe", "globe.png", uv_sphere(12, 24)))

    def test_bmp_and_tga_render_as_the_png(self):
        rows = checkerboard(16, 4)
        self.write("small.png", png_bytes(16, 16, rows))
        self.write("small.bmp", bmp_bytes(rows))
        self.write("small.tga", tga_bytes(rows))
        expected = self.render(self.model("small_png", "small.png"))
        for kind in ("bmp", "tga"):
            with self.subTest(format=kind):
                self.assert_same_bytes(expected, self.render(self.model("small_" + kind, "small." + kind)))

    def test_gltf_and_glb_render_as_the_obj(self):
        # Without normals (the crease rule gives each format the same), no highlight: the
        # glTF material of base colour 1, metallic 0 and roughness 1 maps onto this MTL.
        self.write("tiles.png", png_bytes(32, 32, checkerboard(32, 4)))
        self.write("tiles.mtl", "newmtl skin\nKd 0.3 0.3 0.3\nKs 0 0 0\nillum 1\nmap_Kd tiles.png\n")
        quad = QUAD.replace("vn 0 0 1\n", "").replace("/1 ", " ").replace("/1\n", "\n")
        obj = self.write("tiles.obj", "mtllib tiles.mtl\nusemtl skin\n" + quad)
        expected = self.render(obj)
        for name in ("tiles_gltf.gltf", "tiles_glb.glb"):
            with self.subTest(format=name):
                path = os.path.join(OUTPUT, name)
                converted = run(sys.executable, CONVERT, obj, path, "--texture", os.path.join(OUTPUT, "tiles.png"))
                self.assertEqual(converted.returncode, 0, converted.stderr)
                self.assert_same_bytes(expected, self.render(path))

    def test_unreadable_textures_are_one_warning_each(self):
        untextured = self.render(self.model("plain", None))
        whole = png_bytes(16, 16, checkerboard(16, 4))
        ihdr = struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0)
        huge = (b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" + ihdr +
                struct.pack(">I", zlib.crc32(b"IHDR" + ihdr)) + whole[33:])
        self.write("cut.png", whole[:len(whole) // 2])
        self.write("huge.png", huge)
        os.makedirs(os.path.join(OUTPUT, "folder.png"), exist_ok=True)
        cases = {"missing.png": "cannot open file", "cut.png": "not a readable PNG, JPEG, BMP or TGA image",
                 "huge.png": "the image is 100000x100000, over 16384 pixels a side",
                 "/dev/zero": "a device, not a file", "folder.png": "cannot"}
        for texture, reason in cases.items():
            with self.subTest(texture=texture):
                name = "bad_" + os.path.basename(texture).replace(".", "_")
                png = self.render(self.model(name, texture), warnings=1)
                self.assertIn("warning: texture not read: ", self.said[0])
                self.assertIn(texture, self.said[0])
                self.assertIn(reason, self.said[0])
                self.assertTrue(self.said[0].endswith("1 material keeps its colour"), self.said[0])
                self.assert_same_bytes(untextured, png)

    def test_a_model_without_texture_coordinates_keeps_its_colours(self):
        self.write("unused.png", png_bytes(4, 4, checkerboard(4, 1)))
        flat = QUAD.replace("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n", "").replace("/1/", "//").replace(
            "/2/", "//").replace("/3/", "//").replace("/4/", "//")
        without = self.model("flat_plain", None, flat)
        png = self.render(self.model("flat", "unused.png", flat), warnings=1)
        self.assertIn("no texture coordinates (vt)", self.said[0])
        self.assert_same_bytes(self.render(without), png)


if __name__ == "__main__":
    if None in (RAYTRACER, REFERENCE, IMAGE_DIFF, CONVERT, OUTPUT):
        sys.exit(__doc__)
    os.makedirs(OUTPUT, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
