/*
** length.c -- the default method's length ("gauss"): the integrator over
** [t0, t1] (integrator.h), a fast path for the commonest call, and the
** plain API's lengths (arclen_length and its forms) beside it.
*/
#include "gauss/integrator.h"

/* The commonest call -- a whole plane curve, two branch pairs in reach, no
** report asked -- as arclen_integ_start() and arclen_integ_integrate() take it, step for step (the
** same sums in the same order, so the same result), without the
** integrator's record, the argument check (arclen_hodo_quick refuses what
** it would) or a call between the steps.  rtol is the truncation budget.
** Returns 0 when the curve is not of that kind: the caller then takes
** the general path from the start. */
static int length_fast(const double *c, double rtol, double *len) {
  arclen_hodo h;
  arclen_branch br;
  double mid[ARCLEN_CUT_PIECES], half_width[ARCLEN_CUT_PIECES];
  double mins[ARCLEN_CUT_PIECES - 1];
  double len_lower = 0, lgoal, sum = 0;
  int n[ARCLEN_CUT_PIECES], nmin, i;
  if (!arclen_hodo_quick(c, 2, &h)) return 0;
  arclen_branch_points(&h, &br);
  if (br.n != 4) return 0;
  nmin = arclen_feet_of(&br, 0, 1, arclen_footcut(rtol), mins);
  for (i = 0; i <= nmin; i++) {
    double a = i ? mins[i - 1] : 0, b = i < nmin ? mins[i] : 1;
    len_lower += arclen_hodo_chord(&h, a, b);
    half_width[i] = (b - a) / 2;
    mid[i] = a + half_width[i];
  }
  if (!(len_lower > 0)) return 0;
  lgoal = arclen_goal_log2(rtol, len_lower, 1, arclen_lead_log2(br.lead2));   /* width 1 */
  if (!arclen_cut_orders(&br, nmin + 1, mid, half_width, lgoal, NMAX, n)) return 0;
  for (i = 0; i <= nmin; i++)
    sum += arclen_apply_rule(&h, arclen_rule_at_least(n[i]), mid[i], half_width[i]);
  *len = arclen_times_pow2(sum, h.exp);
  return 1;
}

/* length_fast for a call that may be of its kind. */
static int try_fast(const double *c, int dim, double t0, double t1,
                    double rtol, double *len) {
  if (dim != 2 || t0 != 0 || t1 != 1 ||
      !(rtol >= ARCLEN_RTOL_MIN && rtol <= ARCLEN_RTOL_MAX))
    return 0;
  return length_fast(c, arclen_truncation_budget(rtol), len);
}

/* The length over [t0, t1] of a checked curve (t0 > t1: negative). */
static double length_core(const double *c, int dim, double t0, double t1,
                          double rtol, arclen_info *info) {
  integrator in;
  double a = t0 < t1 ? t0 : t1, b = t0 < t1 ? t1 : t0, sum = 0;
  double budget = arclen_truncation_budget(rtol);
  if (a == b) return 0;
  if (arclen_integ_start(&in, c, dim, a, b, budget, arclen_footcut(budget))) {
    in.want_err = info != NULL;
    sum = arclen_integ_integrate(&in);
  }
  if (info) {
    arclen_integ_fill_info(info, &in, in.h.exp);
    info->err = arclen_integ_curve_units(&in, in.err);
  }
  return arclen_integ_curve_units(&in, t0 > t1 ? -sum : sum);
}

int arclen_length_gauss(const double *c, int dim, const arclen_opts *o,
                        double *len, arclen_info *info) {
  int e;
  if (!info && try_fast(c, dim, o->t0, o->t1, o->rtol, len)) return ARCLEN_OK;
  e = arclen_integ_check_args(c, dim, o->rtol, o->t0, o->t1);
  *len = NAN;
  if (info) arclen_info_init(info);
  if (e) return e;
  *len = length_core(c, dim, o->t0, o->t1, o->rtol, info);
  return ARCLEN_OK;
}

/* The plain API's length: NaN on bad input.  Here, beside the fast path
** it takes, so that the commonest call is one call. */
static double length_of(const double *c, int dim, double t0, double t1,
                        double rtol) {
  double len;
  if (try_fast(c, dim, t0, t1, rtol, &len)) return len;
  if (arclen_integ_check_args(c, dim, rtol, t0, t1)) return NAN;
  return length_core(c, dim, t0, t1, rtol, NULL);
}

double arclen_length_gl(const double *c, int dim, int n) {
  arclen_hodo h;
  arclen_hodo_scaled(c, dim, &h);
  if (h.zero) return 0;
  return arclen_times_pow2(arclen_apply_rule(&h, arclen_rule_at_least(n), 0.5, 0.5), h.exp);
}

double arclen_length(const double c[8], double rtol) {
  return length_of(c, 2, 0, 1, rtol);
}
double arclen_length_range(const double c[8], double t0, double t1,
                           double rtol) {
  return length_of(c, 2, t0, t1, rtol);
}
double arclen_length3(const double c[12], double rtol) {
  return length_of(c, 3, 0, 1, rtol);
}
double arclen_length3_range(const double c[12], double t0, double t1,
                            double rtol) {
  return length_of(c, 3, t0, t1, rtol);
}
