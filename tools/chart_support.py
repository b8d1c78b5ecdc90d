"""What the chart scripts of tools/ share: matplotlib without a display, and their CSV."""

import csv
import sys


def import_pyplot(tool):
    """matplotlib.pyplot drawing to files (no display), or None after saying what to install."""
    try:
        import matplotlib
        matplotlib.use("Agg")  # no display needed
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"{tool}: matplotlib is missing (tools/install_deps.sh --bench)", file=sys.stderr)
        return None
    return plt


def read_rows(path):
    """The rows of a CSV file with a header line, as dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
