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
from input_checks import (NUMBER, OPTIONAL, BadInput, check_each, check_output_path, check_record, fail,  # noqa: E402
                          read_json)

PROG = "sweep_chart.py"
# The fields the chart reads, of the sweep and of each point (raster sweep writes more).
SWEEP_FIELDS = {"points": list, "param": str, "scene": str, "threshold_db": NUMBER, "range": dict, "size": list,
                "time": NUMBER}
POINT_FIELDS = {"method": str, "value": NUMBER, "value_index": int, "fails": bool, "nonfinite_pixels": int,
                "psnr_vs_llvmpipe_db": OPTIONAL(NUMBER)}

STYLE = {"softpipe": dict(color="#d62728", linestyle="--", marker="D")}


def load(path, flip):
    """The sweep in path, its fields checked (and each point's FLIP where flip is charted)."""
    sweep = read_json(PROG, path, "a sweep.json")
    try:
        check_record(sweep, SWEEP_FIELDS, "")
        check_record(sweep["range"], {"log": bool}, "'range'")
        if len(sweep["size"]) != 2 or not all(isinstance(n, int) and n > 0 for n in sweep["size"]):
            raise BadInput("'size' is not [width, height]")
        check_each(sweep["points"], POINT_FIELDS, "point")
    except BadInput as e:
        fail(PROG, f"{path}: not a sweep.json ({e})")
    if flip:
        if any("flip_vs_llvmpipe" not in p for p in sweep["points"]):
            fail(PROG, f"{path}: the sweep has no FLIP (written before it was measured); "
                       "run raster sweep again or chart --metric psnr")
        try:
            for i, point in enumerate(sweep["points"]):
                check_record(point, {"flip_vs_llvmpipe": OPTIONAL(NUMBER)}, f"point {i}")
        except BadInput as e:
            fail(PROG, f"{path}: not a sweep.json ({e})")
    return sweep


def draw_flip(sweep):
    points = sweep["points"]
    sides = [p["method"] for p in points if p["value_index"] == points[0]["value_index"]] if points else []
    fig, ax = plt.subplots(figsize=(8.5, 5))
    top = 0.0
    for side in sides:
        if side == "llvmpipe":
            continue
        mine = [p for p in points if p["method"] == side]
        xs = [p["value"] for p in mine]
        ys = [p["flip_vs_llvmpipe"] if p["flip_vs_llvmpipe"] is not None else float("nan") for p in mine]
        top = max([top] + [y for y in ys if y == y])
        style = STYLE.get(side, dict(marker="o"))
        ax.plot(xs, ys, label=side, markersize=4, linewidth=1.4, **style)
        first = next((p for p in mine if p["fails"]), None)
        if first is not None and first["flip_vs_llvmpipe"] is not None:
            y = first["flip_vs_llvmpipe"]
            ax.plot([first["value"]], [y], marker="x", color="red", markersize=12, markeredgewidth=2.5, linestyle="none")
            ax.annotate(f"{side} fails\n{first['value']:.4g}", (first["value"], y), textcoords="offset points",
                        xytext=(6, 6), fontsize=8, color="red")
    for p in points:
        if p["method"] == "llvmpipe" and p["nonfinite_pixels"] > 0:
            ax.axvline(p["value"], color="#bbbbbb", linewidth=6, alpha=0.5, zorder=0)
    if sweep["range"]["log"]:
        ax.set_xscale("log")
    ax.set_ylim(bottom=0, top=max(top * 1.15, 1e-3))
    ax.set_xlabel(sweep["param"])
    ax.set_ylabel("final image mean FLIP against llvmpipe (0: identical)")
    w, h = sweep["size"]
    ax.set_title(f"{sweep['scene']}: {sweep['param']} swept, {w}x{h}, t={sweep['time']:g}; "
                 f"red X: first failure (< {sweep['threshold_db']:g} dB or non-finite)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    return fig


def draw(sweep):
    points = sweep["points"]
    sides = [p["method"] for p in points if p["value_index"] == points[0]["value_index"]] if points else []
    finite = [p["psnr_vs_llvmpipe_db"] for p in points if p["psnr_vs_llvmpipe_db"] is not None]
    ceiling = max(finite + [sweep["threshold_db"]]) + 10 if finite else sweep["threshold_db"] + 20
    fig, ax = plt.subplots(figsize=(8.5, 5))
    for side in sides:
        if side == "llvmpipe":
            continue
        mine = [p for p in points if p["method"] == side]
        xs = [p["value"] for p in mine]
        ys = [ceiling if p["psnr_vs_llvmpipe_db"] is None else p["psnr_vs_llvmpipe_db"] for p in mine]
        style = STYLE.get(side, dict(marker="o"))
        ax.plot(xs, ys, label=side, markersize=4, linewidth=1.4, **style)
        first = next((p for p in mine if p["fails"]), None)
        if first is not None:
            y = ceiling if first["psnr_vs_llvmpipe_db"] is None else first["psnr_vs_llvmpipe_db"]
            ax.plot([first["value"]], [y], marker="x", color="red", markersize=12, markeredgewidth=2.5, linestyle="none")
            ax.annotate(f"{side} fails\n{first['value']:.4g}", (first["value"], y), textcoords="offset points",
                        xytext=(6, -24), fontsize=8, color="red")
    for p in points:
        if p["method"] == "llvmpipe" and p["nonfinite_pixels"] > 0:
            ax.axvline(p["value"], color="#bbbbbb", linewidth=6, alpha=0.5, zorder=0)
    ax.axhline(sweep["threshold_db"], color="black", linestyle=":", linewidth=1)
    ax.text(0.01, sweep["threshold_db"], f" fails below {sweep['threshold_db']:g} dB", transform=ax.get_yaxis_transform(),
            va="bottom", fontsize=8)
    ax.axhline(ceiling, color="#999999", linewidth=0.8)
    ax.text(0.01, ceiling, " identical to llvmpipe", transform=ax.get_yaxis_transform(), va="bottom", fontsize=8,
            color="#555555")
    if sweep["range"]["log"]:
        ax.set_xscale("log")
    ax.set_ylim(bottom=0, top=ceiling + 8)
    ax.set_xlabel(sweep["param"])
    ax.set_ylabel("final image PSNR against llvmpipe (dB)")
    w, h = sweep["size"]
    ax.set_title(f"{sweep['scene']}: {sweep['param']} swept, {w}x{h}, t={sweep['time']:g}"
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
    check_output_path(PROG, "--out", args.out)
    fig = draw_flip(sweep) if args.metric == "flip" else draw(sweep)
    for ext in ("png", "svg"):
        write_atomically(fig, f"{args.out}.{ext}")


if __name__ == "__main__":
    main()
