"""Every frame of --turntable 8 of every classic scene shows the scene's objects.

    turntable_test.py RAYTRACER SCENES_DIR OUTPUT_DIR

A frame shows the objects when enough of its pixels change without them: the scene is
rendered again without the objects that are not a floor, wall or backdrop (the primitives
no larger than a quarter of the scene's extent, the turntable's own rule for its centre;
all of them when none is that small), about the same line (the first run prints it, the
second is given its centre with --orbit-center and must print the same axis), and the
pixels that differ between the two renders are where the objects are seen, cast a shadow or
are mirrored. (Recolouring them instead would miss an object lit by no light: the model's
ambient term is not multiplied by the diffuse colour.) Each frame must have at least
MIN_SHARE of its pixels so; before the turntable orbited the centre of what the camera sees
about the floor's normal, table.scene's frame 4 showed the floor's underside alone.

A model seen from its own camera is fitted again for each frame: a plank long along x
spans the fit's share of the frame (80%) or less in every frame, and 60% or more. Kept at
frame 0's distance, it filled 89% of the frames that see its long side.
"""
import glob
import math
import os
import shutil
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "lib"))
from png_read import read_png  # noqa: E402

RAYTRACER, SCENES, OUTPUT = sys.argv[1:4] if len(sys.argv) >= 4 else (None,) * 3
FRAMES = 8
MIN_SHARE = 0.05
SIZE = ["--width", "96", "--height", "72"]

# Fields of a material, in file order; mir: is optional.
MATERIAL = ("dif:", "spe:", "shi:")


def objects(tokens):
    """[(keyword, [(key, [number tokens])])] of a scene file's tokens, after count and amb:."""
    result, i = [], 5
    while i < len(tokens):
        keyword = tokens[i].lower()
        fields, i = [], i + 1
        while i < len(tokens) and tokens[i].lower() not in ("sphere", "triangle", "light"):
            key, i = tokens[i].lower(), i + 1
            values = []
            while i < len(tokens) and not tokens[i].endswith(":") and tokens[i].lower() not in (
                    "sphere", "triangle", "light"):
                values.append(tokens[i])
                i += 1
            fields.append((key, values))
        result.append((keyword, fields))
    return result


def without_objects(text):
    """The scene text without its small primitives (all, when none is small)."""
    tokens = text.split()
    parsed = objects(tokens)
    points = []
    for keyword, fields in parsed:
        if keyword == "sphere":
            centre, radius = [float(v) for v in fields[0][1]], float(fields[1][1][0])
            points += [[c - radius for c in centre], [c + radius for c in centre]]
        elif keyword == "triangle":
            points += [[float(v) for v in values] for key, values in fields if key == "pos:"]
    low = [min(p[a] for p in points) for a in range(3)]
    high = [max(p[a] for p in points) for a in range(3)]
    large = 0.25 * math.dist(low, high)
    def small(keyword, fields):
        if keyword == "sphere":
            return 2.0 * float(fields[1][1][0]) <= large
        if keyword == "triangle":
            corners = [[float(v) for v in values] for key, values in fields if key == "pos:"]
            return max(math.dist(corners[a], corners[(a + 1) % 3]) for a in range(3)) <= large
        return False
    objects_there = [small(keyword, fields) for keyword, fields in parsed]
    if not any(objects_there):
        objects_there = [keyword != "light" for keyword, _fields in parsed]
    kept = [(keyword, fields) for (keyword, fields), gone in zip(parsed, objects_there) if not gone]
    out = [str(len(kept))] + tokens[1:5]
    for keyword, fields in kept:
        out.append(keyword)
        for key, values in fields:
            out += [key] + values
    return "\n".join(out) + "\n"


def orbit(stderr):
    """(centre, axis) texts of the turntable's line as Raytracer prints it."""
    for line in stderr.decode().splitlines():
        if line.startswith("Turntable: "):
            words = line.split()
            return words[-3], words[-1]
    raise AssertionError("no Turntable: line in " + stderr.decode())


class EveryFrameShowsTheObjects(unittest.TestCase):
    def test_every_classic_scene(self):
        scenes = sorted(glob.glob(os.path.join(SCENES, "*.scene")))
        self.assertGreater(len(scenes), 5)
        for scene in scenes:
            name = os.path.basename(scene)[:-len(".scene")]
            with self.subTest(scene=name):
                folder = os.path.join(OUTPUT, name)
                shutil.rmtree(folder, ignore_errors=True)
                os.makedirs(folder)
                bare = os.path.join(folder, "bare.scene")
                with open(scene) as source, open(bare, "w") as copy:
                    copy.write(without_objects(source.read()))
                lines = []
                for source, prefix, centre in ((scene, "plain", []), (bare, "bare", None)):
                    if centre is None:
                        centre = ["--orbit-center", lines[0][0]]
                    drawn = subprocess.run([RAYTRACER, source, "--turntable", str(FRAMES), "-o",
                                            os.path.join(folder, prefix + "-{frame}.png"), *centre, *SIZE],
                                           capture_output=True, timeout=300)
                    self.assertEqual(drawn.returncode, 0, drawn.stderr)
                    lines.append(orbit(drawn.stderr))
                self.assertEqual(lines[0], lines[1])
                shares = []
                for frame in range(FRAMES):
                    width, height, a = read_png(os.path.join(folder, "plain-%d.png" % frame))
                    _w, _h, b = read_png(os.path.join(folder, "bare-%d.png" % frame))
                    changed = sum(1 for y in range(height) for x in range(width) if a[y][x] != b[y][x])
                    shares.append(changed / (width * height))
                print("turntable: %s: objects in %s of each frame" % (
                    name, ", ".join("%.0f%%" % (100 * s) for s in shares)))
                self.assertGreaterEqual(min(shares), MIN_SHARE, shares)


# A fitted frame's silhouette spans FIT_SHARE of the frame's width or height at most (a
# pixel's rounding either side allowed for), and MIN_FIT at least.
FIT_SHARE, MIN_FIT = 0.80, 0.60


def silhouette_span(png):
    """The larger of the non-white pixels' width and height as shares of the frame's."""
    width, height, rows = read_png(png)
    seen = [(x, y) for y in range(height) for x in range(width) if rows[y][x] != (255, 255, 255)]
    xs, ys = [x for x, _y in seen], [y for _x, y in seen]
    return max((max(xs) - min(xs) + 1) / width, (max(ys) - min(ys) + 1) / height)


class EveryFrameFitsTheModel(unittest.TestCase):
    def test_a_plank_fills_each_frame(self):
        folder = os.path.join(OUTPUT, "plank")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        model = os.path.join(folder, "plank.obj")
        with open(model, "w") as out:
            for x in (-4, 4):
                for y in (-0.1, 0.1):
                    for z in (-1, 1):
                        out.write("v %r %r %r\n" % (x, y, z))
            for face in ((1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)):
                out.write("f %d %d %d %d\n" % face)
        size = ["--width", "160", "--height", "120", "--no-ground"]
        frames = os.path.join(folder, "frame-{frame}.png")
        drawn = subprocess.run([RAYTRACER, model, "--turntable", str(FRAMES), "-o", frames, *size],
                               capture_output=True, timeout=300)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        single = os.path.join(folder, "single.png")
        self.assertEqual(subprocess.run([RAYTRACER, model, "-o", single, *size], capture_output=True,
                                        timeout=300).returncode, 0)
        with open(single, "rb") as a, open(frames.format(frame=0), "rb") as b:
            self.assertEqual(a.read(), b.read())  # frame 0 is the default view, bit for bit
        spans = [silhouette_span(frames.format(frame=k)) for k in range(FRAMES)]
        print("turntable: plank: silhouette spans %s" % ", ".join("%.2f" % s for s in spans))
        for span in spans:
            self.assertGreaterEqual(span, MIN_FIT, spans)
            self.assertLessEqual(span, FIT_SHARE + 1.0 / 120, spans)


if __name__ == "__main__":
    if None in (RAYTRACER, SCENES, OUTPUT):
        sys.exit(__doc__)
    os.makedirs(OUTPUT, exist_ok=True)
    unittest.main(argv=[sys.argv[0], "-v"])
