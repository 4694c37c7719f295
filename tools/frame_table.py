#!/usr/bin/env python3
"""Prints the issue-19 frame table (docs/perf.md) from tools/frame_matrix.sh's run folders.

usage: tools/frame_table.py OUT [--skip N]

One row per run folder OUT/<scene>-<size>-<mode>-<deform>-<shadows>-<gbuffer>/timings.csv: the mean
of each GPU pass, of gpu_total_ms, frame_ms (steady state) and frame_latency_ms over its rows after
the first N (default 10: the first frames pay for uploads and shader warm-up), in milliseconds.
"""
import argparse
import csv
import pathlib
import statistics
import sys

PASSES = ["shadow", "gbuffer", "light", "ssr", "ray_list", "trace", "hit_shade", "resolve"]
TOTALS = ["gpu_total", "frame", "frame_latency"]


def mean_of(rows, column):
    values = [float(row[column]) for row in rows if row.get(column, "") not in ("", None)]
    return statistics.fmean(values) if values else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--skip", type=int, default=10)
    args = parser.parse_args()
    runs = sorted(path.parent for path in args.out.glob("*/timings.csv"))
    if not runs:
        sys.exit(f"frame_table: no */timings.csv under {args.out}")
    columns = PASSES + TOTALS
    print("| run | rows | " + " | ".join(columns) + " |")
    print("|---|---|" + "---|" * len(columns))
    for run in runs:
        with open(run / "timings.csv", newline="") as file:
            rows = list(csv.DictReader(file))[args.skip:]
        cells = []
        for column in columns:
            value = mean_of(rows, column + "_ms")
            cells.append("-" if value is None or (column in PASSES and value == 0.0) else f"{value:.2f}")
        print(f"| {run.name} | {len(rows)} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
