#!/usr/bin/env python3
"""Chart of tools/stability's results: failure rate against scene scale, per method.

    python3 tools/lib/stability_chart.py results.csv chart.png

One panel per stress family, the family's parameter on a log x axis (distance/radius for
far_sphere, the ground quad's width for ground*, the scene's scale otherwise), the share
of wrong pixels on a symmetric-log y axis (0 is drawn at the bottom). One line per method:
the defaults in fp32 and fp64, each naive method alone in fp32 (the others at their
defaults), the scaled offset in fp32, and all of the family's naive methods together
in fp32 and fp64. Needs matplotlib (Debian: python3-matplotlib); exits 3 without it, 1 if
there is nothing to plot.
"""
import math
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree for chart_support
from chart_support import chart_inputs  # noqa: E402

# (label, colour, style, wanted settings); a line is drawn only where the family varies
# every method it names.
LINES = [
    ("defaults (stable, watertight, error-bound), fp32", "tab:green", "-", {"precision": "fp32"}),
    ("defaults, fp64", "tab:green", ":", {"precision": "fp64"}),
    ("naive sphere test, fp32", "tab:red", "-", {"precision": "fp32", "sphere_test": "naive"}),
    ("Moller-Trumbore, fp32", "tab:purple", "-", {"precision": "fp32", "triangle_test": "mt"}),
    ("fixed offset 1e-4, fp32", "tab:orange", "-", {"precision": "fp32", "offset": "fixed"}),
    ("scaled offset, fp32", "tab:blue", "-", {"precision": "fp32", "offset": "scaled"}),
    ("all naive, fp32", "black", "--", {"precision": "fp32", "all_naive": True}),
    ("all naive, fp64", "grey", ":", {"precision": "fp64", "all_naive": True}),
]
DEFAULTS = {"sphere_test": "stable", "triangle_test": "watertight", "offset": "error-bound"}
NAIVE = {"sphere_test": "naive", "triangle_test": "mt", "offset": "fixed"}
TITLES = {"far_sphere": "far sphere (radius 1)", "far_sphere_scaled": "far sphere d/r = 1e3, scaled",
          "edge_mesh": "edge-aimed closed mesh", "grazing": "grazing ground plane",
          "mirrors": "two facing mirrors", "degenerate": "zero-area / zero-normal triangles",
          "inside_sphere": "camera inside a sphere",
          "ground": "huge ground, objects of size 1", "ground_small": "huge ground, millimetre objects",
          "ground_high": "huge ground, objects of size 10 seen from 100",
          "ground_overhead": "huge ground, overhead light", "ground_mirror": "huge mirror ground"}
XLABELS = {"distance_over_radius": "distance / radius", "scale": "scene scale",
           "extent": "ground extent (the quad's width)"}


def varied_methods(rows):
    """The method columns that take more than one value in rows."""
    return {m for m in DEFAULTS if len({r[m] for r in rows}) > 1}


def wanted(row, spec, varied):
    if row["precision"] != spec["precision"]:
        return False
    if spec.get("all_naive"):
        return all(row[m] == (NAIVE[m] if m in varied else DEFAULTS[m]) for m in DEFAULTS)
    settings = dict(DEFAULTS, **{k: v for k, v in spec.items() if k in DEFAULTS})
    return all(row[m] == settings[m] for m in DEFAULTS)


def main():
    inputs = chart_inputs("stability_chart", __doc__.splitlines()[0], "family")
    if isinstance(inputs, int):
        return inputs
    plt, rows, families, png = inputs
    columns = min(3, len(families))
    lines_of_panels = math.ceil(len(families) / columns)
    fig, axes = plt.subplots(lines_of_panels, columns, figsize=(5.2 * columns, 3.9 * lines_of_panels),
                             squeeze=False)
    handles = {}
    for ax, family in zip(axes.flat, families):
        family_rows = [r for r in rows if r["family"] == family]
        varied = varied_methods(family_rows)
        for label, color, style, spec in LINES:
            needs = {m for m in DEFAULTS if m in spec}
            if not needs <= varied or (spec.get("all_naive") and len(varied) < 2):
                continue
            points = sorted((float(r["value"]), 100 * float(r["failure_rate"]))
                            for r in family_rows if wanted(r, spec, varied))
            if not points:
                continue
            xs, ys = zip(*points)
            (line,) = ax.plot(xs, ys, style, color=color, marker="o", markersize=3.5, label=label)
            handles.setdefault(label, line)
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=0.01)
        ax.set_ylim(bottom=0, top=110)
        ax.set_title(TITLES.get(family, family), fontsize=10)
        ax.set_xlabel(XLABELS.get(family_rows[0]["parameter"], family_rows[0]["parameter"]))
        ax.set_ylabel("wrong pixels (%)")
        ax.grid(True, which="major", alpha=0.3)
    for ax in list(axes.flat)[len(families):]:
        ax.axis("off")
    fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=4, fontsize=8,
               frameon=False)
    fig.suptitle("Failure rate against scene scale (wrong: > 2/255 outside the CPU reference's "
                 "range over rays 0.01 px apart)", fontsize=11)
    fig.tight_layout(rect=(0, 0.07, 1, 0.96))
    fig.savefig(png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
