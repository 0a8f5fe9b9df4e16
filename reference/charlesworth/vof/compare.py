#!/usr/bin/env python3
"""Compare surface series at the charlesworth gauge: each CSV (t,eta, the first
two columns; a header line) against a reference CSV, by seed 001's measures
(RMSE over the reference's largest |eta|, eq 16; Pearson correlation) over
the reference's times up to --end, the compared series interpolated
linearly in time. With --linear the plane linear Cauchy-Poisson solution of
the same crater (REFERENCES 5.1, walls as images, the Gaussian filter
exp(-(k R0/20)^2) that `validate` uses) is computed here as well and
compared like a CSV.

Usage: compare.py REF.csv [--end 8] [--linear] [SERIES.csv ...]"""
import argparse
import math
import sys

sys.path.insert(0, __import__("os").path.dirname(__file__))
import make_case as mc  # noqa: E402  (the crater, flume and gauge of the case)


def read_csv(path):
    rows = []
    with open(path) as f:
        next(f)
        for line in f:
            p = line.strip().split(",")
            if len(p) >= 2:
                rows.append((float(p[0]), float(p[1])))
    return rows


def interp(rows, t):
    if t <= rows[0][0]:
        return rows[0][1]
    for (t0, e0), (t1, e1) in zip(rows, rows[1:]):
        if t0 <= t <= t1:
            return e0 + (e1 - e0) * (t - t0) / (t1 - t0)
    return float("nan")


def crater_transform(k):
    """F(k) = 2 int_0^R eta0 (2 x^2/R^2 - 1) cos(k x) dx, in closed form."""
    R, e = mc.R0, mc.ETA0
    if k * R < 1e-3:  # its series: 2 eta0 (-R/3 - k^2 R^3 / 30)
        return 2 * e * (-R / 3 - (k * R) ** 2 * R / 30)
    s, c = math.sin(k * R), math.cos(k * R)
    return 2 * e * (s / k + 4 * c / (R * k * k) - 4 * s / (R * R * k ** 3))


def linear_series(times, nk=6000):
    delta = mc.R0 / 20
    kmax = 5.0 / delta
    dk = kmax / (nk - 1)
    ks = [j * dk for j in range(nk)]
    F = [crater_transform(k) * math.exp(-(k * delta) ** 2) for k in ks]
    om = [math.sqrt(9.81 * k * math.tanh(k * mc.DEPTH)) for k in ks]
    xs = (mc.X_GAUGE - mc.X_SHOT, 2 * mc.X_WALL - mc.X_GAUGE - mc.X_SHOT, mc.X_GAUGE + mc.X_SHOT)
    cx = [[math.cos(k * x) for k in ks] for x in xs]
    out = []
    for t in times:
        s = 0.0
        for j in range(nk):
            w = 0.5 if j in (0, nk - 1) else 1.0
            s += w * F[j] * (cx[0][j] + cx[1][j] + cx[2][j]) * math.cos(om[j] * t)
        out.append((t, s * dk / math.pi))
    return out


def measures(ref, other, end):
    pts = [(t, e) for t, e in ref if t <= end + 1e-9]
    a = [e for _, e in pts]
    b = [interp(other, t) for t, _ in pts]
    n = len(a)
    amax = max(abs(x) for x in a)
    rmse = math.sqrt(sum((y - x) ** 2 for x, y in zip(a, b)) / n)
    ma, mb = sum(a) / n, sum(b) / n
    cov = sum((x - ma) * (y - mb) for x, y in zip(a, b))
    va = sum((x - ma) ** 2 for x in a)
    vb = sum((y - mb) ** 2 for y in b)
    r = cov / math.sqrt(va * vb)
    return rmse / amax, r, max(abs(y) for y in b) / amax - 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ref")
    ap.add_argument("series", nargs="*")
    ap.add_argument("--end", type=float, default=8.0)
    ap.add_argument("--linear", action="store_true")
    a = ap.parse_args()
    ref = read_csv(a.ref)
    others = [(p, read_csv(p)) for p in a.series]
    if a.linear:
        others.append(("linear Cauchy-Poisson", linear_series([t for t, _ in ref])))
    print(f"against {a.ref} (largest |eta| {max(abs(e) for t, e in ref if t <= a.end):.4f} m, "
          f"t <= {a.end} s)")
    for name, s in others:
        rm, r, pk = measures(ref, s, a.end)
        print(f"  {name}: RMSE/max|eta| {100 * rm:.1f} %, r {r:.3f}, largest |eta| {100 * pk:+.1f} %")


if __name__ == "__main__":
    main()
