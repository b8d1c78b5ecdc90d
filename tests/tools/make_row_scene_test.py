#!/usr/bin/env python3
"""tools/make_row_scene.py: the scenes it writes load with the counts asked for, and the
brute-force path bakes their spheres in up to where the hierarchy takes over.

    make_row_scene_test.py RAYTRACER TOOL OUTPUT_DIR
"""

import json
import os
import subprocess
import sys


def bench(raytracer, scene):
    run = subprocess.run([raytracer, scene, "--bench", "1", "--width", "16", "--height", "16"],
                         capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        sys.exit(f"FAIL: {scene}: exit {run.returncode}: {run.stderr}")
    return json.loads(run.stdout[run.stdout.rfind("{"):])


def main():
    raytracer, tool, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    # 4 + 4: brute force, spheres baked; 8 + 8 = 16 primitives: the hierarchy, nothing baked.
    for spheres, triangles, baked in ((4, 4, True), (0, 3, True), (8, 8, False)):
        scene = os.path.join(out, f"s{spheres}t{triangles}.scene")
        subprocess.run([sys.executable, tool, str(spheres), str(triangles), "-o", scene],
                       check=True, timeout=60)
        report = bench(raytracer, scene)
        got = (report["spheres"], report["triangles"], report["baked_spheres"])
        if got != (spheres, triangles, baked):
            sys.exit(f"FAIL: {scene}: spheres, triangles, baked_spheres = {got}, "
                     f"expected {(spheres, triangles, baked)}")
    print("make_row_scene: scenes load with their counts; baking follows the brute-force path")


if __name__ == "__main__":
    main()
