"""What the chart scripts of tools/ share: matplotlib without a display, and their CSV."""

import argparse
import csv
import sys


def import_pyplot(tool):
    """matplotlib.pyplot drawing to files (no display), or None after saying what to install."""
    try:
        import matplotlib
        matplotlib.use("Agg")  # no display needed
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"{tool}: matplotlib is missing (tools/build/install_deps.sh --bench)", file=sys.stderr)
        return None
    return plt


def read_rows(path):
    """The rows of a CSV file with a header line, as dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def chart_inputs(tool, description, group_column):
    """The command line CSV PNG of a chart script, read: (pyplot, rows, the distinct values of
    group_column in order, the PNG path), or an exit status (3: no matplotlib, 1: no rows)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("csv")
    parser.add_argument("png")
    args = parser.parse_args()
    plt = import_pyplot(tool)
    if plt is None:
        return 3
    rows = read_rows(args.csv)
    groups = list(dict.fromkeys(r[group_column] for r in rows))
    if not groups:
        print(f"{tool}: nothing to plot", file=sys.stderr)
        return 1
    return plt, rows, groups, args.png
