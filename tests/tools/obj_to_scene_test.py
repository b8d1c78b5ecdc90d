#!/usr/bin/env python3
"""tools/obj_to_scene.py: OBJ files written here are converted, and Raytracer loads and
renders what comes out.

    obj_to_scene_test.py RAYTRACER TOOL OUTPUT_DIR
"""

import json
import math
import os
import shutil
import subprocess
import sys
import unittest

RAYTRACER, TOOL, OUTPUT = sys.argv[1:4] if len(sys.argv) >= 4 else (None, None, None)

# A unit cube of quads, no normals; the last face (+z) uses negative indices.
CUBE = """# cube
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


def read(path, mode="r"):
    with open(path, mode) as handle:
        return handle.read()


def convert(obj_text, name, *options, mtl=None):
    """Writes NAME.obj (and mats.mtl beside it), runs the tool; returns (process, scene path)."""
    folder = os.path.join(OUTPUT, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    obj = os.path.join(folder, name + ".obj")
    with open(obj, "w") as handle:
        handle.write(obj_text)
    if mtl is not None:
        with open(os.path.join(folder, "mats.mtl"), "w") as handle:
            handle.write(mtl)
    scene = os.path.join(folder, name + ".scene")
    run = subprocess.run([sys.executable, TOOL, obj, "-o", scene, *options], capture_output=True, text=True,
                         timeout=60)
    return run, scene


def triangles_of(scene):
    """[3 corners {pos, nor, dif, spe, shi, mir}] from a scene the tool wrote: one key and
    its numbers a line, mir (1 when absent) the only optional key."""
    with open(scene) as handle:
        lines = handle.read().split("\n")
    result = []
    for line in lines[2:]:
        fields = line.split()
        if not fields or fields[0] == "light":
            result.append(None) if fields else None
            continue
        if fields[0] == "triangle":
            result.append([])
        elif result and result[-1] is not None:
            key, numbers = fields[0][:-1], tuple(float(t) for t in fields[1:])
            if key == "pos":
                result[-1].append({"mir": 1.0})
            result[-1][-1][key] = numbers[0] if len(numbers) == 1 else numbers
    return [corners for corners in result if corners is not None]


def render(scene):
    """Raytracer's --bench JSON for the scene (a small render, validation on)."""
    run = subprocess.run([RAYTRACER, scene, "--bench", "1", "--width", "64", "--height", "48", "--validate"],
                         capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        raise AssertionError("Raytracer failed (%d):\n%s" % (run.returncode, run.stderr))
    return json.loads(run.stdout.strip().splitlines()[-1])


class ObjToScene(unittest.TestCase):
    def test_cube_of_quads_with_negative_indices_renders(self):
        run, scene = convert(CUBE, "cube", "--fit")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("12 triangles", run.stderr)
        self.assertEqual(len(triangles_of(scene)), 12)
        self.assertEqual(render(scene)["triangles"], 12)
        # The picture too: exit 0 and a PNG.
        png = scene[:-len(".scene")] + ".png"
        drawn = subprocess.run([RAYTRACER, scene, "-o", png, "--width", "64", "--height", "48"],
                               capture_output=True, text=True, timeout=300)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        self.assertTrue(read(png, "rb")[:8] == b"\x89PNG\r\n\x1a\n")

    def test_missing_normals_are_smooth_area_weighted_and_outward(self):
        _run, scene = convert(CUBE, "cube_normals", "--crease", "180")
        for triangle in triangles_of(scene):
            for corner in triangle:
                # Each corner of a cube touches three faces of equal area: the average
                # normal points along the diagonal, away from the centre.
                expected = tuple(c / math.sqrt(3.0) for c in corner["pos"])
                for got, want in zip(corner["nor"], expected):
                    self.assertAlmostEqual(got, want, places=6)

    def test_fit_puts_the_model_ahead_filling_the_share_of_the_view(self):
        # The cube made 5 units wide along x only, and moved far off.
        box = "".join("v %g %g %g\n" % (10 + 2.5 * x, -4 + y, 7 + z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1))
        run, scene = convert(box + "f 1 2 4 3\nf 5 6 8 7\nf 1 3 7 5\n", "cube_fit", "--fit", "--view", "front")
        self.assertEqual(run.returncode, 0, run.stderr)
        positions = [c["pos"] for t in triangles_of(scene) for c in t]
        for axis in (0, 1):
            low, high = min(p[axis] for p in positions), max(p[axis] for p in positions)
            self.assertAlmostEqual((low + high) / 2, 0.0, places=5)
        self.assertAlmostEqual(max(max(p[a] for p in positions) - min(p[a] for p in positions) for a in range(3)),
                               1.5, places=5)
        # The outermost corner, seen from the origin, lies 80% of the way to the edge of a
        # 60-degree, 4:3 view (here the width limits: the box is wide).
        share = max(max(abs(p[1]) / (-p[2] * math.tan(math.radians(30))),
                        abs(p[0]) / (-p[2] * math.tan(math.radians(30)) * 4 / 3)) for p in positions)
        self.assertAlmostEqual(share, 0.8, places=6)

    def test_corner_forms_given_normals_and_fan_triangulation(self):
        obj = ("v 0 0 -3\nv 1 0 -3\nv 1.5 1 -3\nv 0.5 1.5 -3\nv -0.5 1 -3\nvt 0 0\nvn 0 0 2\n"
               "f 1/1/1 2/1/1 3//1 4//-1 5/1/1\n")
        run, scene = convert(obj, "pentagon")
        self.assertEqual(run.returncode, 0, run.stderr)
        triangles = triangles_of(scene)
        self.assertEqual(len(triangles), 3)  # a pentagon: a fan of three
        self.assertEqual([c["pos"] for c in triangles[1]], [(0, 0, -3), (1.5, 1, -3), (0.5, 1.5, -3)])
        self.assertTrue(all(c["nor"] == (0, 0, 2) for t in triangles for c in t))  # as given
        render(scene)

    def test_materials_from_mtl_are_clamped(self):
        mtl = "newmtl shiny\nKd 0.8 0.1 1.7\nKs 0.25\nNs 5000\nnewmtl plain\nKd 0.2 0.3 0.4\n"
        obj = ("mtllib mats.mtl\nv 0 0 -3\nv 1 0 -3\nv 0 1 -3\nusemtl shiny\nf 1 2 3\nusemtl plain\nf 1 3 2\n"
               "usemtl nosuch\nf 2 3 1\n")
        run, scene = convert(obj, "materials", mtl=mtl)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("materials.obj:9: warning: unknown material 'nosuch'", run.stderr)
        shiny, plain, default = (t[0] for t in triangles_of(scene))
        self.assertEqual((shiny["dif"], shiny["spe"], shiny["shi"]), ((0.8, 0.1, 1.0), (0.25, 0.25, 0.25), 1000.0))
        self.assertEqual(plain["dif"], (0.2, 0.3, 0.4))
        self.assertEqual(default["dif"], (0.75, 0.75, 0.75))
        self.assertEqual((default["spe"], default["mir"]), ((0.1, 0.1, 0.1), 0.0))  # no mirror
        render(scene)

        run, scene = convert(obj, "no_library")  # mats.mtl is not there
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("no_library.obj:1: warning: material library", run.stderr)

    def test_illum_says_what_ks_is_and_ns_below_1_is_1(self):
        materials = ("matte 0", "diffuse 1", "glossy 2", "mirror 3", "glass 7", "unsaid")
        mtl = "".join("newmtl %s\nKs 0.6\nNs 0\n%s" % (name.split()[0], "illum %s\n" % name.split()[1]
                                                       if " " in name else "") for name in materials)
        mtl += "newmtl late\nillum 3\nKs 0.4\nnewmtl odd\nillum 2.5\n"  # Ks after illum; a wrong illum
        names = [m.split()[0] for m in materials] + ["late", "odd"]
        obj = "mtllib mats.mtl\nv 0 0 -3\nv 1 0 -3\nv 0 1 -3\n" + "".join(
            "usemtl %s\nf 1 2 3\n" % name for name in names)
        run, scene = convert(obj, "illum", mtl=mtl)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("mats.mtl:%d: warning: illum expects an illumination model, a whole number 0 to 10, got 2.5"
                      % (mtl.count("\n")), run.stderr)
        got = {name: (t[0]["spe"][0], t[0]["mir"], t[0]["shi"]) for name, t in zip(names, triangles_of(scene))}
        self.assertEqual(got, {"matte": (0.0, 0.0, 1.0), "diffuse": (0.0, 0.0, 1.0), "glossy": (0.6, 0.0, 1.0),
                               "mirror": (0.6, 1.0, 1.0), "glass": (0.6, 1.0, 1.0), "unsaid": (0.6, 0.0, 1.0),
                               "late": (0.4, 1.0, 30.0), "odd": (0.1, 0.0, 30.0)})
        self.assertIn("shi: 1\nmir: 0\n", read(scene))
        render(scene)

    def test_up_takes_an_axis_in_either_case_with_an_optional_sign(self):
        _run, plain = convert(CUBE, "up_z", "--up", "z")
        for written in ("Z", "+z", "+Z"):
            run, scene = convert(CUBE, "up_" + written.replace("+", "plus"), "--up", written)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(read(scene), read(plain))
        run, _scene = convert(CUBE, "up_wrong", "--up", "w")
        self.assertEqual(run.returncode, 2)
        self.assertIn("expects an axis, x, y or z in either case with an optional sign (z, Z, +z, -y), got 'w'",
                      run.stderr)

    def test_lights_and_ambient(self):
        _run, scene = convert(CUBE, "lights", "--light", "1,2,3", "--light", "-1,5,0", "--ambient", "0.2,0.3,0.4")
        text = read(scene)
        self.assertTrue(text.startswith("14\namb: 0.2 0.3 0.4\n"), text[:40])
        self.assertIn("light\npos: 1 2 3\ncol: 1 1 1\n", text)
        self.assertIn("light\npos: -1 5 0\n", text)
        _run, scene = convert(CUBE, "default_light")
        self.assertIn("light\npos: 0 4 0\ncol: 1 1 1\n", read(scene))

    def test_malformed_lines_name_file_and_line(self):
        cases = {
            "v 1 2\n": ":1: error: v expects 3 to 7 numbers, got 2",
            "v 1 2 x\n": ":1: error: v: 'x' is not a number",
            "v 0 0 0\nv 1 0 0\nf 1 2\n": ":3: error: a face needs at least 3 corners, got 2",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n": ":5: error: vertex index 4 is out of range: 3",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n": ":4: error: vertex index -4 is out of range",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n": ":4: error: vertex index 0",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2 3\n": ":4: error: normal index 1 is out of range: 0",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n": ":4: error: vertex index '3x' is not a whole number",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/a 2 3\n": ":4: error: texture coordinate index 'a' is not a whole number",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n":
                ":5: error: texture coordinate index 2 is out of range: 1 texture coordinates defined so far",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0 0 0\nf 1 2 3\n": ":4: error: vt expects 1 to 3 numbers, got 4",
            "# nothing\n": ": error: no faces (f) found",
        }
        for number, (obj, message) in enumerate(cases.items()):
            with self.subTest(obj=obj):
                run, scene = convert(obj, "bad%d" % number)
                self.assertEqual(run.returncode, 1)
                self.assertIn("bad%d.obj%s" % (number, message), run.stderr)
                self.assertFalse(os.path.exists(scene))


if __name__ == "__main__":
    if None in (RAYTRACER, TOOL, OUTPUT):
        sys.exit(__doc__)
    os.makedirs(OUTPUT, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
