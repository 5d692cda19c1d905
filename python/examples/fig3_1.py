"""The paper's Fig. 3.1 from Python: the hybrid's hidden-surface time against its Expr. 3.1
threshold on scenes A and F, relative to the pure Z-buffer (threshold 0), with the paper's 0.04
marked. One call to fb89.sweep, its table's columns as numpy arrays, and matplotlib.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/fig3_1.py out/fig3_1.png [REPEAT]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import fb89  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "fig3_1.png"
repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 7
table = fb89.sweep("threshold", ["A", "F"], start=0.001, stop=1.0, steps=13, repeat=repeat)
scene, threshold, ms = table["scene"], table["threshold"], table["hs_cpu_ms"]
fig, ax = plt.subplots(figsize=(7, 4.5))
for name in np.unique(scene):
    mine = (scene == name) & (threshold > 0) & np.isfinite(threshold)
    zbuffer = ms[(scene == name) & (threshold == 0)][0]
    ax.plot(threshold[mine], ms[mine] / zbuffer, marker="o", label=f"scene {name}")
ax.axhline(1, color="gray", linestyle="--", label="pure Z-buffer")
ax.axvline(0.04, color="gray", linestyle=":", label="the paper's 0.04")
ax.set(xscale="log", xlabel="threshold (Expr. 3.1)", ylabel="hidden-surface time / Z-buffer's",
       title="Fig. 3.1: the Warnock/Z-buffer hybrid against its threshold")
ax.legend(fontsize=8)
fig.savefig(out, dpi=100)
print(f"wrote {out}")
