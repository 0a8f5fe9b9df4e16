/* testutil.h: the PASS/FAIL line every check prints, naming its reference.
 * A test program returns the number of failed checks (0 = pass), or 77 to be
 * reported as skipped by ctest. */
#ifndef WALLLOAD_TESTUTIL_H
#define WALLLOAD_TESTUTIL_H

#include <math.h>
#include <stdio.h>

static int wl_test_failures = 0;

/* Check |got - want| <= tol (absolute). */
#define CHECK_ABS(got, want, tol, ref)                                                            \
  do {                                                                                            \
    double g_ = (got), w_ = (want), t_ = (tol);                                                   \
    int ok_ = isfinite(g_) && fabs(g_ - w_) <= t_;                                                \
    printf("%s %s: got %.10g, want %.10g +- %.3g [%s] (%s:%d)\n", ok_ ? "PASS" : "FAIL", #got, g_, \
           w_, t_, ref, __FILE__, __LINE__);                                                      \
    if (!ok_) wl_test_failures++;                                                                 \
  } while (0)

/* Check |got - want| <= rtol * |want| (relative). */
#define CHECK_REL(got, want, rtol, ref)                                                           \
  do {                                                                                            \
    double g_ = (got), w_ = (want), t_ = (rtol);                                                  \
    int ok_ = isfinite(g_) && fabs(g_ - w_) <= t_ * fabs(w_);                                     \
    printf("%s %s: got %.10g, want %.10g (rel %.2e, tol %.1e) [%s] (%s:%d)\n",                   \
           ok_ ? "PASS" : "FAIL", #got, g_, w_, w_ != 0 ? fabs(g_ - w_) / fabs(w_) : fabs(g_), t_, \
           ref, __FILE__, __LINE__);                                                              \
    if (!ok_) wl_test_failures++;                                                                 \
  } while (0)

/* Check a condition. */
#define CHECK_TRUE(cond, ref)                                                                     \
  do {                                                                                            \
    int ok_ = !!(cond);                                                                           \
    printf("%s %s [%s] (%s:%d)\n", ok_ ? "PASS" : "FAIL", #cond, ref, __FILE__, __LINE__);        \
    if (!ok_) wl_test_failures++;                                                                 \
  } while (0)

#define TEST_RESULT() (wl_test_failures > 255 ? 255 : wl_test_failures)

#endif
