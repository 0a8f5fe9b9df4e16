"""assess_compare.py: CPU vs CUDA agreement of `wallload assess` outputs
(BENCHMARKS.md, "assess end to end, CPU vs CUDA").

usage: python3 bench/assess_compare.py DIR
DIR holds the unpacked e2e.tgz of bench/assess_e2e.sh run: sol_cpu/,
sol_cuda/, sea_cpu/, sea_cuda/ with summary.json and <case>_{wall,gauges}.csv.
Prints per case the summary values and their relative difference, per gauge
the largest and RMS difference over the wave height H (and the largest up to
0.5 s before the CPU's peak-force time), and per wall-force series the RMS
difference over the impact window (CPU filtered dynamic force above 10 % of
its peak) relative to the RMS of the CPU's dynamic force there.
"""
import os
import json, csv, sys, math
def rd(p):
    rows = list(csv.DictReader(open(p)))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}
def cmp(run, case, H):
    a = json.load(open(f'{run}_cpu/summary.json'))['cases'][case]
    b = json.load(open(f'{run}_cuda/summary.json'))['cases'][case]
    v = lambda c, k: c[k]['value'] if isinstance(c[k], dict) else c[k]
    print(f'### {run} {case} (H = {H} m)')
    for k in ['particles', 'steps', 'runtime', 'particle_steps_per_second', 'peak_force', 'peak_force_time',
              'peak_force_dynamic', 'peak_force_boundary', 'impulse', 'impulse_boundary', 'peak_moment',
              'max_runup', 'rise_time', 'duration']:
        x, y = v(a, k), v(b, k)
        x = float('nan') if x is None else x; y = float('nan') if y is None else y
        rel = (y - x) / abs(x) * 100 if x != 0 and x == x and y == y else float('nan')
        print(f'  {k:28s} cpu {x:12.6g}  cuda {y:12.6g}  diff {rel:+7.2f} %')
    ga, gb = rd(f'{run}_cpu/{case}_gauges.csv'), rd(f'{run}_cuda/{case}_gauges.csv')
    n = min(len(ga['time_s']), len(gb['time_s'])); t = ga['time_s'][:n]
    tp = v(a, 'peak_force_time')
    for g in [k for k in ga if k != 'time_s']:
        d = [gb[g][i] - ga[g][i] for i in range(n)]
        pre = [abs(d[i]) for i in range(n) if t[i] < tp - 0.5]
        rms = math.sqrt(sum(x * x for x in d) / n)
        print(f'  gauge {g:12s} max|d|/H {max(map(abs, d))/H:6.3f}  rms/H {rms/H:6.3f}  max|d|/H before t_peak-0.5s {max(pre)/H if pre else float("nan"):6.3f}')
    wa, wb = rd(f'{run}_cpu/{case}_wall.csv'), rd(f'{run}_cuda/{case}_wall.csv')
    st = v(a, 'static_force'); pk = v(a, 'peak_force_dynamic')
    for col in ['force_filtered_N_per_m', 'force_boundary_N_per_m', 'force_N_per_m']:
        idx = [i for i in range(n) if wa['force_filtered_N_per_m'][i] - st > 0.1 * pk]
        if not idx: continue
        i0, i1 = idx[0], idx[-1]
        d = [wb[col][i] - wa[col][i] for i in range(i0, i1 + 1)]
        ref = [wa[col][i] - st for i in range(i0, i1 + 1)]
        rr = math.sqrt(sum(x * x for x in d) / len(d)) / math.sqrt(sum(x * x for x in ref) / len(ref))
        print(f'  wall {col:26s} impact window {t[i0]:.3f}-{t[i1]:.3f} s: rel RMS diff {rr*100:6.2f} %  max|d|/peak_dyn {max(map(abs,d))/pk*100:6.2f} %')
    # growth of the difference with time, gauge 1
    g = [k for k in ga if k != 'time_s'][0]
    w = [(t[i], abs(gb[g][i] - ga[g][i]) / H) for i in range(n)]
    seg = max(1, n // 10)
    print('  |d|/H of', g, 'by tenth of the record:', ' '.join(f'{w[j*seg][0]:.1f}s:{max(x[1] for x in w[j*seg:(j+1)*seg]):.3f}' for j in range(10)))
os.chdir(sys.argv[1] if len(sys.argv) > 1 else '.')
cmp('sol', 'solitary', 0.06)
cmp('sea', 'solitary', 0.05)
cmp('sea', 'explosion', 0.05)
