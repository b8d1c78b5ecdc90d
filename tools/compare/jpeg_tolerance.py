#!/usr/bin/env python3
"""Measures the tolerance a JPEG of each quality needs: for every scene and quality, the
smallest channel tolerance (in levels) at which Raytracer compare finds at least 99.5% of
the pixels of a correct render, saved as JPEG, matching the reference. The table in
host/compare/tolerance.cpp comes from its output (the worst scene per quality).

usage: jpeg_tolerance.py RAYTRACER SCENE... [--qualities 50,75,85,90,95,100] [--out DIR]
Prints a CSV line per scene and quality, then the worst per quality. Renders with
Raytracer (-o x.jpg --quality Q) on lavapipe; about a minute per scene on 2 cores.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

# Every global setting fixed at the model's defaults: only the full reference is traced.
FIXED = ["--depth", "5", "--background", "1,1,1", "--fov-axis", "vertical", "--rays", "centre",
         "--flip", "none", "--gamma", "1", "--channels", "rgb", "--brightness", "1",
         "--quantize", "round"]


def matching(raytracer, image, scene, tolerance):
    out = subprocess.run([raytracer, "compare", str(image), str(scene), "--json",
                          "--tolerance", str(tolerance)] + FIXED,
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)["images"][0]["matching_fraction"]


def needed_tolerance(raytracer, image, scene, share):
    low, high = 0, 64  # matching(high) is assumed to hold
    while low < high:
        middle = (low + high) // 2
        if matching(raytracer, image, scene, middle) >= share:
            high = middle
        else:
            low = middle + 1
    return low


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("raytracer")
    parser.add_argument("scenes", nargs="+", type=pathlib.Path)
    parser.add_argument("--qualities", default="50,75,85,90,95,100")
    parser.add_argument("--share", type=float, default=0.995)
    args = parser.parse_args()
    qualities = [int(q) for q in args.qualities.split(",")]
    worst = {q: (0, "") for q in qualities}
    print("scene,quality,tolerance")
    with tempfile.TemporaryDirectory() as folder:
        for scene in args.scenes:
            for quality in qualities:
                image = pathlib.Path(folder) / f"{scene.stem}-{quality}.jpg"
                subprocess.run([args.raytracer, str(scene), "-o", str(image), "--quality",
                                str(quality), "--quiet"], check=True)
                tolerance = needed_tolerance(args.raytracer, image, scene, args.share)
                print(f"{scene.name},{quality},{tolerance}", flush=True)
                if tolerance > worst[quality][0]:
                    worst[quality] = (tolerance, scene.name)
    for quality in qualities:
        print(f"# quality {quality}: at most {worst[quality][0]} ({worst[quality][1]})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
