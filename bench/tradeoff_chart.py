#!/usr/bin/env python3
"""Speed against accuracy, from `raster tradeoff`'s tradeoff.json.

x: speed-up over llvmpipe (log scale); y: PSNR of the final image against llvmpipe (dB),
and in a second row against the `precise` preset (the most accurate methods).
Points identical to llvmpipe have no PSNR (it is infinite): they are drawn on a marked
ceiling above the highest finite value. One labelled point per method set (points drawn on
one another share a label naming them all; labels are placed where they overlap nothing),
llvmpipe and softpipe as drivers, the Pareto front (no point both faster and closer) as a
line, and the 40 dB line the `fast` preset must stay above. The speed-up axis spans the
presets, the methods and llvmpipe: a driver far slower (softpipe) is drawn at its left end
as an arrow, its speed-up in its label. One column per scene (per size, per result), up to
four a row.

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
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import NullFormatter  # noqa: E402
from matplotlib.transforms import Bbox  # noqa: E402

from chart_files import write_atomically  # noqa: E402
from input_checks import (NUMBER, OPTIONAL, BadInput, check_output_path, check_range, check_record, fail,  # noqa: E402
                          read_json)

PROG = "tradeoff_chart"

# The ranges a result's numbers can take (raster writes null for a PSNR that is not finite:
# identical images, drawn on the ceiling). A speed-up is a ratio of two frames' medians: past
# 1e9 either way, one frame took under a nanosecond against the other's second (and the axis's
# ticks overflow near 1e308). A PSNR of raster's images stays within about +-1,000 dB, the limit
# leaving room; FLIP is an error in 0..1.
SPEEDUP_LIMIT = 1e9
DB_LIMIT = 1e4
# The most results one chart draws: `raster tradeoff all` writes one per scene, four today. 32
# is already sixteen rows of panels (two a row of scenes) and some 25 s of drawing; much further the figure grows past
# what matplotlib draws (2^16 pixels a side, at about 240).
MAX_RESULTS = 32

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
                    where = f"{result['scene']} point {i}"
                    check_record(point, point_fields, where)
                    if not point["speedup_vs_llvmpipe"] > 0:
                        raise BadInput(f"{where}: 'speedup_vs_llvmpipe' is not above 0")
                    check_range(point, "speedup_vs_llvmpipe", 1 / SPEEDUP_LIMIT, SPEEDUP_LIMIT, where)
                    for field, _ in METRICS[metric]["fields"]:
                        if metric == "flip":
                            check_range(point, field, 0, 1, where, why="FLIP's range")
                        else:
                            check_range(point, field, -DB_LIMIT, DB_LIMIT, where)
            except BadInput as e:
                fail(PROG, f"{path}: not a tradeoff result ({e})")
            results.append(result)
    if not results:
        fail(PROG, "no results to draw")
    if len(results) > MAX_RESULTS:
        fail(PROG, f"{len(results)} results: more than the {MAX_RESULTS} one chart draws (chart fewer files)")
    return results


# What the y axis shows: the fields of the two rows, and how a value reads.
METRICS = {
    "psnr": dict(fields=(("psnr_vs_llvmpipe_db", "llvmpipe"), ("psnr_vs_precise_db", "precise"))),
    "flip": dict(fields=(("flip_vs_llvmpipe", "llvmpipe"), ("flip_vs_precise", "precise"))),
}


def set_speed_axis(ax, lo, hi):
    """A log axis from lo to hi with its speed-ups written out (0.5, 1, 2, 3, 5, 10, ...): the
    span is about a decade, where a log axis's own ticks would name only 10^0."""
    ax.set_xscale("log")
    ax.set_xlim(lo, hi)
    decades = range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)
    ticks = [t for t in (round(m * 10.0 ** e, 12) for e in decades for m in (1, 2, 3, 5)) if lo <= t <= hi]
    ax.set_xticks(ticks, [f"{t:g}" for t in ticks])
    ax.xaxis.set_minor_formatter(NullFormatter())


def scatter_point(ax, point, x, y, outlined, off_scale):
    """One point in its kind's style, outlined where it is on the Pareto front; a point off
    the axis's left end is drawn there as an arrow pointing left."""
    style = dict(KIND_STYLE.get(point["kind"], KIND_STYLE["method"]))
    if off_scale:
        style["marker"] = "<"
    ax.scatter([x], [y], zorder=3, edgecolors="black" if outlined else "none", linewidths=1.2, clip_on=False,
               **style)


def point_label(point, off_scale):
    """A point's name; off the axis, with the speed-up its place no longer shows."""
    return f"{point['name']} ({point['speedup_vs_llvmpipe']:.2g}x)" if off_scale else point["name"]


def flip_floor_of(results, field):
    """Where FLIP 0 (identical) is drawn: a third of the smallest error measured."""
    positive = [p[field] for r in results for p in r["points"] if p[field] is not None and p[field] > 0]
    return (min(positive) if positive else 1e-3) / 3.0


def flip_pareto(xs, ys):
    """No other point at least as fast with at most the error, and better in one of the two."""
    return [not any(j != i and xs[j] >= xs[i] and ys[j] <= ys[i] and (xs[j] > xs[i] or ys[j] < ys[i])
                    for j in range(len(xs))) for i in range(len(xs))]


def draw_flip_panel(ax, result, floor, field, reference):
    """One scene's points with the mean FLIP in `field` against `reference` on the y axis; returns
    their labels and where they are drawn (names, xs, ys) for label_points."""
    points = result["points"]
    xs = [p["speedup_vs_llvmpipe"] for p in points]
    values = [p[field] for p in points]
    ys = [floor if v is None or v <= 0 else v for v in values]
    against_llvmpipe = reference == "llvmpipe"
    front = flip_pareto(xs, ys)
    lo, hi, off_scale = x_range(xs, [p["kind"] for p in points])
    for p, x, y, on_front, off in zip(points, xs, ys, front, off_scale):
        scatter_point(ax, p, lo if off else x, y, against_llvmpipe and on_front, off)
    line = sorted((x, y) for x, y, f in zip(xs, ys, front) if f)
    if against_llvmpipe and len(line) > 1:
        ax.plot([f[0] for f in line], [f[1] for f in line], color="black", linewidth=1, linestyle="--", zorder=2)
    ax.axhline(floor, color="#2ca02c", linewidth=0.8)
    ax.text(0.01, floor, f" identical to {reference}", color="#2ca02c", fontsize=7, va="bottom",
            transform=ax.get_yaxis_transform())
    set_speed_axis(ax, lo, hi)
    ax.set_yscale("log")
    ax.set_ylim(max(ys + [floor]) * 2.0, floor / 2.0)   # inverted: smaller errors higher up
    size = result.get("size", ["?", "?"])
    ax.set_title(f"{result['scene']} {size[0]}x{size[1]}, t={result.get('time')}, {result.get('threads')} threads: "
                 f"against {reference}", fontsize=9)
    ax.set_xlabel("speed-up over llvmpipe (x, log scale)", fontsize=8)
    ax.set_ylabel(f"mean FLIP of the final image vs {reference} (log, 0 best)", fontsize=8)
    ax.grid(True, which="both", linewidth=0.3)
    ax.tick_params(labelsize=7)
    return ([point_label(p, off) for p, off in zip(points, off_scale)],
            [lo if off else x for x, off in zip(xs, off_scale)], ys)


def ceiling_of(results, field):
    finite = [p[field] for r in results for p in r["points"] if p[field] is not None]
    top = max(finite + [FAST_THRESHOLD_DB])
    return 10.0 * math.ceil((top + 8.0) / 10.0)


def draw_panel(ax, result, ceiling, field, reference):
    """One scene's points: y is the PSNR in `field` against `reference` (llvmpipe: with the
    Pareto front and the fast preset's floor; precise: how near each point is to the most
    accurate methods). Returns the labels and where they are drawn, as draw_flip_panel does."""
    points = result["points"]
    xs = [p["speedup_vs_llvmpipe"] for p in points]
    ys = [ceiling if p[field] is None else p[field] for p in points]
    against_llvmpipe = reference == "llvmpipe"
    lo, hi, off_scale = x_range(xs, [p["kind"] for p in points])
    for p, x, y, off in zip(points, xs, ys, off_scale):
        scatter_point(ax, p, lo if off else x, y, against_llvmpipe and p.get("pareto"), off)
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
    set_speed_axis(ax, lo, hi)
    ax.set_ylim(min(ys + [FAST_THRESHOLD_DB]) - 8, ceiling + 6)
    size = result.get("size", ["?", "?"])
    ax.set_title(f"{result['scene']} {size[0]}x{size[1]}, t={result.get('time')}, {result.get('threads')} threads: "
                 f"against {reference}", fontsize=9)
    ax.set_xlabel("speed-up over llvmpipe (x, log scale)", fontsize=8)
    ax.set_ylabel(f"PSNR of the final image vs {reference} (dB)", fontsize=8)
    ax.grid(True, which="both", linewidth=0.3)
    ax.tick_params(labelsize=7)
    return ([point_label(p, off) for p, off in zip(points, off_scale)],
            [lo if off else x for x, off in zip(xs, off_scale)], ys)


def label_offsets():
    """Where a label may go, in points from its point, nearest first: beside it on the
    right, then on the left, then ever further up or down on either side."""
    yield 6, 3
    yield -6, 3
    for step in range(1, 16):
        for dy in (3 - 11 * step, 3 + 11 * step):
            yield 6, dy
            yield -6, dy


def coincident_groups(centres, within):
    """Points whose centres lie within `within` pixels of the group's first, in order: they
    are drawn on one another, so they share one label."""
    groups = []
    for i, (x, y) in enumerate(centres):
        for group in groups:
            gx, gy = centres[group[0]]
            if abs(gx - x) <= within and abs(gy - y) <= within:
                group.append(i)
                break
        else:
            groups.append([i])
    return groups


def label_points(ax, names, xs, ys):
    """Labels every point where it overlaps no other label and no point: the first free
    place of label_offsets() inside the panel, with a grey leader where it is not beside its
    point (where none is free, beside it on the right). Points drawn on one another share a
    label that names them all. Called once the figure's layout is final, since it measures
    the labels on the canvas."""
    renderer = ax.figure.canvas.get_renderer()
    panel = ax.get_window_extent(renderer)
    pixels = ax.figure.dpi / 72.0   # pixels a point
    centres = [tuple(ax.transData.transform((x, y))) for x, y in zip(xs, ys)]
    radius = 4.0 * pixels   # a marker's half width
    taken = [Bbox.from_bounds(cx - radius, cy - radius, 2 * radius, 2 * radius) for cx, cy in centres]
    taken += [text.get_window_extent(renderer) for text in ax.texts]   # the reference lines' names
    groups = coincident_groups(centres, radius / 2)
    # Most accurate first, then fastest: the ceiling's labels are the ones read first.
    for group in sorted(groups, key=lambda g: (-ys[g[0]], xs[g[0]])):
        i, (cx, cy) = group[0], centres[group[0]]
        text = textwrap.fill(", ".join(names[k] for k in group), 44)
        # The text's size, measured once; each place's box follows from its offset and alignment.
        probe = ax.annotate(text, (xs[i], ys[i]), textcoords="offset points", xytext=(6, 3), fontsize=6.5)
        width, height = probe.get_window_extent(renderer).size
        probe.remove()
        for dx, dy in label_offsets():
            beside = dy == 3
            x0 = cx + dx * pixels - (0 if dx > 0 else width)   # ha: left on the right, right on the left
            y0 = cy + dy * pixels - (0 if beside else height / 2)   # va: bottom beside, else centre
            box = Bbox.from_bounds(x0, y0, width, height)
            inside = panel.x0 <= box.x0 and box.x1 <= panel.x1 and panel.y0 <= box.y0 and box.y1 <= panel.y1
            if inside and not any(box.overlaps(other) for other in taken):
                ax.annotate(text, (xs[i], ys[i]), textcoords="offset points", xytext=(dx, dy), fontsize=6.5,
                            ha="left" if dx > 0 else "right", va="bottom" if beside else "center",
                            arrowprops=None if beside else dict(arrowstyle="-", color="#bbbbbb", linewidth=0.5))
                taken.append(box)
                break
        else:
            ax.annotate(text, (xs[i], ys[i]), textcoords="offset points", xytext=(6, 3), fontsize=6.5)
            taken.append(Bbox.from_bounds(cx + 6 * pixels, cy + 3 * pixels, width, height))


def x_range(xs, kinds):
    """The speed-up axis: every preset and method, and 1 (llvmpipe). A driver far slower than
    those (softpipe, 20-170 times slower than llvmpipe) would squeeze them into the right
    edge of a log axis; it is drawn at the left edge instead (off_scale), labelled with its
    speed-up."""
    main = [x for x, kind in zip(xs, kinds) if kind != "driver"] + [1.0]
    lo, hi = min(main) / 1.5, max(xs) * 1.6
    return lo, hi, [x < lo for x in xs]


def figure(results, metric):
    """The chart of results (load_results') under metric, labelled and laid out."""
    # Rows of up to four scenes, as even as they go (four: one row; five: three and two): each
    # scene against llvmpipe, and below it against precise.
    scene_rows = math.ceil(len(results) / 4)
    columns = math.ceil(len(results) / scene_rows)
    fig, axes = plt.subplots(2 * scene_rows, columns, figsize=(5.2 * columns, 4.2 * 2 * scene_rows), squeeze=False)
    labels = []   # (panel, its points' labels and places), placed once the layout is final
    for row_offset, (field, reference) in enumerate(METRICS[metric]["fields"]):
        for k, result in enumerate(results):
            ax = axes[2 * (k // columns) + row_offset][k % columns]
            if metric == "flip":
                labels.append((ax, draw_flip_panel(ax, result, flip_floor_of(results, field), field, reference)))
            else:
                labels.append((ax, draw_panel(ax, result, ceiling_of(results, field), field, reference)))
    for k in range(len(results), scene_rows * columns):
        axes[2 * (k // columns)][k % columns].axis("off")
        axes[2 * (k // columns) + 1][k % columns].axis("off")
    handles = [plt.Line2D([], [], linestyle="", marker=s["marker"], color=s["color"], label=k)
               for k, s in KIND_STYLE.items()]
    handles.append(plt.Line2D([], [], color="black", linestyle="--", label="Pareto front (outlined points)"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    for ax, (names, xs, ys) in labels:
        label_points(ax, names, xs, ys)
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", nargs="+", help="tradeoff.json files")
    parser.add_argument("--out", required=True, help="output prefix: PREFIX.png and PREFIX.svg")
    parser.add_argument("--metric", choices=sorted(METRICS), default="psnr",
                        help="accuracy on the y axis: PSNR (dB, default) or the mean LDR-FLIP error")
    args = parser.parse_args()
    results = load_results(args.results, args.metric)
    check_output_path(PROG, "--out", args.out, suffixes=(".png", ".svg"))
    fig = figure(results, args.metric)
    for ext in ("png", "svg"):
        write_atomically(fig, f"{args.out}.{ext}")


if __name__ == "__main__":
    main()
