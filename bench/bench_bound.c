/*
** bench_bound.c -- how tight the default method's error bound is, on the
** bench's random curves that take one piece: the bound of the n-point rule
** (gauss_bound.c) over its true error, at every order whose error lies well
** above rounding, and the order the method chooses against the least order
** that meets the tolerance in truth (the oracle, from a 1e-15 reference).
*/
#include <math.h>
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"
#include "curve/cubic.h"
#include "gauss/bound.h"
#include "gauss/gauss_tables.h"

#define NCURVES 3000
#define MAXRATIOS (NCURVES * 128)

static double curves[8 * NCURVES];
static double ratios[MAXRATIOS], chosen[NCURVES], oracle[NCURVES];

/* The bound of the n-point rule on [0, 1] in scaled units: the method's
** own (arclen_cut_ratio at 2^0) times its common factor half_width (4/pi) lead. */
static double bound_at(const arclen_cut_curve *cc, const arclen_cut_piece *pbound,
                       double lead, int n) {
  return arclen_cut_ratio(cc, pbound, 0, n) * 0.5 * (4 / 3.14159265358979323846) *
         lead;
}

int main(void) {
  int i, n, nr = 0, nc = 0;
  double gaps[NCURVES], mchosen = 0, moracle = 0;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    arclen_opts o;
    arclen_info info;
    arclen_hodo h;
    arclen_branch br;
    arclen_cut_curve cc;
    arclen_cut_piece pbound;
    double len, ref, refs;
    arclen_opts_init(&o);
    arclen_length_gauss(c, 2, &o, &len, &info);
    if (info.pieces != 1) continue;
    arclen_hodo_scaled(c, 2, &h);
    arclen_branch_points(&h, &br);
    arclen_cut_prepare(&br, &cc);
    if (!cc.ok) continue;
    arclen_cut_bound(&cc, 0.5, 0.5, &pbound);
    ref = arclen_length(c, 1e-15);
    refs = ldexp(ref, -h.exp);
    oracle[nc] = 0;
    for (n = 2; n <= ARCLEN_GAUSS_MAX; n++) {
      double err = fabs(ldexp(arclen_length_gl(c, 2, n), -h.exp) - refs);
      if (err > 1e-13 * refs && nr < MAXRATIOS)
        ratios[nr++] = bound_at(&cc, &pbound, sqrt(br.lead2), n) / err;
      if (!oracle[nc] && err <= 1e-12 * refs) oracle[nc] = n;
    }
    chosen[nc] = (double)info.evals;
    gaps[nc] = chosen[nc] - oracle[nc];
    nc++;
  }
  for (i = 0; i < nc; i++) {
    mchosen += chosen[i] / nc;
    moracle += oracle[i] / nc;
  }
  printf("%d one-piece curves of 3000 random cubics in [0,10]^2\n", nc);
  printf("bound / true error, %d (curve, order) pairs with error > 1e-13:\n", nr);
  qsort(ratios, nr, sizeof *ratios, bench_cmp);
  printf("  min %.2f  10%% %.2f  median %.2f  90%% %.2f\n", ratios[0],
         ratios[nr / 10], ratios[nr / 2], ratios[nr - nr / 10]);
  printf("order at tol 1e-12: chosen median %.0f, oracle median %.0f, "
         "chosen - oracle median %.0f (mean %.1f vs %.1f)\n",
         bench_median(chosen, nc), bench_median(oracle, nc),
         bench_median(gaps, nc), mchosen, moracle);
  return 0;
}
