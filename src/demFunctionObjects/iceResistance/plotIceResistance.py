#!/usr/bin/env python3
"""Plot of the iceResistance function object: the resistance against time,
the steady window and its mean +- 2 standard errors.

    plotIceResistance.py <iceResistance.dat> <iceResistanceMean.dat> <out.png>
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def columns(path):
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if words and words[0] == "time":
                    names = words
                continue
            if line.strip():
                rows.append([float(x) for x in line.split()])
    return names, rows


def means(path):
    out, start = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            w = line.split()
            if len(w) >= 5:
                out[w[0]] = (float(w[1]), float(w[2]))
                start = float(w[4])
    return out, start


def main(dat, meanFile, png):
    names, rows = columns(dat)
    rows = [r for r in rows if r[names.index("iceSteps")] > 0]
    m, start = means(meanFile)
    t = [r[0] for r in rows]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    styles = {"Rice": "tab:blue", "Rfluid": "tab:green", "Rtotal": "k",
              "RiceNet": "tab:red"}
    for key, colour in styles.items():
        y = [r[names.index(key)] for r in rows]
        if key == "Rfluid" and all(v == 0 for v in y):
            continue
        ax.plot(t, y, color=colour, lw=0.8, label=key)
        if key in m and m[key][0] == m[key][0]:
            mean, err = m[key]
            ax.hlines(mean, start, t[-1], colors=colour, linestyles="--", lw=1.2)
            if err == err:
                ax.fill_between([start, t[-1]], mean - 2 * err, mean + 2 * err,
                                color=colour, alpha=0.15)
    if start == start and start is not None:
        ax.axvline(start, color="grey", lw=0.8, ls=":", label="steady window start")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("resistance [N]")
    ax.set_title("iceResistance: dashed = steady mean, band = +- 2 standard errors")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main(*sys.argv[1:4])
