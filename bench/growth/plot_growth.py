"""Draws the growth benchmark's chart from the tables fb89_growth writes (bench/growth).

Usage: /usr/bin/python3 bench/growth/plot_growth.py FOLDER
Reads FOLDER/growth.csv and FOLDER/growth_slopes.csv, writes FOLDER/growth.png: on the left
each method's CPU time (load + set-up + hidden-surface, and hidden-surface alone) against
faces, on the right its peak resident memory with the loaded scene's own size, both log-log,
each line labelled with its fitted slope over the top three rungs. The OBJ rung is drawn as
open markers.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.dont_write_bytecode = True  # nothing written beside the scripts
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from output_file import save  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def slope_of(slopes, method, quantity):
    for s in slopes:
        if s["source"] == "generator" and s["method"] == method and s["quantity"] == quantity:
            return float(s["slope_top"])
    return float("nan")


def main(folder):
    rows = [r for r in read(os.path.join(folder, "growth.csv")) if r["ok"] == "1"]
    slopes = read(os.path.join(folder, "growth_slopes.csv"))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12.5, 5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, method in enumerate(methods):
        color = colors[k % len(colors)]
        gen = [r for r in rows if r["method"] == method and r["source"] == "generator"]
        obj = [r for r in rows if r["method"] == method and r["source"] == "obj"]
        faces = [int(r["faces"]) for r in gen]
        total = [float(r["total_ms"]) / 1e3 for r in gen]
        hidden = [float(r["hidden_surface_ms"]) / 1e3 for r in gen]
        peak = [int(r["peak_rss_bytes"]) / 2**20 for r in gen]
        left.plot(faces, total, "o-", color=color,
                  label=f"{method}: total ~ F^{slope_of(slopes, method, 'total_ms'):.2f}")
        left.plot(faces, hidden, "s:", color=color, alpha=0.7,
                  label=f"{method}: hidden-surface ~ F^{slope_of(slopes, method, 'hidden_surface_ms'):.2f}")
        right.plot(faces, peak, "o-", color=color,
                   label=f"{method}: peak ~ F^{slope_of(slopes, method, 'peak_rss'):.2f}")
        if obj:
            left.plot([int(r["faces"]) for r in obj], [float(r["total_ms"]) / 1e3 for r in obj],
                      "o", mfc="none", color=color, markersize=10)
            right.plot([int(r["faces"]) for r in obj], [int(r["peak_rss_bytes"]) / 2**20 for r in obj],
                       "o", mfc="none", color=color, markersize=10)
    scene = {int(r["faces"]): int(r["scene_bytes"]) / 2**20 for r in rows if r["source"] == "generator"}
    xs = sorted(scene)
    right.plot(xs, [scene[x] for x in xs], "k--",
               label=f"input (loaded scene) ~ F^{slope_of(slopes, methods[0], 'scene_bytes'):.2f}")
    for ax, title, unit in ((left, "CPU time (open: top rung read from OBJ)", "s"),
                            (right, "peak resident memory (open: top rung from OBJ)", "MiB")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("faces")
        ax.set_ylabel(unit)
        ax.set_title(title)
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Growth: terrain ladder at 1024x780, slopes fitted over the top three rungs")
    fig.tight_layout()
    save(fig, os.path.join(folder, "growth.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
