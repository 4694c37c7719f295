#!/usr/bin/env python3
"""Prints the mean GPU time of every scope of `glint render --profile-scopes` runs as a markdown table.

usage: tools/scope_table.py RUN [RUN ...] [--skip N]

RUN is a run folder holding scopes.csv (or the scopes.csv itself). One row per scope path
(gbuffer/compute_visibility/tiles), in tree order (a scope's children follow it, in the order the
frame ran them); one column per run: the mean over the frames after the first N
(default 10: the first frames pay for uploads and shader warm-up, as tools/frame_table.py) of the
frames that ran the scope, in milliseconds; followed by how many frames ran it, in parentheses,
where that is fewer than all ("-" where a run never ran it). A scope run twice in a frame (the same
path) counts with its sum.
"""
import argparse
import csv
import pathlib
import statistics
import sys


def read_scopes(path, skip):
    """{scope path: [ms per frame]} over the frames after the first `skip`, and the paths in tree order."""
    with open(path, newline="") as file:
        rows = list(csv.DictReader(file))
    frames = sorted({int(row["frame"]) for row in rows})
    kept = set(frames[skip:])
    times, order = {}, []
    for row in rows:
        if int(row["frame"]) not in kept:
            continue
        scope = row["scope"]
        if scope not in times:
            times[scope] = []
            order.append(scope)
        times[scope].append((int(row["frame"]), float(row["ms"])))
    per_frame = {}
    for scope, samples in times.items():
        sums = {}
        for frame, ms in samples:
            sums[frame] = sums.get(frame, 0.0) + ms
        per_frame[scope] = list(sums.values())
    return per_frame, order, len(kept)


def tree_order(orders):
    """Merges the runs' path orders: every path after its parent, siblings in first-seen order."""
    children, seen = {}, set()
    for order in orders:
        for path in order:
            if path in seen:
                continue
            seen.add(path)
            parent = path.rsplit("/", 1)[0] if "/" in path else ""
            # A parent a run never recorded (skipped frames) still groups its children.
            while parent and parent not in seen:
                seen.add(parent)
                grand = parent.rsplit("/", 1)[0] if "/" in parent else ""
                children.setdefault(grand, []).append(parent)
                parent = grand
            children.setdefault(parent, []).append(path)
    ordered = []

    def visit(parent):
        for child in children.get(parent, []):
            ordered.append(child)
            visit(child)

    visit("")
    return ordered


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", type=pathlib.Path, nargs="+")
    parser.add_argument("--skip", type=int, default=10)
    args = parser.parse_args()
    tables = []
    for run in args.runs:
        path = run if run.is_file() else run / "scopes.csv"
        if not path.is_file():
            sys.exit(f"scope_table: {path}: no such file (render with --profile-scopes)")
        per_frame, order, frames = read_scopes(path, args.skip)
        if frames == 0:
            sys.exit(f"scope_table: {path}: no frames after the first {args.skip} (--skip)")
        name = run.name if run.is_dir() else run.parent.name
        tables.append((name, per_frame, order, frames))
    print("| scope | " + " | ".join(f"{name} (ms, {frames} frames)" for name, _, _, frames in tables) + " |")
    print("|---|" + "---:|" * len(tables))
    for path in tree_order([order for _, _, order, _ in tables]):
        cells = []
        for _, per_frame, _, frames in tables:
            values = per_frame.get(path)
            if not values:
                cells.append("-")
            elif len(values) == frames:
                cells.append(f"{statistics.fmean(values):.3f}")
            else:
                cells.append(f"{statistics.fmean(values):.3f} ({len(values)})")
        print(f"| {path} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
