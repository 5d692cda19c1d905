"""The host-vs-controller split of every method on scenes A-F (docs/RESULTS.md, "The 1989
host"), from Python: each render's host time against the TMS34010's modelled frame time.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/split_chart.py out/split.png [HOST]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import fb89  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "split.png"
host = sys.argv[2] if len(sys.argv) > 2 else "native"
fig, ax = plt.subplots(figsize=(7, 5))
for method in fb89.methods():
    renders = [fb89.render(scene, method=method, size="512x390", host=host)
               for scene in ["A", "B", "C", "D", "E", "F"]]
    ax.scatter([r.split["controller_ms"] for r in renders], [r.split["host_ms"] for r in renders],
               label=method)
ax.axline((1, 1), slope=1, color="gray", linestyle="--", label="host = controller")
ax.set(xscale="log", yscale="log", xlabel="controller frame time (modelled ms)",
       ylabel=f"host set-up + hidden-surface, {host} (ms)",
       title="The split: above the line the host bounds the frame")
ax.legend(fontsize=8)
fig.savefig(out, dpi=100)
print(f"wrote {out}")
