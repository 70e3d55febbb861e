#!/usr/bin/env python3
"""Speed against accuracy, from `raster tradeoff`'s tradeoff.json.

x: speed-up over llvmpipe (log scale); y: PSNR of the final image against llvmpipe (dB),
and in a second row against the `precise` preset (the most accurate methods).
Points identical to llvmpipe have no PSNR (it is infinite): they are drawn on a marked
ceiling above the highest finite value. One labelled point per method set, llvmpipe and
softpipe as drivers, the Pareto front (no point both faster and closer) as a line, and the
40 dB line the `fast` preset must stay above. One column per scene (per size, per result).

--metric flip puts the mean LDR-FLIP error (compare/flip.h: 0 no visible difference, 1 the
most) on the y axis instead: log scale, smaller errors higher up, so "up" still reads "more
accurate"; identical images (FLIP 0) sit on a marked line above the smallest error, and the
Pareto front is the one FLIP makes (the JSON's "pareto" is PSNR's). Results written before
FLIP was measured have no FLIP: the chart says so and exits 2.

Usage: tradeoff_chart.py RESULT.json [RESULT.json ...] --out PREFIX [--metric psnr|flip]
writes PREFIX.png and PREFIX.svg, each complete or not at all (written beside, then renamed).
A RESULT.json holds one scene's object, or a list of them (`raster tradeoff all`).
A file that is not one, or a PREFIX whose folder takes no files, exits 2 naming it.
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from chart_files import write_atomically  # noqa: E402
from input_checks import NUMBER, OPTIONAL, BadInput, check_output_path, check_record, fail, read_json  # noqa: E402

PROG = "tradeoff_chart"

FAST_THRESHOLD_DB = 40.0
KIND_STYLE = {
    "preset": dict(marker="o", color="#1f77b4", s=60),
    "method": dict(marker="s", color="#7f7f7f", s=36),
    "driver": dict(marker="D", color="#d62728", s=60),
}


def load_results(paths, metric):
    """Every scene's result in paths, the fields the chart reads checked (METRICS[metric]'s)."""
    point_fields = {"name": str, "kind": str, "speedup_vs_llvmpipe": NUMBER}
    point_fields.update({field: OPTIONAL(NUMBER) for field, _ in METRICS[metric]["fields"]})
    results = []
    for path in paths:
        data = read_json(PROG, path, "a tradeoff result")
        for result in data if isinstance(data, list) else [data]:
            try:
                check_record(result, {"scene": str, "points": list}, "")
                if not result["points"]:
                    raise BadInput(f"{result['scene']}: no points")
                for i, point in enumerate(result["points"]):
                    if metric == "flip" and "flip_vs_llvmpipe" not in point:
                        fail(PROG, f"{path}: {result['scene']}: the result has no FLIP (written before it was "
                                   "measured); run raster tradeoff again or chart --metric psnr")
                    check_record(point, point_fields, f"{result['scene']} point {i}")
                    if not point["speedup_vs_llvmpipe"] > 0:
                        raise BadInput(f"{result['scene']} point {i}: 'speedup_vs_llvmpipe' is not above 0")
            except BadInput as e:
                fail(PROG, f"{path}: not a tradeoff result ({e})")
            results.append(result)
    if not results:
        fail(PROG, "no results to draw")
    return results


# What the y axis shows: the fields of the two rows, and how a value reads.
METRICS = {
    "psnr": dict(fields=(("psnr_vs_llvmpipe_db", "llvmpipe"), ("psnr_vs_precise_db", "precise"))),
    "flip": dict(fields=(("flip_vs_llvmpipe", "llvmpipe"), ("flip_vs_precise", "precise"))),
}


def flip_floor_of(results, field):
    """Where FLIP 0 (identical) is drawn: a third of the smallest error measured."""
    positive = [p[field] for r in results for p in r["points"] if p[field] is not None and p[field] > 0]
    return (min(positive) if positive else 1e-3) / 3.0


def flip_pareto(xs, ys):
    """No other point at least as fast with at most the error, and better in one of the two."""
    return [not any(j != i and xs[j] >= xs[i] and ys[j] <= ys[i] and (xs[j] > xs[i] or ys[j] < ys[i])
                    for j in range(len(xs))) for i in range(len(xs))]


def draw_flip_panel(ax, result, floor, field, reference):
    """One scene's points with the mean FLIP in `field` against `reference` on the y axis."""
    points = result["points"]
    xs = [p["speedup_vs_llvmpipe"] for p in points]
    values = [p[field] for p in points]
    ys = [floor if v is None or v <= 0 else v for v in values]
    against_llvmpipe = reference == "llvmpipe"
    front = flip_pareto(xs, ys)
    for p, x, y, on_front in zip(points, xs, ys, front):
        style = KIND_STYLE.get(p["kind"], KIND_STYLE["method"])
        edge = "black" if against_llvmpipe and on_front else "none"
        ax.scatter([x], [y], zorder=3, edgecolors=edge, linewidths=1.2, **style)
    line = sorted((x, y) for x, y, f in zip(xs, ys, front) if f)
    if against_llvmpipe and len(line) > 1:
        ax.plot([f[0] for f in line], [f[1] for f in line], color="black", linewidth=1, linestyle="--", zorder=2)
    ax.axhline(floor, color="#2ca02c", linewidth=0.8)
    ax.text(0.01, floor, f" identical to {reference}", color="#2ca02c", fontsize=7, va="bottom",
            transform=ax.get_yaxis_transform())
    ax.set_xscale("log")
    ax.set_yscale("log")
    lo, hi = min(xs), max(xs)
    ax.set_xlim(lo / 1.5, hi * 1.6)
    ax.set_ylim(max(ys + [floor]) * 2.0, floor / 2.0)   # inverted: smaller errors higher up
    label_points(ax, [p["name"] for p in points], xs, ys)
    size = result.get("size", ["?", "?"])
    ax.set_title(f"{result['scene']} {size[0]}x{size[1]}, t={result.get('time')}, {result.get('threads')} threads: "
                 f"against {reference}", fontsize=9)
    ax.set_xlabel("speed-up over llvmpipe (x, log scale)", fontsize=8)
    ax.set_ylabel(f"mean FLIP of the final image vs {reference} (log, 0 best)", fontsize=8)
    ax.grid(True, which="both", linewidth=0.3)
    ax.tick_params(labelsize=7)


def ceiling_of(results, field):
    finite = [p[field] for r in results for p in r["points"] if p[field] is not None]
    top = max(finite + [FAST_THRESHOLD_DB])
    return 10.0 * math.ceil((top + 8.0) / 10.0)


def draw_panel(ax, result, ceiling, field, reference):
    """One scene's points: y is the PSNR in `field` against `reference` (llvmpipe: with the
    Pareto front and the fast preset's floor; precise: how near each point is to the most
    accurate methods)."""
    points = result["points"]
    xs = [p["speedup_vs_llvmpipe"] for p in points]
    ys = [ceiling if p[field] is None else p[field] for p in points]
    against_llvmpipe = reference == "llvmpipe"
    for p, x, y in zip(points, xs, ys):
        style = KIND_STYLE.get(p["kind"], KIND_STYLE["method"])
        edge = "black" if against_llvmpipe and p.get("pareto") else "none"
        ax.scatter([x], [y], zorder=3, edgecolors=edge, linewidths=1.2, **style)
    front = sorted((x, y) for p, x, y in zip(points, xs, ys) if p.get("pareto"))
    if against_llvmpipe and len(front) > 1:
        ax.plot([f[0] for f in front], [f[1] for f in front], color="black", linewidth=1, linestyle="--",
                zorder=2, label="Pareto front")
    ax.axhline(ceiling, color="#2ca02c", linewidth=0.8)
    ax.text(0.01, ceiling, f" identical to {reference}", color="#2ca02c", fontsize=7, va="bottom",
            transform=ax.get_yaxis_transform())
    if against_llvmpipe:
        ax.axhline(FAST_THRESHOLD_DB, color="#ff7f0e", linewidth=0.8, linestyle=":")
        ax.text(0.01, FAST_THRESHOLD_DB, f" {FAST_THRESHOLD_DB:.0f} dB (fast preset floor)", color="#ff7f0e",
                fontsize=7, va="bottom", transform=ax.get_yaxis_transform())
    ax.set_xscale("log")
    lo, hi = min(xs), max(xs)
    ax.set_xlim(lo / 1.5, hi * 1.6)
    ax.set_ylim(min(ys + [FAST_THRESHOLD_DB]) - 8, ceiling + 6)
    label_points(ax, [p["name"] for p in points], xs, ys)
    size = result.get("size", ["?", "?"])
    ax.set_title(f"{result['scene']} {size[0]}x{size[1]}, t={result.get('time')}, {result.get('threads')} threads: "
                 f"against {reference}", fontsize=9)
    ax.set_xlabel("speed-up over llvmpipe (x, log scale)", fontsize=8)
    ax.set_ylabel(f"PSNR of the final image vs {reference} (dB)", fontsize=8)
    ax.grid(True, which="both", linewidth=0.3)
    ax.tick_params(labelsize=7)


def label_points(ax, names, xs, ys):
    """Labels every point; points that land close together (method sets of about the same
    speed and accuracy) get their labels stacked in one column beside the first, so none
    hides another."""
    to_axes = ax.transData + ax.transAxes.inverted()
    placed = []  # (axes x, axes y, labels stacked there so far)
    order = sorted(range(len(names)), key=lambda i: (-ys[i], xs[i]))
    for i in order:
        ax_x, ax_y = to_axes.transform((xs[i], ys[i]))
        for k, (px, py, count) in enumerate(placed):
            if abs(px - ax_x) < 0.06 and abs(py - ax_y) < 0.06:
                ax.annotate(names[i], (xs[i], ys[i]), xycoords="data", textcoords="offset points",
                            xytext=(6, 3 - 9 * count), fontsize=6.5,
                            arrowprops=dict(arrowstyle="-", color="#bbbbbb", linewidth=0.5))
                placed[k] = (px, py, count + 1)
                break
        else:
            ax.annotate(names[i], (xs[i], ys[i]), textcoords="offset points", xytext=(6, 3), fontsize=6.5)
            placed.append((ax_x, ax_y, 1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", nargs="+", help="tradeoff.json files")
    parser.add_argument("--out", required=True, help="output prefix: PREFIX.png and PREFIX.svg")
    parser.add_argument("--metric", choices=sorted(METRICS), default="psnr",
                        help="accuracy on the y axis: PSNR (dB, default) or the mean LDR-FLIP error")
    args = parser.parse_args()
    results = load_results(args.results, args.metric)
    check_output_path(PROG, "--out", args.out)
    # Rows of up to three scenes: each scene against llvmpipe, and below it against precise.
    columns = min(3, len(results))
    scene_rows = math.ceil(len(results) / columns)
    fig, axes = plt.subplots(2 * scene_rows, columns, figsize=(5.2 * columns, 4.2 * 2 * scene_rows), squeeze=False)
    for row_offset, (field, reference) in enumerate(METRICS[args.metric]["fields"]):
        for k, result in enumerate(results):
            ax = axes[2 * (k // columns) + row_offset][k % columns]
            if args.metric == "flip":
                draw_flip_panel(ax, result, flip_floor_of(results, field), field, reference)
            else:
                draw_panel(ax, result, ceiling_of(results, field), field, reference)
    for k in range(len(results), scene_rows * columns):
        axes[2 * (k // columns)][k % columns].axis("off")
        axes[2 * (k // columns) + 1][k % columns].axis("off")
    handles = [plt.Line2D([], [], linestyle="", marker=s["marker"], color=s["color"], label=k)
               for k, s in KIND_STYLE.items()]
    handles.append(plt.Line2D([], [], color="black", linestyle="--", label="Pareto front (outlined points)"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    for ext in ("png", "svg"):
        write_atomically(fig, f"{args.out}.{ext}")


if __name__ == "__main__":
    main()
