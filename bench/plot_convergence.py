#!/usr/bin/env python3
"""plot_convergence.py -- log-log plot of the error against time of renders
reported by `wavefront render --report CSV`, one curve per CSV, with a dashed
line of slope -1: an unbiased Monte Carlo estimator's (relative) MSE falls as
1/samples, so as 1/time, and a curve parallel to the line converges at that
rate. The line is anchored at the first CSV's first point.

Usage: python3 bench/plot_convergence.py OUT.png CSV [CSV ...]
           [--metric relmse|mse|mae|relmse_estimate] [--labels LABEL ...] [--title TEXT]

Labels default to the CSVs' file stems. Up to 10 curves take matplotlib's
tab10 colours; more take tab20, whose colours come in light/dark pairs, so
pass related CSVs next to each other. Needs matplotlib (Debian:
python3-matplotlib, installed by scripts/setup.sh for /usr/bin/python3).
"""

import argparse
import csv
import os
import sys

METRICS = ("relmse", "mse", "mae", "relmse_estimate")
METRIC_NAMES = {"relmse": "relMSE", "mse": "MSE", "mae": "MAE", "relmse_estimate": "estimated relMSE"}


def fail(message):
    print(f"plot_convergence.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_curve(path, metric):
    """(seconds, error) of the checkpoints that have the metric; the first has
    no estimate and a render without a reference has no measured error."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    if metric not in (reader.fieldnames or []):
        fail(f"{path}: no column '{metric}'")
    points = [(float(r["seconds"]), float(r[metric])) for r in rows if r[metric]]
    if not points:
        fail(f"{path}: column '{metric}' has no values")
    return points


def main():
    parser = argparse.ArgumentParser(description="Log-log plot of render error against time.")
    parser.add_argument("output", metavar="OUT.png")
    parser.add_argument("csvs", metavar="CSV", nargs="+")
    parser.add_argument("--metric", choices=METRICS, default="relmse")
    parser.add_argument("--labels", nargs="+", metavar="LABEL", help="one per CSV (default: the file stems)")
    parser.add_argument("--title")
    args = parser.parse_args()
    labels = args.labels or [os.path.splitext(os.path.basename(p))[0] for p in args.csvs]
    if len(labels) != len(args.csvs):
        fail(f"{len(labels)} labels for {len(args.csvs)} CSVs")
    curves = [read_curve(path, args.metric) for path in args.csvs]

    try:
        import matplotlib
    except ImportError:
        fail("matplotlib is missing: apt-get install python3-matplotlib, and run Debian's /usr/bin/python3")
    matplotlib.use("Agg")  # files only: no display needed
    import matplotlib.pyplot as plt

    colours = plt.get_cmap("tab10" if len(curves) <= 10 else "tab20").colors
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=100)
    for i, (points, label) in enumerate(zip(curves, labels)):
        seconds, errors = zip(*points)
        ax.loglog(seconds, errors, marker=".", color=colours[i % len(colours)], label=label)

    t0, e0 = curves[0][0]
    t1 = max(t for points in curves for t, _ in points)
    ax.loglog([t0, t1], [e0, e0 * t0 / t1], "k--", linewidth=1, label="slope −1 (error ∝ 1/time)")

    ax.set_xlabel("seconds")
    ax.set_ylabel(METRIC_NAMES[args.metric])
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, which="major", linewidth=0.5)
    ax.grid(True, which="minor", linewidth=0.3, alpha=0.4)
    # Outside the axes: the curves fill the corners a legend would take.
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
