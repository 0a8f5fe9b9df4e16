#!/usr/bin/env python3
"""Surface elevation from a make_case.py run: eta(t) = sum(alpha dy) - depth
along each sampled vertical line (one sample per cell centre).

Usage: gauge.py CASE_DIR [NAME] > series.csv   (NAME: gauge, at20, at25)
Prints `t,eta` with eta in metres, one row per 0.05 s sample."""
import glob
import os
import sys

FT = 0.3048
DEPTH = 16.5 * FT


def series(case, name="gauge"):
    rows = []
    for d in glob.glob(os.path.join(case, "postProcessing", name, "*")):
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        files = glob.glob(os.path.join(d, "*alpha.water*"))
        if not files:
            continue
        ys, al = [], []
        with open(files[0]) as f:
            for line in f:
                p = line.split()
                if len(p) >= 2:
                    ys.append(float(p[0]))
                    al.append(float(p[1]))
        if len(ys) < 2:
            continue
        dy = (ys[-1] - ys[0]) / (len(ys) - 1)  # the samples stand at cell centres
        rows.append((t, sum(al) * dy - DEPTH))
    rows.sort()
    return rows


if __name__ == "__main__":
    case = sys.argv[1]
    name = sys.argv[2] if len(sys.argv) > 2 else "gauge"
    print("t,eta")
    for t, e in series(case, name):
        print(f"{t:.4f},{e:.6f}")
