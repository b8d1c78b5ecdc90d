#!/usr/bin/env python3
"""Smoke test of tools/kernel_costs: one round at 64x48 on two scenes; the CSV must hold one
row per scene and variant with the documented columns, and sane values. Then --baseline
with --variants: two programs compared alone.

    kernel_costs_test.py RAYTRACER SOURCE_DIR OUT_DIR
"""
import csv
import pathlib
import shutil
import subprocess
import sys

COLUMNS = ["scene", "variant", "flags", "status", "spheres", "triangles", "compiled_out", "metric",
           "runs", "ms_min", "ms_max", "change_percent", "spread_percent", "gap_percent"]
VARIANTS = ["default", "sphere naive", "triangle mt", "offset fixed", "offset scaled", "all naive", "fp64", "general"]


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def main():
    binary, source, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    shutil.rmtree(out, ignore_errors=True)
    csv_path = out / "kernel_costs.csv"
    # test1.scene: one sphere, no triangles (their code is compiled out, so the triangle test
    # does not apply and the general kernel differs); mesh.scene: spheres, triangles and
    # highlights, so the general kernel is its own.
    scenes = [source.parent / "shared" / "scenes" / "test1.scene", source / "scenes" / "mesh.scene"]
    command = [sys.executable, source / "tools" / "kernel_costs", binary, "--rounds", "1",
               "--frames", "1", "--width", "64", "--height", "48", "--scenes", *scenes,
               "--csv", csv_path]
    print("running:", " ".join(map(str, command)), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout, result.stderr, sep="\n")
    if result.returncode != 0:
        fail(f"exit status {result.returncode}")
    if "| scene | default cpu_ms_per_frame |" not in result.stdout:
        fail("no table on stdout")
    with open(csv_path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != COLUMNS:
            fail(f"columns {reader.fieldnames}, expected {COLUMNS}")
        rows = list(reader)
    got = [(r["scene"], r["variant"]) for r in rows]
    expected = [(s.name, v) for s in scenes for v in VARIANTS]
    if got != expected:
        fail(f"rows {got}, expected {expected}")
    row = {(r["scene"], r["variant"]): r for r in rows}
    # A variant that changes no code of the scene's kernel is not run.
    skipped = {("test1.scene", "triangle mt"): "n/a", ("mesh.scene", "general"): "same"}
    for key, r in row.items():
        if key in skipped:
            if r["status"] != skipped[key] or r["runs"] != "0" or r["ms_min"]:
                fail(f"{key} should be skipped as {skipped[key]}: {r}")
            continue
        if r["status"] != "ok" or r["runs"] != "1" or not float(r["ms_min"]) > 0 or \
                r["ms_min"] != r["ms_max"] or r["metric"] != "cpu_ms_per_frame" or \
                r["spread_percent"] != "" or r["gap_percent"] != "":
            fail(f"insane row {r}")
        if key[1] == "default" and float(r["change_percent"]) != 0:
            fail(f"the default changes against itself: {r}")
    if row[("test1.scene", "default")]["triangles"] != "0" or \
            row[("mesh.scene", "default")]["triangles"] != "2402":
        fail("primitive counts not carried from the report")
    if row[("test1.scene", "general")]["compiled_out"] != "triangles" or \
            row[("mesh.scene", "general")]["compiled_out"] != "":
        fail("compiled_out not carried from the report")
    check_baseline(binary, source, out)
    print("OK")
    return 0


def check_baseline(binary, source, out):
    """--baseline OTHER --variants baseline: the default and the other program only, on one
    scene; the other program's rows name it. (The same binary stands in for an old build.)"""
    csv_path = out / "baseline.csv"
    scene = source / "scenes" / "mesh.scene"
    command = [sys.executable, source / "tools" / "kernel_costs", binary, "--rounds", "2",
               "--frames", "1", "--width", "64", "--height", "48", "--scenes", scene,
               "--baseline", binary, "--variants", "baseline", "--csv", csv_path]
    print("running:", " ".join(map(str, command)), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout, result.stderr, sep="\n")
    if result.returncode != 0:
        fail(f"--baseline: exit status {result.returncode}")
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if [r["variant"] for r in rows] != ["default", "baseline"]:
        fail(f"--baseline --variants baseline: rows {[r['variant'] for r in rows]}")
    baseline = rows[1]
    if baseline["status"] != "ok" or baseline["runs"] != "2" or \
            baseline["flags"] != f"program {pathlib.Path(binary).resolve()}" or \
            not float(baseline["ms_min"]) > 0:
        fail(f"insane baseline row {baseline}")
    unknown = subprocess.run(command[:-2] + ["--variants", "nonsense"], capture_output=True, text=True)
    if unknown.returncode != 2 or "unknown variant 'nonsense'" not in unknown.stderr:
        fail(f"an unknown variant was not a usage error: {unknown.returncode} {unknown.stderr}")


if __name__ == "__main__":
    sys.exit(main())
