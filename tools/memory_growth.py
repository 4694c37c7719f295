#!/usr/bin/env python3
"""Memory growth over a long `glint render` run (docs/reliability.md, "Long runs").

    tools/memory_growth.py RUN/timings.csv [--from-row 100] [--limit-percent 1]

Reads the resident_mb and gpu_memory_used_mb columns that glint writes for every frame and prints,
for each, the value at the row `--from-row` (counted from 0, default 100: the first frames fill
caches and pools), the value at the last row, the peak, and the growth in percent between the two.
Exits 1 when a growth exceeds --limit-percent, 2 on a missing or malformed file.
"""
import argparse
import csv
import sys


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("timings", help="timings.csv of a glint render run")
    parser.add_argument("--from-row", type=int, default=100, help="row the growth is measured from (default 100)")
    parser.add_argument("--limit-percent", type=float, default=1.0, help="largest growth accepted (default 1)")
    args = parser.parse_args()
    try:
        with open(args.timings, newline="") as file:
            rows = list(csv.DictReader(file))
    except OSError as error:
        print(f"memory_growth: {args.timings}: {error.strerror}", file=sys.stderr)
        return 2
    if len(rows) <= args.from_row:
        print(f"memory_growth: {args.timings}: {len(rows)} rows, fewer than --from-row {args.from_row} + 1",
              file=sys.stderr)
        return 2
    exceeded = False
    print(f"{args.timings}: frames {rows[args.from_row]['frame']} -> {rows[-1]['frame']} ({len(rows)} rows)")
    for column in ("resident_mb", "gpu_memory_used_mb"):
        if column not in rows[0]:
            print(f"memory_growth: {args.timings}: no column {column}", file=sys.stderr)
            return 2
        values = [float(row[column]) for row in rows if row[column] != ""]
        if len(values) != len(rows):
            print(f"  {column:<20} not sampled on this machine")
            continue
        start, end, peak = values[args.from_row], values[-1], max(values[args.from_row:])
        growth = 100.0 * (end - start) / start
        exceeded |= growth > args.limit_percent
        print(f"  {column:<20} {start:10.1f} MiB -> {end:10.1f} MiB (peak {peak:.1f}): {growth:+.2f} %")
    return 1 if exceeded else 0


if __name__ == "__main__":
    sys.exit(main())
