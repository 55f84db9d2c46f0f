#!/usr/bin/env python3
"""gt bench --docs: error against GPU time, one curve per method (bench_table.tsv of gt-cli
bench-report). Usage: bench_plot.py TABLE.tsv OUT.png"""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
# The sweep's main tile count: the first adaptive row's (the others vary tiles and max factor).
main_tiles = next(r["tiles"] for r in rows if r["method"] == "adaptive")
fig, ax = plt.subplots(figsize=(8, 5.5))
styles = {"paper": ("tab:red", "s", "paper's per-patch"), "uniform": ("tab:blue", "o", "tiles, uniform factor"),
          "adaptive": ("tab:green", "^", "tiles, adaptive (pixel error)"), "fallback": ("tab:gray", "D", "fallback (no tessellator)"),
          "cached adaptive": ("tab:purple", "v", "tiles, cached adaptive (compute pre-pass, integer factors)")}
for method, (color, marker, label) in styles.items():
    for octaves, dash in (("0", "-"), ("4", ":")):
        pts = sorted((float(r["gpu_ms"]), float(r["max_px"])) for r in rows
                     if r["method"] == method and r["octaves"] == octaves
                     and (method == "paper" or r["tiles"] == main_tiles)
                     and (not method.endswith("adaptive") or float(r["maxfactor"]) == 64))
        pts = [p for p in pts if p[0] > 0 and p[1] > 0]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], dash, color=color, marker=marker,
                    label=label + (" + noise" if octaves != "0" else ""))
ax.set_xscale("log"); ax.set_yscale("log")
ax.set_xlabel("GPU time per frame, ms (mean over the camera path)")
ax.set_ylabel("largest error on the camera path, pixels")
ax.axhline(1.0, color="k", lw=0.5)
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
ax.set_title("Accuracy vs time (gt bench)")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
print("plot", sys.argv[2])
