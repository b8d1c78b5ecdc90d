#!/usr/bin/env python3
"""Times Raytracer compare: for each scene, a correct 640x480 render (the CPU reference's
own PNG, from reference_render), Raytracer's render of it upside down (a PPM from
Raytracer -o, its rows reversed here), and the scene as a tracer with a classic mistake
renders it (reference_render --mistake) as PNG and as JPEG of quality 75, each compared
with the scene, the global search and the catalogue of mistakes included. Prints a table
of seconds (search, full-size reference, the regions' facts and causes, whole run as the
process saw it), the verdicts and the first region's cause, for docs/performance.md.

usage: compare_bench.py BUILD_DIR SCENE... [--runs N] [--mistake NAME]
BUILD_DIR holds Raytracer and tools/reference_render. The median of N runs (default 3).
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time


def compare(raytracer, image, scene):
    start = time.perf_counter()
    out = subprocess.run([raytracer, "compare", str(image), str(scene), "--json"],
                         capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - start
    entry = json.loads(out)["images"][0]
    return wall, entry


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("scenes", nargs="+", type=pathlib.Path)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--mistake", default="no-shadows",
                        help="the mistake of the wrong images (reference_render --help)")
    args = parser.parse_args()
    raytracer = args.build / "Raytracer"
    reference = args.build / "tools" / "reference_render"
    print("| scene | image | verdict | first cause | search s | reference s | causes s "
          "| whole run s |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        for scene in args.scenes:
            png = folder / f"{scene.stem}.png"
            subprocess.run([reference, str(scene), "-o", str(png)], check=True,
                           capture_output=True)
            # A JPEG of the same render, upside down: the PPM from Raytracer, rows reversed.
            ppm = folder / f"{scene.stem}.ppm"
            subprocess.run([raytracer, str(scene), "-o", str(ppm), "--quiet"], check=True)
            data = ppm.read_bytes()
            header_end = 0
            for _ in range(3):  # magic, size, maximum: three lines as Raytracer writes them
                header_end = data.index(b"\n", header_end) + 1
            width, height = map(int, data.split(b"\n")[1].split())
            rows = [data[header_end + r * width * 3: header_end + (r + 1) * width * 3]
                    for r in range(height)]
            flipped = folder / f"{scene.stem}-flipped.ppm"
            flipped.write_bytes(data[:header_end] + b"".join(reversed(rows)))
            wrong = []
            for suffix, extra in ((".png", []), (".jpg", ["--jpeg-quality", "75"])):
                image = folder / f"{scene.stem}-{args.mistake}{suffix}"
                subprocess.run([reference, str(scene), "-o", str(image), "--mistake",
                                args.mistake] + extra, check=True, capture_output=True)
                wrong.append((f"{args.mistake} {suffix[1:].upper()}", image))
            for label, image in [("correct PNG", png), ("upside-down PPM", flipped)] + wrong:
                runs = [compare(raytracer, image, scene) for _ in range(args.runs)]
                walls = [wall for wall, _ in runs]
                entry = runs[0][1]
                search = statistics.median(e["search"]["seconds"] for _, e in runs)
                ref = statistics.median(e["reference_seconds"] for _, e in runs)
                causes = statistics.median(e["diagnosis_seconds"] for _, e in runs)
                verdict = entry["verdict"] + (f" ({entry['options']})" if entry["options"] else "")
                regions = entry["regions"]
                cause = (regions[0].get("cause") or "none") if regions else "-"
                print(f"| {scene.name} | {label} | {verdict} | {cause} | {search:.2f} | "
                      f"{ref:.2f} | {causes:.2f} | {statistics.median(walls):.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
