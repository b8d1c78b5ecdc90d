#!/usr/bin/env python3
"""Chart of tools/speed_accuracy's results: error against frame time, with the Pareto front.

    python3 tools/lib/speed_accuracy_chart.py results.csv chart.png

One column per scene; the top row RMSE (linear [0,1] units), the middle row mean CIE76
Delta E, the bottom row 1 - SSIM (8-bit), all against frame time (wall_ms_median), log-log. Colour: sampler; marker:
precision (circle fp32, square fp64); each point labelled with its spp. The line joins the
panel's Pareto front (outlined points: no other setting both faster and more accurate on
that panel's metric; the CSV's pareto column is the front on RMSE). Needs matplotlib
(Debian: python3-matplotlib); exits 3 without it, 1 if there is nothing to plot.
"""
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree for chart_support
from chart_support import chart_inputs  # noqa: E402

COLOURS = {"grid": "tab:blue", "stratified": "tab:orange", "r2": "tab:green"}
MARKERS = {"fp32": "o", "fp64": "s"}
# (CSV column, axis label, the value plotted: an error, lower is better)
METRICS = (("rmse", "RMSE (linear [0,1])", float),
           ("delta_e76", "mean Delta E*ab (CIE76, sRGB)", float),
           ("ssim", "1 - SSIM (8-bit, RGB averaged)", lambda v: 1 - float(v)))


def pareto_front(points):
    """The (time, error) points that no other point beats on both, fastest first."""
    front = []
    for x, y, _ in sorted(points, key=lambda p: (p[0], p[1])):
        if not front or y < front[-1][1]:
            front.append((x, y))
    return front


def main():
    inputs = chart_inputs("speed_accuracy_chart", __doc__.splitlines()[0], "scene")
    if isinstance(inputs, int):
        return inputs
    plt, rows, scenes, png = inputs
    fig, axes = plt.subplots(len(METRICS), len(scenes), figsize=(5.6 * len(scenes), 12.0),
                             squeeze=False)
    for column, scene in enumerate(scenes):
        scene_rows = [r for r in rows if r["scene"] == scene]
        for row_index, (metric, label, error) in enumerate(METRICS):
            ax = axes[row_index][column]
            points = [(float(r["wall_ms_median"]), max(error(r[metric]), 1e-6), r)
                      for r in scene_rows]
            front = pareto_front(points)
            for x, y, r in points:
                ax.scatter(x, y, color=COLOURS.get(r["sampler"], "black"),
                           marker=MARKERS.get(r["precision"], "x"), s=28,
                           edgecolors="black" if (x, y) in front else "none", linewidths=0.8)
                ax.annotate(r["spp"], (x, y), textcoords="offset points", xytext=(4, 3), fontsize=6,
                            color="dimgrey")
            xs, ys = zip(*front)
            ax.plot(xs, ys, "-", color="black", linewidth=0.8, alpha=0.6)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("frame time, ms (wall_ms_median)")
            ax.set_ylabel(label)
            ax.set_title(f"{scene}, {scene_rows[0]['width']}x{scene_rows[0]['height']}", fontsize=10)
            ax.grid(True, which="both", alpha=0.25)
    handles = [plt.Line2D([], [], color=c, marker="o", linestyle="", label=f"sampler {s}")
               for s, c in COLOURS.items()]
    handles += [plt.Line2D([], [], color="grey", marker=m, linestyle="", label=p)
                for p, m in MARKERS.items()]
    handles.append(plt.Line2D([], [], color="black", linewidth=0.8, label="Pareto front (outlined)"))
    fig.legend(handles=handles, loc="lower center", ncol=6, fontsize=8, frameon=False)
    reference = rows[0]["reference_spp"]
    fig.suptitle(f"Error against frame time (numbers: spp). Reference: CPU reference renderer, "
                 f"fp64, {reference} spp on a regular grid. {rows[0]['device']}", fontsize=10)
    fig.tight_layout(rect=(0, 0.04, 1, 0.96))
    fig.savefig(png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
