#!/usr/bin/env python3
"""Charts of a `glint bench` run, styled after the paper's figures.

Usage: python3 plot_bench.py DIR

Reads DIR/summary.json (written by `glint bench`) and writes DIR/charts/<name>.png and .svg:
  fig5, fig7, fig8, fig9, fig10  frame time along the walkthrough per structure (interval means, as
                                 the paper's line charts), and a bar per structure (mean, with the
                                 5th-95th percentile range)
  fig11                          per structure, rebuild time against render time (the paper's Fig. 11)
  fig12                          ssr, hybrid and rt along the walkthrough, static and deforming
  fig4                           the full scene's floor plan with the camera and light paths
  table1, table2                 colour buckets and SSIM of ssr and hybrid against rt per frame
  adaptive                       (--experiment adaptive) per scene, SSIM and PSNR against rt over the
                                 reflection cost of ssr, hybrid, rt and auto at its budgets, the
                                 Pareto front joined
Needs python3-matplotlib only. glint copies this script next to its results; the source is
tools/plot_bench.py in the glint repository.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FRAME_FIGURES = {
    "fig5": "Fig. 5: static full scene",
    "fig7": "Fig. 7: full scene, deforming dinosaurs",
    "fig8": "Fig. 8: simplified scene, static",
    "fig9": "Fig. 9: simplified scene, deforming dinosaurs",
    "fig10": "Fig. 10: ray tracing the deforming dinosaurs only",
}
QUALITY_TABLES = {
    "table1": "Table I: quality against rt, static",
    "table2": "Table II: quality against rt, simplified scene, deforming",
}
MODE_COLOURS = {"ssr": "tab:green", "hybrid": "tab:blue", "rt": "tab:red", "auto": "tab:purple"}


def done_cells(summary, figure):
    return [c for c in summary["cells"] if c["figure"] == figure and c["status"] == "done"]


def series_label(cell):
    return cell["structure"] + (" " + cell["update"] if cell["update"] else "")


def interval_series(cell):
    xs = [(i["first_frame"] + i["last_frame"]) / 2.0 for i in cell["intervals"]]
    ys = [i["mean_ms"] for i in cell["intervals"]]
    return xs, ys


def style_axes(ax, title, xlabel, ylabel):
    ax.set_title(title, fontsize=10)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, color="0.85", linewidth=0.6)
    ax.set_axisbelow(True)


def save(fig, out_dir, name):
    fig.tight_layout()
    for extension in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, name + "." + extension), dpi=120)
    plt.close(fig)


def setting_text(summary):
    s = summary["settings"]
    renderer = summary["environment"]["gl"]["renderer"]
    return "{}x{}, stride {}, {}".format(s["width"], s["height"], s["stride"], renderer)


def plot_frame_figure(summary, figure, title, out_dir):
    cells = done_cells(summary, figure)
    if not cells:
        return False
    fig, (lines, bars) = plt.subplots(1, 2, figsize=(12, 4.2), gridspec_kw={"width_ratios": [2.2, 1]})
    for cell in cells:
        xs, ys = interval_series(cell)
        dashed = cell["update"] in ("refit", "auto")
        lines.plot(xs, ys, linestyle="--" if dashed else "-", marker="." if len(xs) < 30 else None,
                   linewidth=1.2, label=series_label(cell))
    style_axes(lines, title, "walkthrough frame", "frame time (ms)")
    lines.set_ylim(bottom=0)
    lines.legend(fontsize=7, ncol=2)
    labels = [series_label(c) for c in cells]
    means = [c["frame_ms"]["mean"] for c in cells]
    low = [c["frame_ms"]["mean"] - c["frame_ms"]["p5"] for c in cells]
    high = [c["frame_ms"]["p95"] - c["frame_ms"]["mean"] for c in cells]
    positions = list(range(len(cells)))
    bars.barh(positions, means, xerr=[[max(v, 0) for v in low], [max(v, 0) for v in high]], color="tab:blue",
              alpha=0.8, error_kw={"linewidth": 0.8, "capsize": 2})
    bars.set_yticks(positions)
    bars.set_yticklabels(labels, fontsize=7)
    bars.invert_yaxis()
    style_axes(bars, "mean (p5-p95)", "frame time (ms)", "")
    fig.suptitle(setting_text(summary), fontsize=8, x=0.99, ha="right")
    save(fig, out_dir, figure)
    return True


def plot_fig12(summary, out_dir):
    cells = done_cells(summary, "fig12")
    if not cells:
        return False
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2), sharey=True)
    for ax, deform, title in ((axes[0], False, "(a) static"), (axes[1], True, "(b) deforming")):
        for cell in (c for c in cells if c["deform"] == deform):
            xs, ys = interval_series(cell)
            ax.plot(xs, ys, color=MODE_COLOURS.get(cell["reflections"]), linewidth=1.2,
                    marker="." if len(xs) < 30 else None, label=cell["reflections"])
        style_axes(ax, "Fig. 12 " + title, "walkthrough frame", "frame time (ms)")
        if ax.lines:
            ax.legend(fontsize=8)
    # Once both panels hold their lines: the shared axis then spans both (setting it on the first
    # panel alone froze its top at the static panel's data and cut the deforming curves).
    axes[0].set_ylim(bottom=0)
    fig.suptitle(setting_text(summary), fontsize=8, x=0.99, ha="right")
    save(fig, out_dir, "fig12")
    return True


def plot_fig11(summary, out_dir):
    points = [p for p in summary.get("fig11", []) if p["render_ms"] is not None]
    if not points:
        return False
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for measured, marker, legend in ((True, "o", "rebuild every frame (deforming cell)"),
                                     (False, "s", "whole build (static cell; no rebuild cell)")):
        chosen = [p for p in points if (p["rebuild_ms"] is not None) == measured and
                  (measured or p["build_ms"] is not None)]
        if not chosen:
            continue
        xs = [p["rebuild_ms"] if measured else p["build_ms"] for p in chosen]
        ys = [p["render_ms"] for p in chosen]
        ax.scatter(xs, ys, marker=marker, s=36, color="tab:blue" if measured else "tab:orange", label=legend,
                   zorder=3)
        for x, y, p in zip(xs, ys, chosen):
            ax.annotate(p["structure"], (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
    style_axes(ax, "Fig. 11: rebuild time against render time", "rebuild time (ms)",
               "render time: mean frame time, static (ms)")
    if ax.collections:
        ax.set_xlim(left=0)
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=7, loc="best")
    fig.suptitle(setting_text(summary), fontsize=8, x=0.99, ha="right")
    save(fig, out_dir, "fig11")
    return True


FLOOR_COLOURS = {"#": (0.55, 0.55, 0.55), "d": (0.80, 0.35, 0.10)}


def plot_fig4(summary, out_dir):
    plan = summary.get("floor_plan")
    if not plan:
        return False
    grid = plan["grid"]
    rows, columns, cell = grid["rows"], grid["columns"], grid["cell"]
    x0, z0 = grid["origin"]
    image = [[(1.0, 1.0, 1.0) for _ in range(columns)] for _ in range(rows)]
    for r, line in enumerate(grid["cells"]):
        for c, value in enumerate(line):
            if value in FLOOR_COLOURS:
                image[r][c] = FLOOR_COLOURS[value]
    extent = (x0, x0 + columns * cell, z0 + rows * cell, z0)  # z grows down the page, as a top view
    width = 11.0
    height = max(2.5, min(9.0, width * rows / max(columns, 1) + 1.2))
    fig, ax = plt.subplots(figsize=(width, height))
    ax.imshow(image, extent=extent, interpolation="nearest")
    camera, light = plan["camera"], plan["light"]
    ax.plot([p[0] for p in camera], [p[1] for p in camera], color="tab:blue", linewidth=1.4, label="camera path")
    ax.plot([p[0] for p in light], [p[1] for p in light], color="gold", linewidth=1.4, linestyle="--",
            label="light path")
    if camera:
        ax.plot(camera[0][0], camera[0][1], marker="o", color="tab:blue", markersize=5)
    for letter, mark in zip("abcdefgh", plan["marked_frames"]):
        (cx, cz), (tx, tz) = mark["camera"], mark["target"]
        ax.annotate("", xy=(cx + 0.15 * (tx - cx), cz + 0.15 * (tz - cz)), xytext=(cx, cz),
                    arrowprops={"arrowstyle": "->", "color": "tab:red", "linewidth": 1.2})
        ax.plot(cx, cz, marker="o", color="tab:red", markersize=4)
        ax.annotate("({}) {}".format(letter, mark["frame"]), (cx, cz), textcoords="offset points", xytext=(4, -10),
                    fontsize=7, color="tab:red")
    ax.plot([], [], color=FLOOR_COLOURS["#"], linewidth=6, label="geometry at walking height")
    ax.plot([], [], color=FLOOR_COLOURS["d"], linewidth=6, label="deforming meshes")
    style_axes(ax, "Fig. 4: floor plan of {} with the camera path".format(plan["scene"]), "x", "z")
    ax.set_aspect("equal")
    ax.legend(fontsize=7, loc="upper right", ncol=2)
    save(fig, out_dir, "fig4")
    return True


def plot_quality(summary, table, title, out_dir):
    cells = done_cells(summary, table)
    if not cells:
        return False
    rows = cells[0]["rows"]
    frames = sorted({r["frame"] for r in rows})
    fig, (buckets, ssim) = plt.subplots(1, 2, figsize=(10, 3.8))
    width = 0.38
    for offset, mode in ((-width / 2, "ssr"), (width / 2, "hybrid")):
        values = {r["frame"]: r for r in rows if r["mode"] == mode}
        xs = [i + offset for i in range(len(frames))]
        buckets.bar(xs, [values[f]["buckets_percent"]["mean"] for f in frames], width, label=mode,
                    color=MODE_COLOURS[mode])
        ssim.bar(xs, [values[f]["ssim_luma"] for f in frames], width, label=mode, color=MODE_COLOURS[mode])
    for ax, name in ((buckets, "colour buckets (%)"), (ssim, "SSIM (luma)")):
        ax.set_xticks(range(len(frames)))
        ax.set_xticklabels([str(f) for f in frames])
        style_axes(ax, title if ax is buckets else "structural similarity", "frame", name)
        ax.legend(fontsize=8, loc="lower right")
    low = min(min(r["buckets_percent"]["mean"] for r in rows), 95.0)
    buckets.set_ylim(low - 1.0, 100.5)
    ssim.set_ylim(min(min(r["ssim_luma"] for r in rows), 0.9) - 0.02, 1.005)
    fig.suptitle(setting_text(summary), fontsize=8, x=0.99, ha="right")
    save(fig, out_dir, table)
    return True


def plot_adaptive(summary, out_dir):
    """--experiment adaptive: quality against reflection cost per scene, the Pareto front joined."""
    scenes = summary.get("scenes", [])
    if summary.get("experiment") != "adaptive" or not scenes:
        return False
    fig, axes = plt.subplots(2, len(scenes), figsize=(max(8.0, 5.5 * len(scenes)), 8), squeeze=False)
    for column, scene in enumerate(scenes):
        configs = scene["configs"]
        for row, (key, label) in enumerate((("ssim", "SSIM vs rt (luma)"), ("psnr_db", "PSNR vs rt (dB)"))):
            ax = axes[row][column]
            for point in configs:
                colour = MODE_COLOURS.get(point["reflections"], "tab:gray")
                ax.scatter(point["reflection_ms"], point[key], color=colour, s=40, zorder=3)
                ax.annotate(point["label"], (point["reflection_ms"], point[key]), textcoords="offset points",
                            xytext=(4, 4), fontsize=8)
            front = sorted((p for p in configs if p["pareto"]), key=lambda p: p["reflection_ms"])
            ax.plot([p["reflection_ms"] for p in front], [p[key] for p in front], color="black", linewidth=1,
                    linestyle="--", label="Pareto front (SSIM)", zorder=2)
            style_axes(ax, scene["scene"], "reflection cost (ms: SSR + ray list + trace + hit shade)", label)
            if row == 0 and column == 0:
                ax.legend(fontsize=8)
    s = summary["settings"]
    fig.suptitle("Reflection quality against cost ({}x{}, {} backend, {})".format(
        s["width"], s["height"], s["backend"], summary["environment"]["gl"]["renderer"]))
    save(fig, out_dir, "adaptive")
    return True


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: python3 plot_bench.py DIR  (DIR holds summary.json from glint bench)\n")
        return 2
    folder = argv[1]
    with open(os.path.join(folder, "summary.json")) as file:
        summary = json.load(file)
    out_dir = os.path.join(folder, "charts")
    os.makedirs(out_dir, exist_ok=True)
    if plot_adaptive(summary, out_dir):
        print("charts: adaptive")
        return 0
    made = []
    for figure, title in FRAME_FIGURES.items():
        if plot_frame_figure(summary, figure, title, out_dir):
            made.append(figure)
    if plot_fig11(summary, out_dir):
        made.append("fig11")
    if plot_fig12(summary, out_dir):
        made.append("fig12")
    if plot_fig4(summary, out_dir):
        made.append("fig4")
    for table, title in QUALITY_TABLES.items():
        if plot_quality(summary, table, title, out_dir):
            made.append(table)
    print("charts: " + (", ".join(made) if made else "none (no finished cells)"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
