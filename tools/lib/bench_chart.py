#!/usr/bin/env python3
"""Chart of tools/bench's results: frame time against triangle count, log-log.

    python3 tools/lib/bench_chart.py results.csv chart.png [--title TEXT]

One colour per renderer; the generated meshes as lines, the classic scenes as hollow
markers. Scenes without triangles have no place on a log axis and are left out.
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it, 1 if there is
nothing to plot.
"""
import argparse
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree for chart_support
from chart_support import import_pyplot, read_rows  # noqa: E402

STYLES = {"raytracer": ("Raytracer", "tab:red", "o"), "embree": ("Embree", "tab:blue", "s"),
          "brute_force": ("brute force", "tab:green", "^")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="Frame time against triangle count")
    args = parser.parse_args()
    plt = import_pyplot("bench_chart")
    if plt is None:
        return 3

    rows = [r for r in read_rows(args.csv) if r["status"] == "ok" and int(r["triangles"]) > 0]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for renderer, (label, color, marker) in STYLES.items():
        for kind in ("mesh", "classic"):
            points = sorted((int(r["triangles"]), float(r["wall_ms_median"])) for r in rows
                            if r["renderer"] == renderer and r["kind"] == kind)
            if not points:
                continue
            xs, ys = zip(*points)
            if kind == "mesh":
                ax.plot(xs, ys, marker=marker, color=color, label=f"{label}, meshes")
            else:
                ax.scatter(xs, ys, marker=marker, facecolors="none", edgecolors=color,
                           label=f"{label}, classic scenes")
    # Each classic scene named once, above its slowest renderer.
    highest = {}
    for r in rows:
        if r["kind"] == "classic":
            point = (int(r["triangles"]), float(r["wall_ms_median"]))
            highest[r["scene"]] = max(highest.get(r["scene"], point), point, key=lambda p: p[1])
    for scene, (x, y) in highest.items():
        ax.annotate(scene.removesuffix(".scene"), (x, y), textcoords="offset points",
                    xytext=(4, 4), ha="left", fontsize=7, color="dimgrey")
    if not ax.has_data():
        print("bench_chart: nothing to plot", file=sys.stderr)
        return 1
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles")
    ax.set_ylabel("ms per frame (median)")
    ax.set_title(args.title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
