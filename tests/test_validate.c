/* test_validate.c: the validate module's arithmetic, against closed forms
 * (no simulation; the runs themselves are tests/cli_validate.sh):
 *  - observed order and Richardson extrapolation (Roache 1998) on
 *    manufactured sequences q_k = q_inf + C (r^-k dp)^p: p and q_inf exact;
 *    non-monotone and out-of-range orders refused;
 *  - case selection: exact names, the 'solitary' group (not solitary_wall),
 *    an unknown name is WL_EINPUT naming the valid cases. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/loads.h"
#include "wallload/validate.h"

/* validate's order arithmetic is wl_loads_convergence (shared with assess's
 * ladder) at a constant ratio r: levels dp, dp/r, dp/r^2. */
static int order3(double q1, double q2, double q3, double r, double *p, double *q_inf) {
  const double h[3] = {1.0, 1.0 / r, 1.0 / (r * r)}, f[3] = {q1, q2, q3};
  struct wl_loads_convergence c;
  wl_loads_convergence(h, f, 3, &c);
  *p = c.order;
  *q_inf = c.extrapolated;
  return c.order_ok;
}

static void manufactured(double p_true, double q_inf, double C) {
  const double r = sqrt(2.0), dp = 0.02;
  double q[3];
  for (int k = 0; k < 3; k++) q[k] = q_inf + C * pow(dp / pow(r, k), p_true);
  double p, qi;
  int ok = order3(q[0], q[1], q[2], r, &p, &qi);
  CHECK_TRUE(ok == 1, "manufactured sequence: order is meaningful");
  CHECK_ABS(p, p_true, 1e-9, "observed order = the manufactured order (Roache 1998)");
  CHECK_ABS(qi, q_inf, 1e-12, "Richardson extrapolation = the manufactured limit");
}

int main(void) {
  manufactured(2.0, 0.0123, 3.0);
  manufactured(1.0, -0.05, -0.8);
  manufactured(0.6, 0.2, 1.5);
  double p, qi;
  CHECK_TRUE(order3(0.10, 0.05, 0.08, sqrt(2.0), &p, &qi) == 0 && isnan(qi),
             "non-monotone differences: no extrapolation");
  CHECK_TRUE(order3(0.10, 0.0999, 0.0998, sqrt(2.0), &p, &qi) == 0 && fabs(p) < 1e-6,
             "order 0 (stagnant error): outside [0.5, 4], no extrapolation");
  CHECK_TRUE(order3(0.1, 0.1, 0.1, sqrt(2.0), &p, &qi) == 0 && isnan(p),
             "equal values: order undefined");

  const int n = wl_validate_n_cases();
  CHECK_TRUE(n >= 7, "at least the seven reference cases of the issue");
  int *sel = calloc((size_t)n, sizeof(int));
  struct wl_error err;
  wl_error_clear(&err);
  CHECK_TRUE(wl_validate_select("solitary", sel, &err) == WL_OK, "the 'solitary' group selects");
  int n_sol = 0, wall = 0;
  for (int i = 0; i < n; i++) {
    if (sel[i] && !strncmp(wl_validate_case_name(i), "solitary-", 9)) n_sol++;
    if (sel[i] && !strcmp(wl_validate_case_name(i), "solitary_wall")) wall = 1;
  }
  CHECK_TRUE(n_sol >= 5 && !wall, "group: the five propagation cases, not solitary_wall");
  memset(sel, 0, sizeof(int) * (size_t)n);
  CHECK_TRUE(wl_validate_select("zhou1999", sel, &err) == WL_OK, "exact name selects");
  CHECK_TRUE(wl_validate_select("nosuch", sel, &err) == WL_EINPUT, "unknown name: WL_EINPUT");
  CHECK_TRUE(strstr(err.msg, "hydrostatic") && strstr(err.msg, "charlesworth"),
             "unknown name: the message lists the valid cases");
  free(sel);
  return TEST_RESULT();
}
