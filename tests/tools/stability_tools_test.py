#!/usr/bin/env python3
"""Smoke test of tools/stability and tools/speed_accuracy: each runs with tiny settings and
its CSV must hold exactly the expected rows, with sane values.

    stability_tools_test.py stability|speed_accuracy RAYTRACER SOURCE_DIR OUT_DIR

The chart is checked only where some python has matplotlib (the tools then draw it);
without it the tools write the CSV alone, as documented.
"""
import csv
import pathlib
import shutil
import subprocess
import sys


def has_matplotlib():
    for python in dict.fromkeys((sys.executable, "/usr/bin/python3")):
        if pathlib.Path(python).exists() and subprocess.run(
                [python, "-c", "import matplotlib"], capture_output=True).returncode == 0:
            return True
    return False


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def run(command):
    print("running:", " ".join(map(str, command)), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout, result.stderr, sep="\n")
    if result.returncode != 0:
        fail(f"exit status {result.returncode}")


def read_csv(path):
    if not path.exists():
        fail(f"{path} was not written")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_stability(binary, source, out):
    run([sys.executable, source / "tools" / "stability", binary, "--quick", "--families",
         "far_sphere", "edge_mesh", "--out", out])
    rows = read_csv(out / "results.csv")
    # --quick: two parameter values per family; far_sphere varies sphere test and offset,
    # edge_mesh triangle test and offset: 4 method combinations x 2 precisions each.
    expected = {(family, value, precision, s, t, o)
                for family, values, axes in (("far_sphere", ("10.0", "1000000.0"), "so"),
                                             ("edge_mesh", ("0.0001", "100000.0"), "to"))
                for value in values for precision in ("fp32", "fp64")
                for s in (("stable", "naive") if "s" in axes else ("stable",))
                for t in (("watertight", "mt") if "t" in axes else ("watertight",))
                for o in ("scaled", "fixed", "error-bound")}
    got = [(r["family"], r["value"], r["precision"], r["sphere_test"], r["triangle_test"],
            r["offset"]) for r in rows]
    if len(got) != len(expected) or set(got) != expected:
        fail(f"unexpected rows: {sorted(set(got) ^ expected)} (got {len(got)} rows)")
    for r in rows:
        if not (0 <= float(r["failure_rate"]) <= 1 and int(r["pixels"]) == 160 * 120 and
                int(r["wrong"]) <= int(r["differing"])):
            fail(f"insane row {r}")
    # The near sphere with the defaults is exact; the far one with the textbook test is not.
    rate = {(r["family"], r["value"], r["precision"], r["sphere_test"], r["triangle_test"],
             r["offset"]): float(r["failure_rate"]) for r in rows}
    if rate[("far_sphere", "10.0", "fp32", "stable", "watertight", "error-bound")] != 0:
        fail("the defaults fail on the near sphere")
    if rate[("far_sphere", "1000000.0", "fp32", "naive", "watertight", "error-bound")] < 0.01:
        fail("the textbook sphere test does not fail at distance/radius 1e6")
    return out / "stability_chart.png"


def check_speed_accuracy(binary, source, out):
    run([sys.executable, source / "tools" / "speed_accuracy", binary, "--quick", "--scenes",
         source / "scenes" / "lights_shadows.scene", "--width", "48", "--height", "36",
         "--samplers", "grid", "r2", "--spp", "1", "4", "--out", out])
    rows = read_csv(out / "results.csv")
    got = sorted((r["sampler"], r["spp"], r["precision"]) for r in rows)
    expected = sorted((s, n, "fp32") for s in ("grid", "r2") for n in ("1", "4"))
    if got != expected:
        fail(f"rows {got}, expected {expected}")
    for r in rows:
        if not (float(r["wall_ms_median"]) > 0 and 0 <= float(r["rmse"]) <= 1 and
                float(r["delta_e76"]) >= 0 and 0 < float(r["ssim"]) <= 1 and
                r["pareto"] in ("yes", "no") and
                r["reference_spp"] == "64"):
            fail(f"insane row {r}")
    if not any(r["pareto"] == "yes" for r in rows):
        fail("no setting is on the Pareto front")
    # One sample per pixel is the pixel centre whatever the sampler: the same image.
    spp1 = {(r["rmse"], r["ssim"]) for r in rows if r["spp"] == "1"}
    if len(spp1) != 1:
        fail(f"spp 1 differs between samplers: {spp1}")
    return out / "speed_accuracy_chart.png"


def main():
    tool, binary, source, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), pathlib.Path(sys.argv[4])
    shutil.rmtree(out, ignore_errors=True)
    chart = {"stability": check_stability, "speed_accuracy": check_speed_accuracy}[tool](binary, source, out)
    if has_matplotlib() and not chart.exists():
        fail(f"matplotlib is available but {chart} was not drawn")
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
