#!/usr/bin/env python3
"""--pixel X,Y (docs/pixel_story.md): the GPU kernel's story of a pixel against the CPU
reference's, and against the PNG rendered with it.

For pixels of a classic scene with mirrors, a project scene and stress scenes: the hit sequence
(kinds, file indices, source lines) and the lights' results equal the reference's, t, normals,
materials and colours agree within the stated tolerance (tools/lib/pixel_story_compare.py), the
final 8-bit colour is the PNG's pixel, and every line named is where that object's keyword
stands in the file (read here, not by the renderers' parser). Also: --spp 4 (sample 0's tree,
the pixel's average), 1000 samples (the story's pixel the image's float, however the
samples were split), --pixel without -o (the story alone, no file written), and bad --pixel
values (exit 2 with a message naming --pixel, in both programs).

usage: pixel_story_test.py RAYTRACER REFERENCE_RENDER SOURCE_DIR SHARED_SCENES OUT_DIR
"""
import json
import pathlib
import struct
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
SOURCE = pathlib.Path(sys.argv[3]).resolve() if len(sys.argv) > 3 else None
if SOURCE:
    sys.path.insert(0, str(SOURCE / "tools" / "lib"))
import pixel_story_compare as compare  # noqa: E402

SIZE = ["--width", "64", "--height", "48"]
PIXELS = ["8,8", "32,24", "20,30", "44,30", "50,40", "10,40"]
failures = []


def fail(message):
    print("FAIL: " + message)
    failures.append(message)


def run(command, cwd=None):
    return subprocess.run([str(c) for c in command], capture_output=True, text=True, timeout=300,
                          cwd=cwd)


def check_lines(story, scene, where):
    """Each named object's line is where its keyword stands: the index-th of its kind."""
    lines = compare.object_lines(scene)

    def named(record, what):
        kind = record.get("kind")
        if kind not in ("sphere", "triangle"):
            return kind
        index, line = record.get("index"), record.get("line")
        if not (isinstance(index, int) and 0 <= index < len(lines[kind])):
            fail(f"{where}: {what} names {kind} {index}, which {scene} does not hold")
        elif lines[kind][index] != line:
            fail(f"{where}: {what} says {kind} {index} begins on line {line}; the file has it on "
                 f"line {lines[kind][index]}")
        return kind

    kinds = set()
    for k, bounce in enumerate(story["bounces"]):
        kinds.add(named(bounce["hit"], f"bounce {k}'s hit"))
        for light in bounce.get("lights", []):
            if lines["light"][light["light"]] != light["line"]:
                fail(f"{where}: light {light['light']} said to begin on line {light['line']}")
            if light["result"] == "blocked":
                named(light["blocker"], f"bounce {k}'s light {light['light']} blocker")
    return kinds


def check_pixel(scene, pixel, out, seen, extra=(), tolerance=compare.TOLERANCE, spp=None):
    where = f"{pathlib.Path(scene).name} pixel {pixel}" + (f" {' '.join(extra)}" if extra else "")
    png = out / f"{pathlib.Path(scene).stem}-{pixel.replace(',', '_')}.png"
    shared = SIZE + (["--spp", spp] if spp else [])
    gpu_run = run([RAYTRACER, scene, "-o", png, "--pixel", pixel, "--validate", *shared,
                   *(["--sampler", "grid"] if spp else []), *extra])
    ref_run = run([REFERENCE, scene, "--pixel", pixel, *shared])
    if gpu_run.returncode != 0 or ref_run.returncode != 0:
        fail(f"{where}: Raytracer exit {gpu_run.returncode}, reference exit {ref_run.returncode}: "
             f"{gpu_run.stderr[-400:]} {ref_run.stderr[-400:]}")
        return
    gpu = compare.load(gpu_run.stdout, "Raytracer")
    reference = compare.load(ref_run.stdout, "reference_render")
    compare.TOLERANCE = tolerance
    first = compare.first_difference(gpu, reference)
    compare.TOLERANCE = 0.001
    if first is not None:
        fail(f"{where}: the stories part at {first}:\n{compare.side_by_side(gpu, reference)}")
    x, y = (int(v) for v in pixel.split(","))
    if compare.png_pixel(png, x, y) != gpu["pixel_8bit"]:
        fail(f"{where}: the story's final colour {gpu['pixel_8bit']} is not the PNG's pixel "
             f"{compare.png_pixel(png, x, y)}")
    seen["kinds"] |= check_lines(gpu, scene, where)
    for bounce in gpu["bounces"]:
        seen["next"].add(bounce["next"])
        seen["lights"] |= {light["result"] for light in bounce.get("lights", [])}
    seen["stories"] += 1


def check_many_lights(out, seen):
    """18 lights: the GPU lists 16 and says so; the pixel is still right."""
    lights = "".join(f"light\npos: {k - 9} {4 + k % 3} 2\ncol: 0.05 0.05 0.05\n" for k in range(18))
    scene = out / "eighteen_lights.scene"
    scene.write_text("20\namb: 0.1 0.1 0.1\n" + lights +
                     "sphere\npos: 0 0 -5\nrad: 1.5\ndif: 0.5 0.4 0.3\nspe: 0.2 0.2 0.2\nshi: 8\n"
                     "triangle\n" + "".join(f"pos: {x} -2 {z}\nnor: 0 1 0\ndif: 0.3 0.3 0.3\n"
                                             "spe: 0 0 0\nshi: 1\n"
                                             for x, z in ((-9, -1), (9, -1), (0, -20))))
    check_pixel(scene, "32,24", out, seen)
    result = run([RAYTRACER, scene, "--pixel", "32,24", *SIZE])
    story = compare.load(result.stdout, "Raytracer")
    listed = len(story["bounces"][0].get("lights", []))
    if not (story["lights"] == 18 and story["lights_recorded"] == 16 and story["lights_truncated"]
            and listed == 16):
        fail(f"18 lights: lights {story['lights']}, recorded {story['lights_recorded']}, "
             f"truncated {story['lights_truncated']}, {listed} listed (want 18, 16, true, 16)")


def check_usage_errors(scene):
    bad = ["64,0", "0,48", "5", "a,b", "-1,3", "1,2,3", "1.5,2", ",3", ""]
    for value in bad:
        for program in (RAYTRACER, REFERENCE):
            result = run([program, scene, "--pixel", value, *SIZE])
            name = pathlib.Path(program).name
            if result.returncode != 2 or "--pixel" not in result.stderr:
                fail(f"{name} --pixel '{value}': exit {result.returncode} (want 2 and a message "
                     f"naming --pixel): {result.stderr[:300]}")
            if result.stdout.strip():
                fail(f"{name} --pixel '{value}' printed on stdout: {result.stdout[:200]}")
    result = run([RAYTRACER, scene, "--pixel", "1,1", "--bench", "2", *SIZE])
    if result.returncode != 2:
        fail(f"--pixel with --bench: exit {result.returncode}, want 2")


def check_story_alone(scene):
    """Without -o: the story on stdout, no window, no file in the working directory."""
    with tempfile.TemporaryDirectory() as folder:
        result = run([RAYTRACER, scene, "--pixel", "32,24", "--validate", *SIZE], cwd=folder)
        if result.returncode != 0:
            fail(f"--pixel without -o: exit {result.returncode}: {result.stderr[-400:]}")
            return
        story = compare.load(result.stdout, "Raytracer")
        if story.get("pixel") != [32, 24] or not story.get("bounces"):
            fail(f"--pixel without -o: no story of pixel 32,24: {result.stdout[:300]}")
        left = list(pathlib.Path(folder).iterdir())
        if left:
            fail(f"--pixel without -o wrote {left}")


def check_many_samples(source):
    """At 1000 samples a pixel that looks into showcase's mirrors needs more loop iterations than
    lavapipe allows one dispatch (docs/design.md, the CPU driver's loop limit): the story's
    pixel_color must still be the float the image holds there, bit for bit."""
    scene = source / "scenes/showcase.scene"
    view = ["--width", "200", "--height", "150", "--spp", "1000", "--camera-pos", "3,4,2",
            "--camera-target", "0,0,-8", "--camera-up", "0,1,0.2"]
    with tempfile.TemporaryDirectory() as folder:
        pfm = pathlib.Path(folder) / "pixel.pfm"
        image = run([RAYTRACER, scene, "-o", pfm, "--crop", "108,105,1,1", *view])
        story_run = run([RAYTRACER, scene, "--pixel", "108,105", *view])
        if image.returncode != 0 or story_run.returncode != 0:
            fail(f"1000 samples: exit {image.returncode} and {story_run.returncode}: "
                 f"{image.stderr[-300:]} {story_run.stderr[-300:]}")
            return
        data = pfm.read_bytes()
        floats = struct.unpack("<3f", data.split(b"\n", 3)[3][:12])
        story = compare.load(story_run.stdout, "Raytracer")
        told = tuple(struct.unpack("<f", struct.pack("<f", v))[0] for v in story["pixel_color"])
        if told != floats:
            fail(f"1000 samples: the story's pixel_color {told} is not the image's {floats}")


def main():
    global RAYTRACER, REFERENCE
    if len(sys.argv) != 6:
        print(__doc__.split("usage: ")[1], file=sys.stderr)
        return 2
    RAYTRACER, REFERENCE = (pathlib.Path(p).resolve() for p in sys.argv[1:3])
    shared, out = pathlib.Path(sys.argv[4]).resolve(), pathlib.Path(sys.argv[5]).resolve()
    out.mkdir(parents=True, exist_ok=True)
    seen = {"kinds": set(), "next": set(), "lights": set(), "stories": 0}
    # Classic scenes with mirrors (test2: spheres and triangles; table: a mesh, the hierarchy).
    for scene in (shared / "test2.scene", shared / "table.scene", SOURCE / "scenes/mirrors.scene"):
        for pixel in PIXELS:
            check_pixel(scene, pixel, out, seen)
    # Stress scenes: a 1e3-wide ground and a mirror ground 1e5 wide, as rendered by default (with
    # --offset scaled the mirror's reflected rays leave far above the ground, which the story
    # shows: docs/pixel_story.md).
    for pixel in PIXELS:
        check_pixel(SOURCE / "scenes/stress/ground_e1e3.scene", pixel, out, seen)
        check_pixel(SOURCE / "scenes/stress/ground_mirror_e1e5.scene", pixel, out, seen)
    # Several samples: sample 0's tree (the grid's first cell, the reference's too) and the
    # average of all four.
    for pixel in ("20,30", "44,30"):
        check_pixel(shared / "test2.scene", pixel, out, seen, spp="4")
    check_many_lights(out, seen)
    check_many_samples(SOURCE)
    # What the pixels must have covered, or the checks above prove little.
    for what, want in (("kinds", {"sphere", "triangle", "none"}),
                       ("next", {"reflect", "miss", "no-mirror"}),
                       ("lights", {"lit", "blocked", "behind"})):
        if not want <= seen[what]:
            fail(f"the pixels never showed {sorted(want - seen[what])} ({what})")
    check_usage_errors(shared / "test2.scene")
    check_story_alone(shared / "test2.scene")
    print(f"pixel_story_test: {seen['stories']} stories compared, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
