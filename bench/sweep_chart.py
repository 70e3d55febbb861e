#!/usr/bin/env python3
"""Error against a scene parameter, from `raster sweep`'s sweep.json.

x: the swept parameter (log scale when the sweep was); y: PSNR of the final image against
llvmpipe (dB). One line per side (each method set, and softpipe: GL against GL); points
identical to llvmpipe have no PSNR (it is infinite) and are drawn on a marked ceiling above
the highest finite value. The failure threshold is a dashed line; each side's first failing
value is marked with a red X (a final image below the threshold, or a non-finite pixel); a
value where llvmpipe itself holds non-finite pixels gets a grey band, since there GL is
broken too.

--metric flip puts the final image's mean LDR-FLIP error against llvmpipe (compare/flip.h:
0 no visible difference, 1 the most) on the y axis instead; identical points read 0 and the
dB threshold is not drawn (failure is still PSNR's, as sweep.json says). A sweep written
before FLIP was measured has none: the chart says so and exits 2.

Usage: sweep_chart.py SWEEP.json --out PREFIX [--metric psnr|flip]
writes PREFIX.png and PREFIX.svg, each complete or not at all (written beside, then renamed).
A file that is not a sweep.json, or a PREFIX whose folder takes no files, exits 2 naming it.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from chart_files import write_atomically  # noqa: E402
from input_checks import (NUMBER, OPTIONAL, BadInput, check_each, check_output_path, check_range,  # noqa: E402
                          check_record, fail, read_json)

PROG = "sweep_chart.py"
# The fields the chart reads, of the sweep and of each point (raster sweep writes more).
SWEEP_FIELDS = {"points": list, "param": str, "scene": str, "threshold_db": NUMBER, "range": dict, "size": list,
                "time": NUMBER}
POINT_FIELDS = {"method": str, "value": NUMBER, "value_index": int, "fails": bool, "nonfinite_pixels": int,
                "psnr_vs_llvmpipe_db": OPTIONAL(NUMBER), "identical_to_llvmpipe": bool}

# The ranges a sweep.json's numbers can take (raster writes null for a PSNR that is not
# finite: identical images, drawn on the ceiling). A PSNR of raster's images, 8-bit, depth or
# float, stays within about +-1,000 dB; the limit leaves room, and keeps the y axis far from
# where matplotlib overflows (near 1e308). The threshold is raster sweep's --threshold, any
# finite number: one past the limit is named at the axis's edge (draw). A swept value is a
# scene parameter (`raster params`: +-1e30 at most); a log axis overflows from about 1e300.
# FLIP is an error in 0..1.
DB_LIMIT = 1e4
VALUE_LIMIT = 1e100

# softpipe (GL against GL) in grey, outside the colours the method sets take in turn (the
# fourth of which, C3, is the red it had, which draft took) and apart from the red crosses.
STYLE = {"softpipe": dict(color="#555555", linestyle="--", marker="D")}


def load(path, flip):
    """The sweep in path, its fields checked (and each point's FLIP where flip is charted)."""
    sweep = read_json(PROG, path, "a sweep.json")
    try:
        check_record(sweep, SWEEP_FIELDS, "")
        check_record(sweep["range"], {"log": bool}, "'range'")
        if len(sweep["size"]) != 2 or not all(isinstance(n, int) and n > 0 for n in sweep["size"]):
            raise BadInput("'size' is not [width, height]")
        check_each(sweep["points"], POINT_FIELDS, "point")
        for i, point in enumerate(sweep["points"]):
            check_range(point, "psnr_vs_llvmpipe_db", -DB_LIMIT, DB_LIMIT, f"point {i}")
            if sweep["range"]["log"]:
                check_range(point, "value", 0, VALUE_LIMIT, f"point {i}", above=True, why="the sweep is on a log scale")
            else:
                check_range(point, "value", -VALUE_LIMIT, VALUE_LIMIT, f"point {i}")
    except BadInput as e:
        fail(PROG, f"{path}: not a sweep.json ({e})")
    if flip:
        if any("flip_vs_llvmpipe" not in p for p in sweep["points"]):
            fail(PROG, f"{path}: the sweep has no FLIP (written before it was measured); "
                       "run raster sweep again or chart --metric psnr")
        try:
            for i, point in enumerate(sweep["points"]):
                check_record(point, {"flip_vs_llvmpipe": OPTIONAL(NUMBER)}, f"point {i}")
                check_range(point, "flip_vs_llvmpipe", 0, 1, f"point {i}", why="FLIP's range")
        except BadInput as e:
            fail(PROG, f"{path}: not a sweep.json ({e})")
    return sweep


def setting(sweep):
    """The base size and time the sweep records, as sweep.md states them: not the one it moves."""
    w, h = sweep["size"]
    size = "each width at 4:3" if sweep["param"] == "size" else f"{w}x{h}"
    time = "each value's time" if sweep["param"] == "time" else f"t={sweep['time']:g}"
    return f"{size}, {time}"


def legend_label(side, points, drawn):
    """The side's name, and where its line lies on another's at every value, which: the
    legend is where a reader can tell such lines apart. drawn maps each series of values
    already drawn (a tuple) to its side, and takes this side's."""
    series = tuple((p["identical_to_llvmpipe"], p["psnr_vs_llvmpipe_db"], p.get("flip_vs_llvmpipe")) for p in points)
    if points and all(p["identical_to_llvmpipe"] for p in points):
        return f"{side} (identical at every value)"
    if series in drawn:
        return f"{side} (the same as {drawn[series]} at every value)"
    drawn[series] = side
    return side


def mark_failures(ax, failures, below, top):
    """A red X at each side's first failure, (side, value, y); one label a value, naming every
    side that first fails there (labels of sides failing at one value would print over each
    other), beside the lowest (below=True) or highest of their crosses: under it, or over it
    where that would run past the y axis's end (0 or top)."""
    for side, value, y in failures:
        ax.plot([value], [y], marker="x", color="red", markersize=12, markeredgewidth=2.5, linestyle="none")
    for value in dict.fromkeys(v for _, v, _ in failures):
        here = [(side, y) for side, v, y in failures if v == value]
        names = ", ".join(side for side, _ in here)
        y = min(y for _, y in here) if below else max(y for _, y in here)
        under = y > 0.15 * top if below else y > 0.85 * top
        ax.annotate(f"{names} fail{'s' if len(here) == 1 else ''}\n{value:.4g}", (value, y),
                    textcoords="offset points", xytext=(6, -24) if under else (6, 6), fontsize=8, color="red")


def draw_flip(sweep):
    points = sweep["points"]
    sides = [p["method"] for p in points if p["value_index"] == points[0]["value_index"]] if points else []
    fig, ax = plt.subplots(figsize=(8.5, 5))
    top = 0.0
    failures, drawn = [], {}
    for side in sides:
        if side == "llvmpipe":
            continue
        mine = [p for p in points if p["method"] == side]
        xs = [p["value"] for p in mine]
        ys = [p["flip_vs_llvmpipe"] if p["flip_vs_llvmpipe"] is not None else float("nan") for p in mine]
        top = max([top] + [y for y in ys if y == y])
        style = STYLE.get(side, dict(marker="o"))
        ax.plot(xs, ys, label=legend_label(side, mine, drawn), markersize=4, linewidth=1.4, **style)
        first = next((p for p in mine if p["fails"]), None)
        if first is not None and first["flip_vs_llvmpipe"] is not None:
            failures.append((side, first["value"], first["flip_vs_llvmpipe"]))
    ax.set_ylim(bottom=0, top=max(top * 1.15, 1e-3))
    mark_failures(ax, failures, below=False, top=max(top * 1.15, 1e-3))
    for p in points:
        if p["method"] == "llvmpipe" and p["nonfinite_pixels"] > 0:
            ax.axvline(p["value"], color="#bbbbbb", linewidth=6, alpha=0.5, zorder=0)
    if sweep["range"]["log"]:
        ax.set_xscale("log")
    ax.set_xlabel(sweep["param"])
    ax.set_ylabel("final image mean FLIP against llvmpipe (0: identical)")
    ax.set_title(f"{sweep['scene']}: {sweep['param']} swept, {setting(sweep)}; "
                 f"red X: first failure (< {sweep['threshold_db']:g} dB or non-finite)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    return fig


def draw(sweep):
    points = sweep["points"]
    sides = [p["method"] for p in points if p["value_index"] == points[0]["value_index"]] if points else []
    finite = [p["psnr_vs_llvmpipe_db"] for p in points if p["psnr_vs_llvmpipe_db"] is not None]
    threshold = sweep["threshold_db"]
    # A threshold past DB_LIMIT, beyond any PSNR, is named at the axis's edge rather than
    # stretching the axis to it (a --threshold of 1e5 squashed every line flat; near 1e308 the
    # axis overflows).
    on_axis = abs(threshold) <= DB_LIMIT
    marks = finite + ([threshold] if on_axis else [])
    ceiling = max(marks) + 10 if finite else max(marks, default=0) + 20
    fig, ax = plt.subplots(figsize=(8.5, 5))
    failures, drawn = [], {}
    for side in sides:
        if side == "llvmpipe":
            continue
        mine = [p for p in points if p["method"] == side]
        xs = [p["value"] for p in mine]
        ys = [ceiling if p["psnr_vs_llvmpipe_db"] is None else p["psnr_vs_llvmpipe_db"] for p in mine]
        style = STYLE.get(side, dict(marker="o"))
        ax.plot(xs, ys, label=legend_label(side, mine, drawn), markersize=4, linewidth=1.4, **style)
        first = next((p for p in mine if p["fails"]), None)
        if first is not None:
            failures.append((side, first["value"], ceiling if first["psnr_vs_llvmpipe_db"] is None
                             else first["psnr_vs_llvmpipe_db"]))
    mark_failures(ax, failures, below=True, top=ceiling + 8)
    for p in points:
        if p["method"] == "llvmpipe" and p["nonfinite_pixels"] > 0:
            ax.axvline(p["value"], color="#bbbbbb", linewidth=6, alpha=0.5, zorder=0)
    if on_axis:
        ax.axhline(threshold, color="black", linestyle=":", linewidth=1)
        ax.text(0.01, threshold, f" fails below {threshold:g} dB", transform=ax.get_yaxis_transform(), va="bottom",
                fontsize=8)
    else:
        above = threshold > 0
        ax.text(0.01, 0.97 if above else 0.03, f" fails below {threshold:g} dB ({'above' if above else 'below'} the axis)",
                transform=ax.transAxes, va="top" if above else "bottom", fontsize=8)
    ax.axhline(ceiling, color="#999999", linewidth=0.8)
    ax.text(0.01, ceiling, " identical to llvmpipe", transform=ax.get_yaxis_transform(), va="bottom", fontsize=8,
            color="#555555")
    if sweep["range"]["log"]:
        ax.set_xscale("log")
    # From 0, or below the lowest PSNR or threshold where one is negative (a float image's can be).
    lowest = min(marks, default=0)
    ax.set_ylim(bottom=0 if lowest >= 0 else lowest - 8, top=ceiling + 8)
    ax.set_xlabel(sweep["param"])
    ax.set_ylabel("final image PSNR against llvmpipe (dB)")
    ax.set_title(f"{sweep['scene']}: {sweep['param']} swept, {setting(sweep)}"
                 + (" (grey: llvmpipe has non-finite pixels)" if any(
                     p["method"] == "llvmpipe" and p["nonfinite_pixels"] > 0 for p in points) else ""), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep")
    parser.add_argument("--out", required=True, help="PREFIX: writes PREFIX.png and PREFIX.svg")
    parser.add_argument("--metric", choices=("psnr", "flip"), default="psnr",
                        help="accuracy on the y axis: PSNR (dB, default) or the mean LDR-FLIP error")
    args = parser.parse_args()
    sweep = load(args.sweep, args.metric == "flip")
    check_output_path(PROG, "--out", args.out, suffixes=(".png", ".svg"))
    fig = draw_flip(sweep) if args.metric == "flip" else draw(sweep)
    for ext in ("png", "svg"):
        write_atomically(fig, f"{args.out}.{ext}")


if __name__ == "__main__":
    main()
