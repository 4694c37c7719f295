#!/usr/bin/env python3
"""Prints docs/perf.md's "Trusted SSR" table from tools/ssr_trust_measure.sh output: per scene and
frame, hybrid against rt (SSIM on luma, PSNR, colour buckets), SSR failures and rays traced.

usage: tools/ssr_trust_table.py OUT
"""
import csv
import json
import sys
from pathlib import Path


def rows(path):
    with open(path, newline="") as f:
        return {int(r["frame"]): r for r in csv.DictReader(f)}


def main(out):
    print("| scene | frame | SSIM | PSNR dB | buckets % | reflective px | SSR failed % | rays hybrid | rays rt |")
    print("|---|---|---|---|---|---|---|---|---|")
    for compare in sorted((out / "compare").glob("*.json")):
        scene, frame = compare.stem.rsplit("_", 1)
        frame = int(frame)
        c = json.loads(compare.read_text())
        hybrid = rows(out / f"{scene}-hybrid" / "timings.csv")[frame]
        rt = rows(out / f"{scene}-rt" / "timings.csv")[frame]
        reflective = int(hybrid["reflective_pixels"])
        failed = int(hybrid["ssr_failed_pixels"])
        psnr = c["psnr_db"]["overall"]
        print(f"| {scene} | {frame} | {c['ssim']['luma']:.4f} | {psnr if isinstance(psnr, str) else f'{psnr:.2f}'} | "
              f"{c['color_buckets_percent']['mean']:.2f} | {reflective} | {100 * failed / max(reflective, 1):.1f} | "
              f"{hybrid['rays_traced']} | {rt['rays_traced']} |")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
