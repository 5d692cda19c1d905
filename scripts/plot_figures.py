"""Draws fb89's charts from the CSV files that `fb89 experiment` writes.

Usage: /usr/bin/python3 scripts/plot_figures.py FOLDER
Reads FOLDER/fig2_1.csv and FOLDER/fig2_4.csv, writes FOLDER/fig2_1.png and fig2_4.png.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.dont_write_bytecode = True  # nothing written beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from output_file import save  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def scene_label(path):
    return os.path.splitext(os.path.basename(path))[0]


def fig2_1(folder):
    rows = read(os.path.join(folder, "fig2_1.csv"))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    width = 0.8 / len(methods)
    for k, method in enumerate(methods):
        ms = [float(r["hs_cpu_ms"]) for s in scenes for r in rows if r["scene"] == s and r["method"] == method]
        ctl = [float(r["controller_ms"]) for s in scenes for r in rows if r["scene"] == s and r["method"] == method]
        xs = [i + (k - (len(methods) - 1) / 2) * width for i in range(len(scenes))]
        left.bar(xs, ms, width, label=method)
        right.bar(xs, ctl, width, label=method)
    for ax, title, unit in ((left, "host hidden-surface time (median CPU)", "ms"),
                            (right, "modelled controller time (tms34010-50mhz)", "ms")):
        ax.set_xticks(range(len(scenes)))
        ax.set_xticklabels([scene_label(s) for s in scenes])
        ax.set_yscale("log")
        ax.set_ylabel(unit)
        ax.set_title(title)
        ax.grid(axis="y", which="both", alpha=0.3)
    left.legend()
    fig.suptitle("Fig. 2.1 re-run: Warnock, scan-line and Z-buffer at 1024x780")
    fig.tight_layout()
    save(fig, os.path.join(folder, "fig2_1.png"))


def fig2_4(folder):
    rows = read(os.path.join(folder, "fig2_4.csv"))
    real = [r for r in rows if not r["scene"].startswith("ideal")]
    ideal = [r for r in rows if r["scene"].startswith("ideal")]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    xs = range(len(real))
    left.bar([x - 0.27 for x in xs], [float(r["predicted"]) for r in real], 0.27, label="Eq. 2.4 predicted")
    left.bar(xs, [float(r["measured_area"]) for r in real], 0.27, label="measured, area test")
    left.bar([x + 0.27 for x in xs], [float(r["measured_centres"]) for r in real], 0.27,
             label="measured, centres test")
    left.set_xticks(list(xs))
    left.set_xticklabels([scene_label(r["scene"]) for r in real])
    left.set_yscale("log")
    left.set_ylabel("window samples")
    left.set_title("scenes A-F (E_s = sqrt(WH), F_v = F/D)")
    left.legend()
    left.grid(axis="y", which="both", alpha=0.3)
    for d in sorted({r["depth_complexity"] for r in ideal}, key=float):
        sub = [r for r in ideal if r["depth_complexity"] == d]
        fv = [float(r["f_v"]) for r in sub]
        right.plot(fv, [float(r["measured_area"]) for r in sub], "o", label=f"measured, D={d}")
        right.plot(fv, [float(r["measured_centres"]) for r in sub], "x", label=f"centres test, D={d}")
    sub = [r for r in ideal if r["depth_complexity"] == ideal[0]["depth_complexity"]]
    right.plot([float(r["f_v"]) for r in sub], [float(r["predicted"]) for r in sub], "-", color="black",
               label="Eq. 2.4")
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel("visible faces F_v")
    right.set_ylabel("window samples")
    right.set_title("ideal scenes, 512x512")
    right.legend(fontsize=8)
    right.grid(which="both", alpha=0.3)
    fig.suptitle("Fig. 2.4 re-run: predicted and actual window samples")
    fig.tight_layout()
    save(fig, os.path.join(folder, "fig2_4.png"))


def threshold_value(text):
    return float("inf") if text == "inf" else float(text)


def fig3_1(folder):
    rows = read(os.path.join(folder, "fig3_1.csv"))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        sub = [r for r in rows if r["scene"] == scene]
        finite = [r for r in sub if 0 < threshold_value(r["threshold"]) < float("inf")]
        zero = [r for r in sub if threshold_value(r["threshold"]) == 0][0]
        ax.plot([float(r["threshold"]) for r in finite], [float(r["hs_cpu_ms"]) for r in finite], "o-",
                label="hybrid")
        ax.axhline(float(zero["hs_cpu_ms"]), color="gray", linestyle="--", label="threshold 0 (Z-buffer)")
        ax.axvline(0.04, color="red", linestyle=":", label="paper's 0.04")
        ax.set_xscale("log")
        ax.set_xlabel("threshold on Expr. 3.1")
        ax.set_ylabel("hidden-surface ms (median CPU)")
        ax.set_title(f"scene {scene_label(scene)}")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Fig. 3.1 re-run: hybrid rendering time vs threshold, 1024x780")
    fig.tight_layout()
    save(fig, os.path.join(folder, "fig3_1.png"))

    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        sub = [r for r in rows if r["scene"] == scene and 0 < threshold_value(r["threshold"]) < float("inf")]
        t = [float(r["threshold"]) for r in sub]
        ax.plot(t, [float(r["hs_cpu_ms"]) for r in sub], "o-", label="host hidden-surface (measured)")
        ax.plot(t, [float(r["controller_ms"]) for r in sub], "s-", label="controller busy (modelled)")
        ax.plot(t, [float(r["bus_ms"]) for r in sub], "^-", label="bus busy (modelled)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("threshold on Expr. 3.1")
        ax.set_ylabel("ms per frame")
        ax.set_title(f"scene {scene_label(scene)}: host vs tms34010-50mhz controller")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(folder, "split.png"))


def accuracy(folder):
    rows = read(os.path.join(folder, "accuracy.csv"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    # the depth-command methods' pixels are ties of the profile's depth word (older CSVs
    # have neither the methods nor the column)
    for method, marker in (("warnock", "o"), ("hybrid", "s"), ("zspans", "^"), ("faces", "v")):
        sub = [r for r in rows if r["method"] == method]
        if not sub:
            continue
        bits = sub[0].get("depth_bits", "")
        label = f"{method} ({bits}-bit depth word: ties)" if bits else method
        wrong = [max(float(r["fraction_wrong"]), 1e-7) for r in sub]
        left.scatter([float(r["ratio_to_zbuffer"]) for r in sub], wrong, marker=marker, label=label)
        right.scatter([float(r["controller_ms"]) for r in sub], wrong, marker=marker, label=label)
    for ax, xlabel in ((left, "host time / Z-buffer time"), (right, "controller ms (modelled)")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("fraction of pixels wrong (exact settings drawn at 1e-7)")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Speed against accuracy on scenes A-F: approximate fills, and the depth word's ties")
    fig.tight_layout()
    save(fig, os.path.join(folder, "accuracy.png"))


def fig4_8(folder):
    """Figs. 4.8, 4.11 and §4's image I: whole-process time against resolution."""
    rows = []
    for name in ("fig4_8.csv", "fig4_11.csv", "fig4_12.csv"):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            rows += read(path)
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.5 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for method, marker in (("raytrace", "o"), ("beam", "s")):
            sub = [r for r in rows if r["scene"] == scene and r["method"] == method]
            pixels = [int(r["width"]) * int(r["height"]) for r in sub]
            label = "ray tracer alone" if method == "raytrace" else "beam-ray hybrid"
            ax.plot(pixels, [float(r["e2e_cpu_ms"]) for r in sub], marker + "-", label=label)
            if method == "beam":
                for x, r in zip(pixels, sub):
                    ax.annotate(f"{float(r['pixels_by_beams_pct']):.0f}% beams", (x, float(r["e2e_cpu_ms"])),
                                textcoords="offset points", xytext=(4, -12), fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
        ax.set_xticks([int(r["width"]) * int(r["height"]) for r in rows if r["scene"] == scene and r["method"] == "beam"])
        ax.set_xticklabels([f"{r['width']}x{r['height']}" for r in rows if r["scene"] == scene and r["method"] == "beam"],
                           fontsize=7)
        ax.set_xlabel("resolution")
        ax.set_ylabel("ms, reading the scene to the last command (median CPU)")
        ax.set_title(f"image {scene_label(scene)}")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Figs. 4.8 and 4.11 re-run: rendering time vs resolution")
    fig.tight_layout()
    save(fig, os.path.join(folder, "fig4_8.png"))


def beam_threshold(folder):
    rows = read(os.path.join(folder, "beam_threshold.csv"))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    for scene in scenes:
        sub = [r for r in rows if r["scene"] == scene and r["threshold"] not in ("raytrace", "inf")
               and float(r["threshold"]) > 0]
        t = [float(r["threshold"]) for r in sub]
        line, = left.plot(t, [float(r["ratio_to_raytrace"]) for r in sub], "o-", label=scene_label(scene))
        inf = [r for r in rows if r["scene"] == scene and r["threshold"] == "inf"]
        if inf:
            left.axhline(float(inf[0]["ratio_to_raytrace"]), color=line.get_color(), linestyle=":", linewidth=1)
        right.plot(t, [float(r["pixels_by_beams_pct"]) for r in sub], "o-", label=scene_label(scene))
    left.axhline(1.0, color="gray", linestyle="--", label="ray tracer alone")
    left.set_ylabel("hidden-surface time / ray tracer's (dotted: threshold inf)")
    right.set_ylabel("% of pixels decided by beams")
    for ax in (left, right):
        ax.set_xscale("log")
        ax.set_xlabel("threshold on Expr. 2.7")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Beam-ray hybrid against its threshold, 1024x780 (every frame equals the ray tracer's)")
    fig.tight_layout()
    save(fig, os.path.join(folder, "beam_threshold.png"))


def ff_error(folder):
    """§5: form-factor and radiosity error against time per method."""
    rows = read(os.path.join(folder, "radiosity_error.csv"))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, 2, figsize=(14, 6.4))
    for column, ax, label in (("ff_error", axes[0], "form-factor error (area-weighted mean |F - F_ref| row sum)"),
                              ("radiosity_rms_error", axes[1], "radiosity error (relative RMS)")):
        # the form-factor panel times the form factors; the radiosity panel every stage
        # (form factors and solve; the adaptive mesh and the hierarchy whole)
        time = "cpu_ms" if column == "ff_error" else "total_cpu_ms"
        labels = []  # (x, y, method), placed once the axes are drawn
        for scene, marker in zip(scenes, "os^v"):
            # a solve that diverged has no error to chart (the table says so)
            sub = [r for r in rows if r["scene"] == scene and r[column] and r.get(time, "")
                   and not (column == "radiosity_rms_error" and r["converged"].startswith("NO"))]
            points = ax.scatter([float(r[time]) for r in sub], [float(r[column]) for r in sub], marker=marker,
                                label=scene_label(scene))
            # one curve per method family: the hemicube's resolutions, the adaptive
            # thresholds, the hierarchy's epsilons
            for family in ("hemicube", "adaptive", "hierarchical"):
                series = sorted((float(r[time]), float(r[column])) for r in sub if r["method"].startswith(family))
                if len(series) > 1:
                    ax.plot([x for x, _ in series], [y for _, y in series], color=points.get_facecolor()[0],
                            linewidth=0.8, alpha=0.6)
            labels += [(float(r[time]), float(r[column]), r["method"]) for r in sub]
        ref = [float(r["reference_error"]) for r in rows]
        if ref:
            ax.axhline(max(ref), color="gray", linestyle=":", linewidth=1) if column == "ff_error" else None
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("form-factor time, ms (median CPU)" if column == "ff_error"
                      else "time to the solution, ms (median CPU)")
        ax.set_ylabel(label)
        ax.grid(which="both", alpha=0.3)
        # where each panel has no points
        ax.legend(fontsize=8, loc="upper left" if column == "ff_error" else "lower left")
        fig.tight_layout()
        place_labels(ax, labels)
    fig.suptitle("Speed against accuracy in radiosity (dotted: the reference's own error estimate)")
    fig.tight_layout()
    save(fig, os.path.join(folder, "radiosity_error.png"))


def place_labels(ax, labels, fontsize=7):
    """Labels points so that no two labels overlap, nor a label the legend: points within a
    few pixels of each other share one label ("flux, hybrid"), and each label takes the first
    of several positions around its point that is free, else the least crowded one."""
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    to_pixels = ax.transData.transform
    groups = []  # [pixel position, (x, y), names]
    for x, y, name in labels:
        px = to_pixels((x, y))
        for g in groups:
            if abs(g[0][0] - px[0]) < 6 and abs(g[0][1] - px[1]) < 6:
                if name not in g[2]:
                    g[2].append(name)
                break
        else:
            groups.append([px, (x, y), [name]])
    legend = ax.get_legend()
    taken = [legend.get_window_extent(renderer)] if legend else []
    points = [g[0] for g in groups]
    offsets = [(4, 3, "left", "bottom"), (4, -3, "left", "top"), (-4, 3, "right", "bottom"),
               (-4, -3, "right", "top"), (0, 7, "center", "bottom"), (0, -7, "center", "top"),
               (10, 10, "left", "bottom"), (10, -10, "left", "top"), (-10, 10, "right", "bottom"),
               (-10, -10, "right", "top"), (16, 0, "left", "center"), (-16, 0, "right", "center")]
    for r in (22, 34, 48):  # farther out, with a leader line
        offsets += [(r, r // 2, "left", "bottom"), (r, -r // 2, "left", "top"),
                    (-r, r // 2, "right", "bottom"), (-r, -r // 2, "right", "top"),
                    (0, r, "center", "bottom"), (0, -r, "center", "top")]
    # the crowded ones first, so that they get the first choice of room
    order = sorted(range(len(groups)), key=lambda i: -sum(
        abs(points[i][0] - p[0]) < 60 and abs(points[i][1] - p[1]) < 20 for p in points))
    for i in order:
        _, (x, y), names = groups[i]
        best = None
        for dx, dy, ha, va in offsets:
            leader = dict(arrowstyle="-", color="gray", linewidth=0.5) if abs(dx) + abs(dy) > 30 else None
            text = ax.annotate(", ".join(names), (x, y), textcoords="offset points", xytext=(dx, dy),
                               ha=ha, va=va, fontsize=fontsize, arrowprops=leader)
            box = text.get_window_extent(renderer).expanded(1.05, 1.1)
            inside = ax.get_window_extent(renderer)
            outside = not (inside.x0 <= box.x0 and box.x1 <= inside.x1 and inside.y0 <= box.y0
                           and box.y1 <= inside.y1)
            clashes = sum(box.overlaps(t) for t in taken) + sum(
                box.contains(p[0], p[1]) for k, p in enumerate(points) if k != i) + 2 * outside
            if best is None or clashes < best[0]:
                if best is not None:
                    best[1].remove()
                best = (clashes, text, box)
            else:
                text.remove()
            if clashes == 0:
                break
        taken.append(best[2])


def split_both_sides(folder):
    """experiment split on a 1989 host: host time per frame against the controller's."""
    rows = read(os.path.join(folder, "split.csv"))
    host = rows[0]["host"]
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, ax = plt.subplots(figsize=(7.5, 6))
    for method in methods:
        sub = [r for r in rows if r["method"] == method]
        ax.scatter([float(r["controller_ms"]) for r in sub], [float(r["host_frame_ms"]) for r in sub],
                   label=method, s=22)
    lo = min(min(float(r["controller_ms"]), float(r["host_frame_ms"])) for r in rows) / 2
    hi = max(max(float(r["controller_ms"]), float(r["host_frame_ms"])) for r in rows) * 2
    ax.plot([lo, hi], [lo, hi], color="gray", linestyle="--", label="host = controller")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("controller frame time, tms34010-50mhz (modelled ms)")
    ax.set_ylabel(f"host set-up + hidden-surface, {host} (modelled ms)")
    ax.set_title(f"The split in one era: {host} host vs TMS34010 controller\n"
                 "every method on every bundled scene; above the line the host bounds the frame")
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(folder, "split_both_sides.png"))


# The 1989 hosts of the split across hosts, oldest first: the first is the one speeds and
# crossovers are counted in multiples of.
HOSTS_1989 = ("sun3-60", "sun4-260", "sparcstation-1", "sparcstation-2", "pc-386-25")
HOST_LABELS = {"sun3-60": "Sun-3/60\n1987", "sun4-260": "Sun-4/260\n1987",
               "sparcstation-1": "SPARCstation 1\n1989", "sparcstation-2": "SPARCstation 2\n1990",
               "pc-386-25": "386/25 PC\n1988",
               "native": "this machine\n(measured)"}


def split_hosts(root):
    """The split across hosts: the Sun-3/60, the Sun-4/260, the SPARCstations 1 and 2 and this
    machine (experiment split on each), host time against controller time and the pipeline
    in time; per method the host speed, in multiples of the Sun-3/60, at which the frame
    stops being host-bound -- at the controller's estimates and over their band -- beside
    each host's own speed-up, how many scenes it bounds, how far the pipeline's frame lies
    over max(host, controller) and the controller's utilization. Writes ROOT/split_hosts.csv
    and ROOT/split_hosts.png."""
    sources = [(host, os.path.join(root, host, "split.csv")) for host in HOSTS_1989] + \
        [("native", os.path.join(root, "split_native.csv"))]
    tables = {host: read(path) for host, path in sources if os.path.exists(path)}
    if "sun3-60" not in tables or len(tables) < 2:
        return
    key = lambda r: (scene_label(r["scene"]), r["method"])  # noqa: E731
    base = {key(r): r for r in tables["sun3-60"]}
    methods = list(dict.fromkeys(r["method"] for r in tables["sun3-60"]))
    median = lambda v: sorted(v)[len(v) // 2] if v else float("nan")  # noqa: E731
    # host over controller: at the controller's estimates, and at the ends of its band (the
    # controller at its dear end gives the low ratio); the band's columns come with the
    # pipeline (experiment split on a 1989 host)
    ratio = lambda r: float(r["host_frame_ms"]) / float(r["controller_ms"])  # noqa: E731
    banded = all("host_over_controller_low" in r for r in tables["sun3-60"])
    # the pipeline's frame over max(host, controller), at the estimates and at the band's dear
    # end, in percent
    over = lambda r, col: 100 * (float(r[col]) / float(r["frame_ms"]) - 1)  # noqa: E731
    rows = []
    for method in methods:
        cells = [k for k in base if k[1] == method]
        # the multiple of the Sun-3/60's host speed at which host time = controller time
        cross = [ratio(base[k]) for k in cells]
        row = {"method": method, "scenes": len(cells),
               "crossover_median": f"{median(cross):.3g}", "crossover_min": f"{min(cross):.3g}",
               "crossover_max": f"{max(cross):.3g}"}
        if banded:
            low = [float(base[k]["host_over_controller_low"]) for k in cells]
            high = [float(base[k]["host_over_controller_high"]) for k in cells]
            row.update({"crossover_median_low": f"{median(low):.3g}",
                        "crossover_median_high": f"{median(high):.3g}",
                        "crossover_min_low": f"{min(low):.3g}",
                        "crossover_max_high": f"{max(high):.3g}"})
        for host in HOSTS_1989 + ("native",):
            if host not in tables:
                continue
            other = {key(r): r for r in tables[host]}
            mine = [other[k] for k in cells if k in other]
            if host != "sun3-60":
                speed = [float(base[k]["host_frame_ms"]) / float(other[k]["host_frame_ms"])
                         for k in cells if k in other and float(other[k]["host_frame_ms"]) > 0]
                row[f"{host}_speed_median"] = f"{median(speed):.3g}"
            row[f"{host}_host_bound"] = f"{sum(r['bound_by'] == 'host' for r in mine)}/{len(cells)}"
            if "pipeline_ms" in (mine[0] if mine else {}):
                near = min(mine, key=lambda r: abs(math.log(ratio(r))))
                row[f"{host}_ratio_median"] = f"{median([ratio(r) for r in mine]):.3g}"
                row[f"{host}_nearest_scene"] = scene_label(near["scene"])
                row[f"{host}_nearest_ratio"] = f"{ratio(near):.3g}"
                if "host_over_controller_low" in near:
                    row[f"{host}_nearest_ratio_low"] = near["host_over_controller_low"]
                    row[f"{host}_nearest_ratio_high"] = near["host_over_controller_high"]
                    row[f"{host}_host_bound_band"] = \
                        f"{sum(float(r['host_over_controller_low']) > 1 for r in mine)}-" \
                        f"{sum(float(r['host_over_controller_high']) > 1 for r in mine)}/" \
                        f"{len(cells)}"
                row[f"{host}_over_max_median_pct"] = \
                    f"{median([over(r, 'pipeline_ms') for r in mine]):.2f}"
                row[f"{host}_over_max_max_pct"] = f"{max(over(r, 'pipeline_ms') for r in mine):.2f}"
                if "pipeline_ms_high" in near:
                    row[f"{host}_over_max_dear_pct"] = \
                        f"{max(over(r, 'pipeline_ms_high') for r in mine):.2f}"
                utils = [100 * float(r["controller_util"]) for r in mine]
                row[f"{host}_controller_util_median_pct"] = f"{median(utils):.3g}"
                row[f"{host}_controller_util_range_pct"] = f"{min(utils):.3g}-{max(utils):.3g}"
        rows.append(row)
    fields = list(dict.fromkeys(f for r in rows for f in r))
    text = ",".join(fields) + "\n" + "".join(
        ",".join(str(r.get(f, "")) for f in fields) + "\n" for r in rows)
    write_text(os.path.join(root, "split_hosts.csv"), text)

    # per method, each host's host/controller ratio over the scenes (median, the scenes' range
    # as a bar and, thinner, that range widened by the controller's band), the hosts in the
    # order of their year: where a method's line crosses 1 lies its crossover
    hosts = [h for h in HOSTS_1989 + ("native",) if h in tables]
    fig, ax = plt.subplots(figsize=(8.5, 6))
    for i, method in enumerate(methods):
        med, lo, hi, band_lo, band_hi = [], [], [], [], []
        for host in hosts:
            mine = [r for r in tables[host] if r["method"] == method]
            ratios = sorted(ratio(r) for r in mine)
            med.append(median(ratios))
            lo.append(med[-1] - ratios[0])
            hi.append(ratios[-1] - med[-1])
            banded_host = all("host_over_controller_low" in r for r in mine)
            band_lo.append(med[-1] - (min(float(r["host_over_controller_low"]) for r in mine)
                                      if banded_host else ratios[0]))
            band_hi.append((max(float(r["host_over_controller_high"]) for r in mine)
                            if banded_host else ratios[-1]) - med[-1])
        x = [k + (i - (len(methods) - 1) / 2) * 0.08 for k in range(len(hosts))]
        ax.errorbar(x, med, yerr=[band_lo, band_hi], fmt="none", capsize=0, lw=0.6,
                    color=f"C{i}")
        ax.errorbar(x, med, yerr=[lo, hi], marker="o", ms=4, capsize=2, lw=1.2,
                    color=f"C{i}", label=method)
    ax.axhline(1.0, color="gray", linestyle="--", label="host = controller")
    ax.set_yscale("log")
    ax.set_xticks(range(len(hosts)))
    ax.set_xticklabels([HOST_LABELS.get(h, h) for h in hosts])
    ax.set_ylabel("host time / controller time (tms34010-50mhz)\nmedian over the scenes; "
                  "bars: the range, thin: widened by the controller's band")
    ax.set_title("The split across hosts: above 1 the host bounds the frame, below it the "
                 "controller\nevery method on every bundled scene at 1024x780 (1989 hosts "
                 "modelled, today's measured)", fontsize=10)
    ax.grid(axis="y", which="both", alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    save(fig, os.path.join(root, "split_hosts.png"))


BOUNDARY_HOSTS = ("sun3-60", "sun4-260", "sparcstation-2", "pc-386-25", "native")
BOUNDARIES = {"zbuffer": "host decides visibility (zbuffer)",
              "zspans": "host scan-converts (zspans)",
              "faces": "host projects only (faces)"}


def boundary(root):
    """Moving the split: the three boundaries (experiment split --methods zbuffer zspans faces)
    on each host, from ROOT/boundary/split_HOST.csv. Writes ROOT/boundary.csv -- per host and
    boundary the medians over the scenes of the host's time, the controller's (and its band),
    the pipeline's frame, both utilizations and the bus bytes, and on how many scenes that
    boundary gives the shortest frame -- and ROOT/boundary.png, the median frame against the
    host's speed (the Z-buffer's host time on the Sun-3/60 over its own), one line per
    boundary."""
    tables = {h: read(os.path.join(root, "boundary", f"split_{h}.csv")) for h in BOUNDARY_HOSTS
              if os.path.exists(os.path.join(root, "boundary", f"split_{h}.csv"))}
    if "sun3-60" not in tables:
        return
    median = lambda v: sorted(v)[len(v) // 2] if v else float("nan")  # noqa: E731
    frame = lambda r: float(r["pipeline_ms"] or r["frame_ms"])  # noqa: E731
    zb = lambda h: {scene_label(r["scene"]): float(r["host_frame_ms"])  # noqa: E731
                    for r in tables[h] if r["method"] == "zbuffer"}
    base = zb("sun3-60")
    rows, speeds = [], {}
    for host, table in tables.items():
        mine = zb(host)
        speeds[host] = median([base[k] / v for k, v in mine.items() if k in base and v > 0])
        by_scene = {}
        for r in table:
            by_scene.setdefault(scene_label(r["scene"]), []).append(r)
        best = {k: min(v, key=frame)["method"] for k, v in by_scene.items()}
        for method in BOUNDARIES:
            rs = [r for r in table if r["method"] == method]
            if not rs:
                continue
            col = lambda c: median([float(r[c]) for r in rs if r.get(c)])  # noqa: E731
            rows.append({
                "host": host, "boundary": method, "scenes": len(rs),
                "host_speed": f"{speeds[host]:.3g}",
                "host_ms": f"{col('host_frame_ms'):.4g}",
                "controller_ms": f"{col('controller_ms'):.4g}",
                "controller_ms_low": f"{col('controller_ms_low'):.4g}",
                "controller_ms_high": f"{col('controller_ms_high'):.4g}",
                "frame_ms": f"{median([frame(r) for r in rs]):.4g}",
                "host_util": f"{col('host_util'):.3g}" if rs[0].get("host_util") else "",
                "controller_util": f"{col('controller_util'):.3g}"
                if rs[0].get("controller_util") else "",
                "bus_bytes": f"{col('bus_bytes'):.0f}",
                "bound_by_host": sum(r["bound_by"] == "host" for r in rs),
                "shortest_frame": sum(best[scene_label(r["scene"])] == method for r in rs)})
    fields = list(rows[0])
    write_text(os.path.join(root, "boundary.csv"), ",".join(fields) + "\n" + "".join(
        ",".join(str(r[f]) for f in fields) + "\n" for r in rows))

    order = sorted(tables, key=lambda h: speeds[h])
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    for i, method in enumerate(BOUNDARIES):
        pts = [(speeds[h], float(r["frame_ms"]), float(r["host_ms"]), float(r["controller_ms"]))
               for h in order for r in rows if r["host"] == h and r["boundary"] == method]
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", color=f"C{i}",
                label=BOUNDARIES[method])
        ax.plot([p[0] for p in pts], [p[3] for p in pts], ls=":", lw=0.8, color=f"C{i}")
    for h in order:  # each host named at its Z-buffer's point
        z = [float(r["frame_ms"]) for r in rows if r["host"] == h and r["boundary"] == "zbuffer"]
        if z:
            ax.annotate(HOST_LABELS.get(h, h).replace("\n", " "), (speeds[h], z[0]),
                        textcoords="offset points", xytext=(4, 6), fontsize=7)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("host speed: the Sun-3/60's Z-buffer time over this host's (median of the scenes)")
    ax.set_ylabel("frame time, ms (the pipeline's; median of the scenes)\n"
                  "dotted: the controller alone")
    ax.set_title("Moving the split: where the host/controller boundary should sit\n"
                 "every bundled scene at 1024x780; TMS34010 board (ISA board on the PC)",
                 fontsize=10)
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(root, "boundary.png"))


def successors(folder):
    """After the paper, the hierarchical Z-buffer (fb89 experiment successors): FOLDER/
    successors.csv drawn as FOLDER/successors.png -- the speed-up over the Z-buffer of the
    paper's hybrid and of the hierarchical Z-buffer against depth complexity, a line each
    over the ideal scene's ladder, a marker each at scenes A-F."""
    rows = read(os.path.join(folder, "successors.csv"))
    labels = {"hybrid-0.04": "the paper's hybrid (§3, threshold 0.04)",
              "hzb": "hierarchical Z-buffer (Greene et al. 1993)"}
    fig, ax = plt.subplots(figsize=(8, 5))
    for i, method in enumerate(labels):
        ladder = sorted((float(r["depth_complexity"]), float(r["speedup"])) for r in rows
                        if r["method"] == method and scene_label(r["scene"]).startswith("ideal-"))
        paper = [(float(r["depth_complexity"]), float(r["speedup"]), scene_label(r["scene"]))
                 for r in rows if r["method"] == method
                 and not scene_label(r["scene"]).startswith("ideal-")]
        ax.plot([p[0] for p in ladder], [p[1] for p in ladder], marker="o", color=f"C{i}",
                label=labels[method] + ", ideal scene")
        ax.scatter([p[0] for p in paper], [p[1] for p in paper], marker="s", color=f"C{i}",
                   facecolors="none", label=labels[method] + ", scenes A-F")
        for dc, up, name in paper:
            ax.annotate(name, (dc, up), textcoords="offset points", xytext=(3, 3), fontsize=6,
                        color=f"C{i}")
    ax.axhline(1.0, color="grey", lw=0.8, ls="--")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ax.set_xlabel("depth complexity (face pixels over covered pixels)")
    ax.set_ylabel("speed-up over the Z-buffer (host hidden-surface time)")
    ax.set_title("After the paper: image and object coherence together\n"
                 "1024x780, this machine, medians of interleaved rounds", fontsize=10)
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save(fig, os.path.join(folder, "successors.png"))


def successors_rays(folder):
    """After the paper, multi-level ray tracing (fb89 experiment successors-rays): FOLDER/
    successors_rays.csv drawn as FOLDER/successors_rays.png -- the speed-up over the ray tracer
    (its BVH) of the paper's beam-ray hybrid, of multi-level ray tracing (with packets of rays
    and without) and of the ray tracer on mlrta's kd-tree, against image width, one panel per
    scene."""
    rows = read(os.path.join(folder, "successors_rays.csv"))
    scenes = list(dict.fromkeys(scene_label(r["scene"]) for r in rows))
    labels = {"beam": "the paper's beam-ray hybrid (§4)",
              "mlrta": "multi-level ray tracing (Reshetov et al. 2005), packets of 8 rays",
              "mlrta-scalar": "multi-level ray tracing, its rays one by one",
              "raytrace-kd": "ray tracer on mlrta's kd-tree"}
    fig, axes = plt.subplots(1, len(scenes), figsize=(3.2 * len(scenes), 3.8), sharey=True,
                             squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for i, method in enumerate(labels):
            points = sorted((int(r["width"]), float(r["speedup"])) for r in rows
                            if scene_label(r["scene"]) == scene and r["method"] == method)
            ax.plot([p[0] for p in points], [p[1] for p in points], marker="o",
                    color=f"C{i}", label=labels[method])
        ax.axhline(1.0, color="grey", lw=0.8, ls="--")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log", base=2)
        ax.set_title(scene, fontsize=9)
        ax.set_xlabel("image width (pixels)", fontsize=8)
        ax.grid(which="both", alpha=0.3)
    axes[0][0].set_ylabel("speed-up over the ray tracer (BVH), hidden-surface time", fontsize=8)
    axes[0][0].legend(fontsize=6)
    fig.suptitle("After the paper: beams that fill windows against beams that find entry points "
                 "(this machine, medians of interleaved rounds)", fontsize=9)
    fig.tight_layout()
    save(fig, os.path.join(folder, "successors_rays.png"))


def timeline_png(json_path, png_path):
    """One frame through the pipeline in time (fb89 render --timeline): the host's, the bus's
    and the controller's lanes in time, host stalls in red, the command buffer's fill below,
    the utilizations in the title."""
    import json
    with open(json_path) as f:
        trace = json.load(f)
    other = trace["otherData"]
    lanes = {1: ("host", 2), 2: ("bus", 1), 3: ("controller", 0)}
    bars = {1: [], 2: [], 3: []}
    stalls, setup, counter = [], [], []
    for e in trace["traceEvents"]:
        ph = e.get("ph")
        if ph == "X":
            span = (e["ts"] / 1e3, e["dur"] / 1e3)
            if e["tid"] == 1 and e["name"] == "stall":
                stalls.append(span)
            elif e["tid"] == 1 and e["name"] == "set-up":
                setup.append(span)
            else:
                bars[e["tid"]].append(span)
        elif ph == "C":
            counter.append((e["ts"] / 1e3, e["args"]["bytes"]))
    fig, (ax, buf) = plt.subplots(2, 1, figsize=(9, 3.6), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1]})
    for tid, (name, row) in lanes.items():
        colour = "#4477aa" if tid != 2 else "#777777"
        # an edge as wide as a hairline, so that a slice narrower than a pixel still shows
        ax.broken_barh(bars[tid], (row - 0.35, 0.7), facecolor=colour, edgecolor=colour,
                       linewidth=0.3)
    ax.broken_barh(setup, (2 - 0.35, 0.7), color="#88ccee", linewidth=0, label="set-up")
    ax.broken_barh(stalls, (2 - 0.35, 0.7), facecolor="#cc3311", edgecolor="#cc3311",
                   linewidth=0.3, label="host stalled")
    ax.set_yticks([lanes[t][1] for t in lanes], [lanes[t][0] for t in lanes])
    ax.legend(fontsize=7, loc="upper right")
    if counter:
        xs, ys = zip(*counter)
        buf.step(xs, [y / 1024 for y in ys], where="post", color="#228833", linewidth=0.8)
    buf.set_ylabel("buffer KiB", fontsize=8)
    buf.set_xlabel("ms from the start of the host's set-up", fontsize=8)
    ax.set_title(f"{other['title']}: frame {other['frame_ms']:,.1f} ms, utilization host "
                 f"{100 * other['host_utilization']:.1f}%, controller "
                 f"{100 * other['controller_utilization']:.1f}% (send times "
                 f"{other['send_times']})", fontsize=8)
    fig.tight_layout()
    save(fig, png_path)
    plt.close(fig)


def timelines(folder):
    """Every *.json timeline under FOLDER drawn beside itself as .png."""
    for root, _, files in os.walk(folder):
        for name in sorted(files):
            if name.endswith(".json"):
                path = os.path.join(root, name)
                timeline_png(path, path[:-5] + ".png")


def write_text(path, text):
    """A table written by the rule every fb89 output follows (output_file.py's, for bytes)."""
    class Text:  # what save() needs of a figure: savefig into a binary file
        def savefig(self, f, **_):
            f.write(text.encode())
    save(Text(), path)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "docs/figures"
    if "--split-hosts" in sys.argv:
        split_hosts(folder)
        return
    if "--boundary" in sys.argv:
        boundary(folder)
        return
    if "--successors" in sys.argv:
        successors(folder)
        if os.path.exists(os.path.join(folder, "successors_rays.csv")):
            successors_rays(folder)
        return
    if "--timelines" in sys.argv:
        timelines(folder)
        return
    if os.path.exists(os.path.join(folder, "split.csv")):
        split_both_sides(folder)
    if os.path.exists(os.path.join(folder, "fig4_8.csv")):
        fig4_8(folder)
    if os.path.exists(os.path.join(folder, "beam_threshold.csv")):
        beam_threshold(folder)
    if os.path.exists(os.path.join(folder, "radiosity_error.csv")):
        ff_error(folder)
    if len(sys.argv) > 2 and sys.argv[2].startswith("--only-section"):
        return
    if os.path.exists(os.path.join(folder, "fig2_1.csv")):
        fig2_1(folder)
    if os.path.exists(os.path.join(folder, "fig2_4.csv")):
        fig2_4(folder)
    if os.path.exists(os.path.join(folder, "fig3_1.csv")):
        fig3_1(folder)
    if os.path.exists(os.path.join(folder, "accuracy.csv")):
        accuracy(folder)


if __name__ == "__main__":
    main()
