#!/usr/bin/python3
"""Plots the TSV of bench/thread_scaling.sh: speed-up over 1 thread against the thread count,
one line per case, with the ideal line. Needs Debian's python3-matplotlib.

    bench/thread_scaling.sh build/glslrun "1 2 4 8 12 16" 20 > scaling.tsv
    /usr/bin/python3 bench/plot_scaling.py scaling.tsv docs/thread_scaling.png "16-core machine"
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    tsv, png = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else ""
    cases = {}
    with open(tsv) as f:
        for row in csv.DictReader(f, delimiter="\t"):
            cases.setdefault(row["case"], []).append((int(row["threads"]), float(row["speedup"])))
    if not cases:
        sys.exit(f"{tsv}: no rows")
    fig, ax = plt.subplots(figsize=(6, 4))
    most = max(t for points in cases.values() for t, _ in points)
    ax.plot([1, most], [1, most], "k:", label="ideal")
    for name, points in cases.items():
        ax.plot([t for t, _ in points], [s for _, s in points], "o-", label=f"{name}, 1920x1080")
    ax.set_xlabel("threads (--threads)")
    ax.set_ylabel("speed-up over 1 thread (median frame)")
    ax.set_title(f"glslrun thread scaling{': ' + title if title else ''}", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=100)


if __name__ == "__main__":
    main()
