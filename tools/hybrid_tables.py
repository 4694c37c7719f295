#!/usr/bin/env python3
"""Prints the markdown tables of docs/perf.md's hybrid section from tools/hybrid_measure.sh output.

usage: tools/hybrid_tables.py OUT
"""
import csv
import json
import sys
from pathlib import Path

FRAMES = [1800, 2100, 2300, 4400]


def rows(path):
    with open(path, newline="") as f:
        return {int(r["frame"]): r for r in csv.DictReader(f)}


def number(text, digits=1):
    return "-" if text in ("", None) else f"{float(text):.{digits}f}"


def quality_table(out):
    print("| frame | deform | ssr vs rt: buckets % | SSIM | PSNR dB | hybrid vs rt: buckets % | SSIM | PSNR dB |")
    print("|---|---|---|---|---|---|---|---|")
    for deform in ("off", "on"):
        for frame in FRAMES:
            cells = []
            for mode in ("ssr", "hybrid"):
                c = json.loads((out / "compare" / f"{frame}_{mode}_deform-{deform}.json").read_text())
                psnr = c["psnr_db"]["overall"]
                cells += [f"{c['color_buckets_percent']['mean']:.2f}", f"{c['ssim']['luma']:.4f}",
                          psnr if isinstance(psnr, str) else f"{psnr:.2f}"]
            print(f"| {frame} | {deform} | " + " | ".join(cells) + " |")


def rays_table(out):
    hybrid = rows(out / "images-hybrid-deform-off" / "timings.csv")
    rt = rows(out / "images-rt-deform-off" / "timings.csv")
    print("| frame | reflective px | rays hybrid | rays rt | hybrid / rt |")
    print("|---|---|---|---|---|")
    for frame in FRAMES:
        h, r = int(hybrid[frame]["rays_traced"]), int(rt[frame]["rays_traced"])
        print(f"| {frame} | {rt[frame]['reflective_pixels']} | {h} | {r} | {h / r:.2f} |")


def timing_table(out):
    runs = sorted(p for p in out.iterdir() if p.name.startswith("timing-"))
    print("| run | frame | frame latency ms | GPU passes ms | ssr | ray list | trace (CPU) | hit shade | accel update | deform |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for run in runs:
        table = rows(run / "timings.csv")
        for frame in FRAMES:
            r = table[frame]
            # frame_latency_ms was called cpu_frame_ms before the frame loop was pipelined.
            latency = r.get("frame_latency_ms", r.get("cpu_frame_ms"))
            print(f"| {run.name[len('timing-'):]} | {frame} | {number(latency)} | {number(r['gpu_total_ms'], 2)} | "
                  f"{number(r['ssr_ms'], 2)} | {number(r['ray_list_ms'], 2)} | {number(r['trace_ms'])} | "
                  f"{number(r['hit_shade_ms'], 2)} | {number(r['accel_update_ms'])} | {number(r['deform_ms'])} |")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip())
    out = Path(sys.argv[1])
    for title, table in (("Quality against rt", quality_table), ("Rays traced (static)", rays_table),
                         ("Frame times", timing_table)):
        print(f"\n### {title}\n")
        table(out)


if __name__ == "__main__":
    main()
