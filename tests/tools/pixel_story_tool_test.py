#!/usr/bin/env python3
"""tools/pixel_story: GPU and reference stories side by side (docs/pixel_story.md).

The tool on a pixel where the two agree (exit 0, "the stories agree"), and where Raytracer is
given another background than the reference (exit 1, the first difference marked at that
bounce's background); then its comparison rules (tools/lib/pixel_story_compare.py) on a real
GPU story altered here: a hit index, a line, a light result, a t and a colour beyond the
tolerance, and the final 8-bit colour off by one level (allowed) and by two (not).

usage: pixel_story_tool_test.py RAYTRACER SOURCE_DIR SHARED_SCENES
"""
import copy
import json
import pathlib
import subprocess
import sys

sys.dont_write_bytecode = True
failures = []


def fail(message):
    print("FAIL: " + message)
    failures.append(message)


def main():
    if len(sys.argv) != 4:
        print(__doc__.split("usage: ")[1], file=sys.stderr)
        return 2
    raytracer = pathlib.Path(sys.argv[1]).resolve()
    source, shared = pathlib.Path(sys.argv[2]).resolve(), pathlib.Path(sys.argv[3]).resolve()
    sys.path.insert(0, str(source / "tools" / "lib"))
    import pixel_story_compare as compare

    tool = [sys.executable, str(source / "tools" / "pixel_story"), "--raytracer", str(raytracer)]
    scene = str(shared / "test2.scene")
    size = ["--width", "64", "--height", "48"]
    agree = subprocess.run(tool + [scene, "44,30"] + size, capture_output=True, text=True,
                           timeout=300)
    if agree.returncode != 0 or "the stories agree" not in agree.stdout:
        fail(f"pixel 44,30: exit {agree.returncode}, want 0 and 'the stories agree':\n"
             f"{agree.stdout}{agree.stderr}")
    for field in ("bounces[1].hit.kind", "pixel_8bit"):
        if field not in agree.stdout:
            fail(f"the side-by-side table lacks {field}:\n{agree.stdout}")
    part = subprocess.run(tool + [scene, "8,8"] + size + ["--", "--background", "0,0,0"],
                          capture_output=True, text=True, timeout=300)
    marked = [line for line in part.stdout.splitlines() if "<<< first difference" in line]
    if part.returncode != 1 or len(marked) != 1 or not marked[0].startswith("bounces[0].background"):
        fail(f"another background: exit {part.returncode}, want 1 and the first difference at "
             f"bounces[0].background:\n{part.stdout}{part.stderr}")

    story = subprocess.run(tool + [scene, "44,30", "--json"] + size, capture_output=True,
                           text=True, timeout=300)
    both = json.loads(story.stdout)
    gpu, reference = both["gpu"], both["reference"]
    if compare.first_difference(gpu, reference) is not None or both["first_difference"]:
        fail(f"the stories of 44,30 should agree: {both['first_difference']}")

    def altered(change, want):
        story = copy.deepcopy(gpu)
        change(story)
        got = compare.first_difference(story, reference)
        if got != want:
            fail(f"altered story: first difference {got}, want {want}")

    def set_in(path, value):
        def change(story):
            record = story
            for key in path[:-1]:
                record = record[key]
            record[path[-1]] = value
        return change

    hit = ["bounces", 1, "hit"]
    altered(set_in(hit + ["index"], gpu["bounces"][1]["hit"]["index"] + 1), "bounces[1].hit.index")
    altered(set_in(hit + ["line"], gpu["bounces"][1]["hit"]["line"] + 1), "bounces[1].hit.line")
    altered(set_in(hit + ["t"], gpu["bounces"][1]["hit"]["t"] * 1.01), "bounces[1].hit.t")
    altered(set_in(hit + ["t"], gpu["bounces"][1]["hit"]["t"] * 1.0001), None)
    altered(set_in(["bounces", 0, "lights", 0, "result"], "blocked"), "bounces[0].lights[0].result")
    color = [c + 0.01 for c in gpu["bounces"][0]["color"]]
    altered(set_in(["bounces", 0, "color"], color), "bounces[0].color")
    level = gpu["pixel_8bit"]
    altered(set_in(["pixel_8bit"], [level[0] + 1, level[1], level[2]]), None)
    altered(set_in(["pixel_8bit"], [level[0], level[1], level[2] + 2]), "pixel_8bit")
    altered(lambda story: story["bounces"].pop(), "bounces[2].ray.origin")
    print(f"pixel_story_tool_test: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
