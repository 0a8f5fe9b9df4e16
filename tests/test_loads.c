/* test_loads.c: the load post-processing against closed forms: hydrostatic
 * force and moment (REFERENCES 1.1: rho g h^2/2, rho g h^3/6), integrals of
 * known functions, the digital Butterworth magnitude response per pass
 * (bilinear transform), rise time / duration of a triangle pulse, and the
 * positive-phase and positive impulses of a decaying oscillating train. */
#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "wallload/loads.h"
#include "wallload/units.h"

int main(void) {
  const double rho = 1000, g = 9.81, h = 0.5;
  /* Probes half a spacing inside a 1 m wall; the wall is dry above h. */
  enum { N = 40 };
  double z[N], p[N];
  double dz = 1.0 / N;
  for (int k = 0; k < N; k++) {
    z[k] = (k + 0.5) * dz;
    p[k] = z[k] < h ? rho * g * (h - z[k]) : 0.0;
  }
  double F, M;
  wl_loads_profile(z, p, N, 0.0, 1.0, &F, &M);
  /* The probe profile misses the triangle's corner at z = h by O(dz^2) and
   * the held end value at the toe adds O(dz^2): 0.2 % at dz = h/20. */
  CHECK_REL(F, rho * g * h * h / 2, 0.002, "hydrostatic force rho g h^2/2 (REFERENCES 1.1)");
  CHECK_REL(M, rho * g * h * h * h / 6, 0.004, "hydrostatic moment rho g h^3/6 (REFERENCES 1.1)");
  /* A linear profile through the whole height with probes at the ends is
   * integrated exactly. */
  double z2[3] = {0, 0.5, 1}, p2[3] = {2, 1, 0};
  wl_loads_profile(z2, p2, 3, 0.0, 1.0, &F, &M);
  CHECK_ABS(F, 1.0, 1e-15, "linear profile force = 1 (by hand)");
  CHECK_ABS(M, 1.0 / 3.0, 1e-15, "linear profile moment int (2-2z) z dz = 1/3 (by hand)");

  /* Cumulative integral of sin over [0, pi] = 2. */
  enum { T = 2001 };
  double *t = malloc(T * sizeof *t), *f = malloc(T * sizeof *f), *I = malloc(T * sizeof *I);
  for (int k = 0; k < T; k++) {
    t[k] = WL_PI * k / (T - 1);
    f[k] = sin(t[k]);
  }
  wl_loads_cumulative(t, f, T, I);
  CHECK_REL(I[T - 1], 2.0, 1e-6, "int_0^pi sin = 2 (trapezoid error pi^2/(12 (T-1)^2) 2)");

  /* The force at rest: the mean of F0 + A sin(2 pi t / T_a) over a whole
   * number of acoustic periods T_a = 4 d / c0 is F0 (closed form); the rest
   * window starts after two periods and must hold two more. */
  {
    const double d = 0.2, c0 = 16.0, Ta = 4 * d / c0, F0 = 196.2, A = 30.0, ds = 0.005;
    double w0, w1;
    CHECK_TRUE(wl_loads_rest_window(0.25, d, c0, &w0, &w1) == 1, "rest window [2 T_a, 0.25 s] usable");
    CHECK_ABS(w0, 2 * Ta, 1e-15, "rest window starts two acoustic periods 4 d/c0 in");
    CHECK_TRUE(wl_loads_rest_window(3.9 * Ta, d, c0, &w0, &w1) == 0,
          "no rest window when fewer than two periods follow the first two");
    CHECK_TRUE(wl_loads_rest_window(NAN, d, c0, &w0, &w1) == 0, "no rest window without an estimate");
    enum { R = 201 };
    double tr[R], fr[R];
    for (int k = 0; k < R; k++) tr[k] = k * ds, fr[k] = F0 + A * sin(2 * WL_PI * tr[k] / Ta);
    /* [2 Ta, 6 Ta] = [0.1, 0.3] s: four whole periods of 10 samples */
    CHECK_REL(wl_loads_mean(tr, fr, R, 2 * Ta, 6 * Ta), F0, 1e-12,
              "mean over whole periods = the force at rest (trapezoid rule exact on a sine's periods)");
    CHECK_TRUE(isnan(wl_loads_mean(tr, fr, R, 0.1, 0.01)), "an empty window has no mean");
  }

  /* Filter: sines well below, at and above the cut-off. filtfilt squares
   * the magnitude: gain = 1/(1 + (f/fc)^4) for a second-order Butterworth. */
  const double dt = 1e-3, fc = 20.0;
  enum { L = 20000 };
  double *x = malloc(L * sizeof *x), *y = malloc(L * sizeof *y), *tt = malloc(L * sizeof *tt);
  const double freqs[3] = {2.0, 20.0, 80.0};
  for (int q = 0; q < 3; q++) {
    for (int k = 0; k < L; k++) x[k] = sin(2 * WL_PI * freqs[q] * k * dt);
    struct wl_error err;
    wl_error_clear(&err);
    wl_loads_lowpass(x, L, dt, fc, y, &err);
    double ax = 0, ay = 0;
    for (int k = L / 4; k < 3 * L / 4; k++) ax += x[k] * x[k], ay += y[k] * y[k];
    /* digital Butterworth by the bilinear transform prewarped at fc:
     * |H|^2 = 1/(1 + (tan(pi f dt)/tan(pi fc dt))^4); filtfilt squares it */
    double r = tan(WL_PI * freqs[q] * dt) / tan(WL_PI * fc * dt);
    double gain = sqrt(ay / ax), want = 1.0 / (1.0 + r * r * r * r);
    CHECK_REL(gain, want, 0.01, "filtfilt Butterworth gain 1/(1+(tan/tan)^4)");
  }
  /* zero phase: a symmetric pulse stays centred */
  for (int k = 0; k < L; k++) {
    double s = (k * dt - 10.0) / 0.2;
    x[k] = exp(-s * s);
  }
  struct wl_error err;
  wl_error_clear(&err);
  wl_loads_lowpass(x, L, dt, 5.0, y, &err);
  int kmax = 0;
  for (int k = 0; k < L; k++)
    if (y[k] > y[kmax]) kmax = k;
  CHECK_ABS(kmax * dt, 10.0, dt, "zero-phase: the filtered pulse peaks where the input does");
  CHECK_TRUE(wl_loads_lowpass(x, L, dt, 600.0, y, &err) == WL_EINPUT,
             "a cut-off above Nyquist is refused");

  /* Triangle pulse on a base of 100: rises 0 -> 1000 over [1, 2] s, falls
   * over [2, 4] s. Rise from 10 % (t = 1.1) to the peak: 0.9 s. Duration
   * above 10 %: 1.1 -> 3.8 s = 2.7 s. */
  for (int k = 0; k < L; k++) {
    tt[k] = k * dt * 0.25; /* 0..5 s */
    double s = tt[k];
    double v = s < 1 ? 0 : s < 2 ? 1000 * (s - 1) : s < 4 ? 1000 * (4 - s) / 2 : 0;
    x[k] = 100 + v;
  }
  struct wl_peak pk;
  wl_loads_peak(tt, x, L, 100.0, &pk);
  CHECK_ABS(pk.value, 1100.0, 1e-6, "triangle peak value");
  CHECK_ABS(pk.time, 2.0, 0.00025, "triangle peak time");
  CHECK_ABS(pk.rise_time, 0.9, 0.0005, "rise time 10 % -> peak (by hand)");
  CHECK_ABS(pk.duration, 2.7, 0.0005, "duration above 10 % (by hand)");
  CHECK_REL(wl_loads_cutoff(40.0, 0.5, 1e-3), 10.0, 1e-12, "cut-off c0/(8 d)");

  /* Positive phase: x = base + A sin(w t) e^(-t/tau) on 0..4 periods, a
   * decaying oscillating train (its net impulse nearly cancels). The peak
   * lies in the first half period, so the phase is [0, pi/w] (x = base at
   * t = 0 and at pi/w exactly), and int (x - base) dt over it is
   * A w / (w^2 + 1/tau^2) (1 + e^(-pi/(w tau))) (by hand: int e^(-t/tau)
   * sin(w t) dt). The trapezoid rule on 2001 samples is good to 1e-5; the
   * sample at pi/w may read a rounding above base (sin(pi) ~ 1e-16), so
   * the phase may end one sample late, adding at most A w dt^2 / 2 ~ 6e-4
   * (1e-4 of the impulse): the tolerance is 2e-4. */
  {
    const double A = 50.0, w = 2.0 * WL_PI, tau = 20.0, base = 100.0, T4 = 4.0;
    const int m = 2001;
    double *ts = malloc(m * sizeof *ts), *xs = malloc(m * sizeof *xs),
           *net = malloc(m * sizeof *net), *cum = malloc(m * sizeof *cum);
    for (int k = 0; k < m; k++) {
      ts[k] = T4 * k / (m - 1);
      net[k] = A * sin(w * ts[k]) * exp(-ts[k] / tau);
      xs[k] = base + net[k];
    }
    struct wl_peak pp;
    wl_loads_peak(ts, xs, (size_t)m, base, &pp);
    size_t i0, i1;
    wl_loads_positive_phase(xs, (size_t)m, base, pp.index, &i0, &i1);
    wl_loads_cumulative(ts, net, (size_t)m, cum);
    double exact = A * w / (w * w + 1.0 / (tau * tau)) * (1.0 + exp(-WL_PI / (w * tau)));
    CHECK_ABS(ts[i0], 0.0, 1e-12, "positive phase starts at the record's start");
    CHECK_ABS(ts[i1], 0.5, 1.01 * T4 / (m - 1), "positive phase ends at pi/w");
    CHECK_REL(cum[i1] - cum[i0], exact, 2e-4, "positive-phase impulse (closed form)");
    /* over 4 whole periods the net impulse is A w / (w^2 + 1/tau^2)
     * (1 - e^(-4 T / tau)): a tenth of the first phase's here */
    double net_exact = A * w / (w * w + 1.0 / (tau * tau)) * (1.0 - exp(-T4 / tau));
    CHECK_REL(cum[m - 1], net_exact, 1e-4, "net impulse of the train (closed form)");
    CHECK_TRUE(cum[m - 1] < 0.15 * (cum[i1] - cum[i0]), "the net impulse is far below the phase's");
    /* the positive impulse of the whole train: the four positive half
     * periods, each the first one's times e^(-k T/tau) (T = 1 s), by hand.
     * The trapezoid rule's relative error on a half sine of N = 250
     * intervals is (pi/N)^2/12 = 1.3e-5: the tolerance is 3e-5. */
    double pos_exact = 0;
    for (int k = 0; k < 4; k++) pos_exact += exact * exp(-k / tau);
    CHECK_REL(wl_loads_positive_impulse(ts, xs, (size_t)m, base), pos_exact, 3e-5,
              "positive impulse of the train: sum of its positive half periods (closed form)");
    {
      /* exact for a piecewise-linear record: base + 1 falling to base - 1
       * over 1 s pushes 1/2 x 1 x 1/2 = 0.25; the mirror image likewise;
       * a record wholly below base, nothing */
      const double t2[3] = {0, 1, 3}, down[3] = {base + 1, base - 1, base - 1},
                   up[3] = {base - 1, base - 1, base + 3}, below[3] = {base - 2, base - 1, base - 3};
      CHECK_ABS(wl_loads_positive_impulse(t2, down, 3, base), 0.25, 1e-15, "crossing down: 0.25");
      CHECK_ABS(wl_loads_positive_impulse(t2, up, 3, base), 0.5 * 3 * 1.5, 1e-15,
                "crossing up over 2 s to +3: 1/2 x 3 x 1.5");
      CHECK_ABS(wl_loads_positive_impulse(t2, below, 3, base), 0.0, 0.0, "below the base: 0");
      /* the time above the base, by hand: 0.5 s of the fall, 1.5 s of the
       * rise, none */
      CHECK_ABS(wl_loads_time_above(t2, down, 3, base), 0.5, 1e-15, "time above, crossing down");
      CHECK_ABS(wl_loads_time_above(t2, up, 3, base), 1.5, 1e-15, "time above, crossing up");
      CHECK_ABS(wl_loads_time_above(t2, below, 3, base), 0.0, 0.0, "time above, below: 0");
    }
    /* the time above is minus the positive impulse's derivative in its
     * base: a central difference of the train's positive impulse (a second
     * computation through wl_loads_positive_impulse) */
    {
      const double db = 1e-4 * A;
      const double slope = (wl_loads_positive_impulse(ts, xs, (size_t)m, base - db) -
                            wl_loads_positive_impulse(ts, xs, (size_t)m, base + db)) /
                           (2 * db);
      CHECK_REL(wl_loads_time_above(ts, xs, (size_t)m, base), slope, 1e-6,
                "time above = -d(positive impulse)/d(base)");
    }
    /* how well a window fixes a mean: a step from 1 to 3 halfway, and a
     * ramp x = t over [0, 1] (halves' means 0.25 and 0.75), by hand */
    {
      double tw[101], step[101], ramp[101];
      for (int k = 0; k <= 100; k++) {
        tw[k] = 0.01 * k;
        step[k] = tw[k] < 0.5 ? 1.0 : 3.0;
        ramp[k] = tw[k];
      }
      CHECK_ABS(wl_loads_halves_spread(tw, ramp, 101, 0.0, 1.0), 0.25, 1e-12,
                "halves' spread of a ramp: (0.75 - 0.25) / 2");
      CHECK_ABS(wl_loads_halves_spread(tw, step, 101, 0.0, 1.0), 1.0, 0.02,
                "halves' spread of a step: (3 - 1) / 2 (one interval straddles it)");
      CHECK_TRUE(isnan(wl_loads_halves_spread(tw, ramp, 101, 0.0, 0.05)),
                 "halves of under 4 samples: NaN");
    }
    /* a phase that is still positive at the record's end ends there */
    wl_loads_positive_phase(xs, 200, base, pp.index, &i0, &i1); /* 0 .. 0.398 s */
    CHECK_TRUE(i0 == 0 && i1 == 199, "phase cut by the record's end");
    /* a peak at or below base has an empty phase */
    for (int k = 0; k < m; k++) xs[k] = base - 1.0;
    wl_loads_positive_phase(xs, (size_t)m, base, 7, &i0, &i1);
    CHECK_TRUE(i0 == 7 && i1 == 7, "no positive phase: i0 = i1 = the peak");
    free(ts), free(xs), free(net), free(cum);
  }
  /* The sampling uncertainty of a mean (loads.h): Student's t for a
   * two-sided 95 % interval from the table of any statistics text
   * (the percentage points of any statistics table: t(1) 12.706, t(7) 2.365, t(30) 2.042,
   * t(60) 2.000, t(120) 1.980), and 4 runs of sd 1 about a mean of 10 by
   * hand: 3.182 / 2 / 10. */
  CHECK_REL(wl_loads_t95(1), 12.706, 1e-4, "t95 with 1 degree of freedom");
  CHECK_REL(wl_loads_t95(7), 2.365, 1e-4, "t95 with 7 (8 runs)");
  CHECK_REL(wl_loads_t95(30), 2.042, 1e-4, "t95 with 30");
  CHECK_REL(wl_loads_t95(60), 2.000, 1e-3, "t95 with 60 (beyond the table)");
  CHECK_REL(wl_loads_t95(120), 1.980, 1e-3, "t95 with 120 (beyond the table)");
  CHECK_REL(wl_loads_mean_uncertainty(1.0, 4, -10.0), 3.182 / 2.0 / 10.0, 1e-12,
            "mean of 4 runs, sd 1, |mean| 10: t95(3) sd / sqrt(4) / 10");
  CHECK_TRUE(isnan(wl_loads_mean_uncertainty(1.0, 1, 10.0)) &&
                 isnan(wl_loads_mean_uncertainty(NAN, 4, 10.0)),
             "one run, or no spread: no sampling uncertainty");
  free(t), free(f), free(I), free(x), free(y), free(tt);
  return TEST_RESULT();
}
