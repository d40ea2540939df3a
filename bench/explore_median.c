/*
** explore_median.c -- where the default method's median curve could save
** points (README, Speed).  On bench_length's random curves it takes the
** ones of one piece with 55..95 evaluations at tol 1e-12, which hold the
** median time, and prints for them, on average:
**   - the order the default method chooses, and the least order of the
**     plain rule on [0, 1] that meets the tolerance in truth (the oracle);
**   - the evaluations when the curve is cut at the foot of its nearest
**     branch point (each part taken as a sub-range by the default method);
**   - the oracle order of the rule after the cubic change of variable
**     t = p + A z + K z^3, z = u - u_p, u in [-1, 1], whose inflection lies
**     at that foot p, with slope A there;
**   - the order an ellipse bound in u would choose: (64/15) M rho^(2-2n) /
**     (rho^2 - 1) with rho through the nearest preimage of a branch point
**     and M, the largest |g| on that ellipse, SAMPLED at 720 points: an
**     estimate of what a rigorous bound could give, not a bound;
**   - the same with M bounded by the triangle inequality on the ellipse
**     (|z| <= a + |u_p|, so |map - p| <= A R + K R^3 and |map'| <= A +
**     3 K R^2, R = a + |u_p|), at the best rho up to the nearest preimage:
**     cheap, and a bound once rho is;
**   - the same bound with rho certified and the slope chosen per curve
**     (rigorous_order below): no sampling, no exact preimages.
** Then, over all the curves, the median of evaluations plus 30 for each
** piece after the first (what a piece costs, README): as the default
** method runs, and with the certified map taken where it asks fewer
** points, or where a cheap test (below) would take it.
** "Truth" is the default method's length at tol 1e-15.  An exploration,
** not a test: run by `make bench-explore`.
*/
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"
#include "curve/cubic.h"
#include "gauss/gauss_tables.h"

#define NCURVES 3000
#define SLOPE 0.2        /* A; the linear map's slope is 0.5 */
#define SAMPLES 720
#define PI 3.14159265358979323846

static double curves[8 * NCURVES];

/* The cubic map and its derivative. */
typedef struct cubic_map { double p, a, k, up; } cubic_map;

static double complex map_at(const cubic_map *m, double complex u) {
  double complex z = u - m->up;
  return m->p + (m->a + m->k * z * z) * z;
}
static double complex map_slope(const cubic_map *m, double complex u) {
  double complex z = u - m->up;
  return m->a + 3 * m->k * z * z;
}

/* u_p and K from p and A, so that the map takes -1 to 0 and 1 to 1
** (bisection on u_p: K from either end must agree).  0 if K <= 0. */
static int map_for(cubic_map *m, double p, double a) {
  double lo = -0.999, hi = 0.999, z0, z1;
  int it;
  m->p = p;
  m->a = a;
  for (it = 0; it < 200; it++) {
    double up = (lo + hi) / 2, za = 1 - up, zb = -1 - up;
    double ka = (1 - p - a * za) / (za * za * za);
    double kb = (-p - a * zb) / (zb * zb * zb);
    if (ka > kb) hi = up; else lo = up;
  }
  m->up = (lo + hi) / 2;
  /* K from both ends together and p from the left one: the ends are then
  ** exact to rounding, and p is off the foot by what the bisection left
  ** (K from one end alone, near u_p = 1, missed the other by 2e-12) */
  z1 = 1 - m->up;
  z0 = 1 + m->up;
  m->k = (1 - 2 * a) / (z1 * z1 * z1 + z0 * z0 * z0);
  m->p = a * z0 + m->k * z0 * z0 * z0;
  return m->k > 0;
}

/* The three roots of map(u) = r (Cardano, principal cube root). */
static void preimages(const cubic_map *m, double complex r,
                      double complex u[3]) {
  double complex c = (m->p - r) / m->k, q = m->a / m->k;
  double complex d = csqrt(c * c / 4 + q * q * q / 27);
  double complex w = cpow(-c / 2 + d, 1.0 / 3);
  int k;
  for (k = 0; k < 3; k++) {
    double complex wk = w * cexp(2 * PI * I * k / 3);
    u[k] = m->up + wk + (wk != 0 ? -q / (3 * wk) : 0);
  }
}

static double rho_through(double complex u) {
  double a = (cabs(u - 1) + cabs(u + 1)) / 2;
  return a + sqrt(a * a - 1);
}

/* The speed at t (curve units). */
static double speed(const double *c, double t) {
  double d[2];
  arclen_derivative(c, 2, t, d);
  return hypot(d[0], d[1]);
}

/* The n-point rule on [0, 1] (m NULL) or on u in [-1, 1] after the map. */
static double rule(const double *c, int n, const cubic_map *m) {
  const arclen_gauss_rule *r = &arclen_gauss_rules[n - 1];
  double s = 0;
  int i;
  for (i = 0; i < r->half; i++) {
    double x = r->x[i], f;
    if (m)
      f = speed(c, creal(map_at(m, -x))) * creal(map_slope(m, -x)) +
          speed(c, creal(map_at(m, x))) * creal(map_slope(m, x));
    else
      f = speed(c, 0.5 - 0.5 * x) * 0.5 + speed(c, 0.5 + 0.5 * x) * 0.5;
    s += r->w[i] * (i == 0 && n % 2 ? f / 2 : f);
  }
  return s;
}

static int oracle(const double *c, double len, const cubic_map *m) {
  int n;
  for (n = 2; n < ARCLEN_GAUSS_MAX; n++)
    if (fabs(rule(c, n, m) - len) <= 1e-12 * len) break;
  return n;
}

/* The least order whose ellipse bound (64/15) M rho^(2-2n) / (rho^2 - 1)
** meets 1e-12 len (M and len in the same units). */
static int bound_order(double big, double rho, double len) {
  int n;
  for (n = 2; n < 200; n++)
    if ((64.0 / 15.0) * big * pow(rho, 2 - 2 * n) / (rho * rho - 1) <=
        1e-12 * len)
      break;
  return n;
}

/* The order the ellipse bound asks for with M bounded by the triangle
** inequality (see the head), in scaled units (h), on the ellipse rho. */
static int crude_order(const arclen_hodo *h, const arclen_branch *b,
                       const cubic_map *m, double rho, double len) {
  double a = (rho + 1 / rho) / 2, r = a + fabs(m->up);
  double far = m->a * r + m->k * r * r * r, big = sqrt(b->lead2);
  int k;
  for (k = 0; k < b->n; k++)   /* |map(u) - r_k| <= far + |p - r_k| */
    big *= sqrt(far + hypot(m->p - b->re[k], b->im[k]));
  big *= m->a + 3 * m->k * r * r;
  return bound_order(big, rho, ldexp(len, -h->exp));
}

/* The nearest preimage's rho. */
static double rho_star(const arclen_branch *b, const cubic_map *m) {
  double rho = HUGE_VAL;
  double complex u[3];
  int k, j;
  for (k = 0; k < b->n; k += 2) {
    preimages(m, b->re[k] + I * b->im[k], u);
    for (j = 0; j < 3; j++)
      if (rho_through(u[j]) < rho) rho = rho_through(u[j]);
  }
  return rho;
}

/* The order the sampled ellipse bound asks for (see the head). */
static int ellipse_order(const double *c, const arclen_branch *b,
                         const cubic_map *m, double len) {
  double rho = rho_star(b, m), big = 0, a, bb;
  int j;
  a = (rho + 1 / rho) / 2;
  bb = (rho - 1 / rho) / 2;
  for (j = 0; j < SAMPLES; j++) {
    double th = 2 * PI * j / SAMPLES;
    double complex w = a * cos(th) + I * bb * sin(th), t = map_at(m, w);
    double complex s = 1 - t;                 /* the hodograph at t: */
    double complex x = 3 * (s * s * (c[2] - c[0]) +
                            2 * s * t * (c[4] - c[2]) + t * t * (c[6] - c[4]));
    double complex y = 3 * (s * s * (c[3] - c[1]) +
                            2 * s * t * (c[5] - c[3]) + t * t * (c[7] - c[5]));
    double g = sqrt(cabs(x * x + y * y)) * cabs(map_slope(m, w));
    if (g > big) big = g;
  }
  return bound_order(big, rho, len);
}

/* ---- the map's bound with rho certified ---------------------------------
** The branch point p + ib whose foot p the map's inflection sits at has
** preimages z = u - u_p with K z^3 + A z = i b.  When eps = K b^2 / A^3 <
** 4/27 they lie on the imaginary axis, z = i y, A y - K y^3 = b, and the
** least y is (b/A) F(eps) with F = sum_k C(3k, k)/(2k + 1) eps^k (the
** Fuss-Catalan numbers 1, 1, 3, 12, 55, ...; F = 1 + eps F^3): all terms
** are positive, so the sum cut anywhere is a lower bound.  Otherwise one
** lies at z = -2iY and two at +-X + iY, with 8 K Y^3 - 2 A Y = b and X^2
** = 3 Y^2 - A/K (Re(map - p) = 0 off the axis needs X^2 = 3 Y^2 - A/K).
** The other pair, p + D, is kept off the ellipse by one of three tests:
** |Im(map - p)| <= be (A + 3 K R^2) < Im D; |map - p| <= R (A + K R^2) <
** |D|; or Im D is reached only where |Re z| >= X_b, where |Re(map - p)|
** exceeds |Re D| (R = a + |u_p| bounds |z| on the ellipse, be its minor
** semi-axis).  p is the map's (within 1e-15 of the foot, map_for), which
** moves the near preimages by as much; the margins below cover it.  This
** is what a fast version would compute; it runs here with libm calls and
** iterations, for the counts only. */

/* The slope for a branch point b above its foot (t units): 0.9 b^0.6 in
** [0.01, 0.45], the best of 18 slopes on these curves, fitted. */
static double slope_for(double b) {
  double a = 0.9 * pow(b, 0.6);
  return a > 0.45 ? 0.45 : a < 0.01 ? 0.01 : a;
}

/* rho of the ellipse through x + iy, |x| taken as small as [lo, hi]
** allows (rho grows with |x| at fixed y). */
static double rho_least(double lo, double hi, double y) {
  double x = lo > 0 ? lo : hi < 0 ? -hi : 0;
  return rho_through(x + I * y);
}

static double near_rho(const cubic_map *m, double b) {
  double a = m->a, k = m->k, s = m->up, eps = k * b * b / (a * a * a);
  if (eps < 4.0 / 27) {
    static const double fc[8] = {1, 1, 3, 12, 55, 273, 1428, 7752};
    double f = 0;
    int i;
    for (i = 7; i >= 0; i--) f = f * eps + fc[i];
    return rho_least(s, s, (b / a) * f * (1 - 1e-12));
  } else {
    /* Newton on the convex 8 K Y^3 - 2 A Y - b from above stays above */
    double y = sqrt(a / (2 * k)) + cbrt(b / (4 * k)), lo, xlo, xhi, r, r2;
    int it;
    for (it = 0; it < 50; it++)
      y -= (8 * k * y * y * y - 2 * a * y - b) / (24 * k * y * y - 2 * a);
    lo = y * (1 - 1e-9);
    if (8 * k * lo * lo * lo - 2 * a * lo - b > 0) return 1;  /* unproven */
    xlo = sqrt(fmax(0, 3 * lo * lo - a / k));
    xhi = sqrt(3 * y * y - a / k) * (1 + 1e-12);
    r = rho_least(s + xlo, s + xhi, lo);
    r2 = rho_least(s - xhi, s - xlo, lo);
    if (r2 < r) r = r2;
    r2 = rho_least(s, s, 2 * lo);
    return r2 < r ? r2 : r;
  }
}

static int far_clear(const cubic_map *m, double rho, double dre, double dim) {
  double al = (rho + 1 / rho) / 2, be = (rho - 1 / rho) / 2;
  double a = m->a, k = m->k, r = al + fabs(m->up), xb2;
  if (dim > be * (a + 3 * k * r * r)) return 1;
  if (hypot(dre, dim) > r * (a + k * r * r)) return 1;
  xb2 = (dim / be - a) / (3 * k);
  return xb2 > 0 && fabs(dre) < sqrt(xb2) * (a + k * xb2 - 3 * k * be * be);
}

/* The least order crude_order allows over 20 ellipses up to the near
** preimages' that clear the other pair (0: none does). */
static int rigorous_order(const arclen_hodo *h, const arclen_branch *br,
                          int j0, const cubic_map *m, double len) {
  double rn = near_rho(m, br->im[j0]), dre = br->re[2 - j0] - m->p;
  int s, best = 0;
  for (s = 20; s >= 1 && rn > 1; s--) {
    double rho = 1 + (rn - 1) * s / 20;
    int n;
    if (!far_clear(m, rho, dre, br->im[2 - j0])) continue;
    n = crude_order(h, br, m, rho, len);
    if (best == 0 || n < best) best = n;
  }
  return best;
}

/* The pair whose foot lies inside (0.02, 0.98), the lowest if both do, of
** a speed with two complex pairs (the other is 2 - j); -1 if none. */
static int near_pair(const arclen_branch *b) {
  int k, j = -1;
  if (b->n != 4 || !(b->im[0] > 0 && b->im[2] > 0)) return -1;
  for (k = 0; k < 4; k += 2)
    if (b->re[k] > 0.02 && b->re[k] < 0.98 && (j < 0 || b->im[k] < b->im[j]))
      j = k;
  return j;
}

/* The cost over all curves (see the head): evaluations + 30 per extra
** piece, default and with the certified map (when asked and allowed). */
static void whole_set(void) {
  static double deflt[NCURVES], better[NCURVES], tested[NCURVES];
  double worst = 0;
  int i, mapped = 0;
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    arclen_opts o;
    arclen_info info;
    arclen_hodo h;
    arclen_branch b;
    cubic_map m;
    double v, len;
    int j0, n;
    arclen_opts_init(&o);
    arclen_length_gauss(c, 2, &o, &v, &info);
    deflt[i] = better[i] = tested[i] = info.evals + 30.0 * (info.pieces - 1);
    arclen_hodo_scaled(c, 2, &h);
    arclen_branch_points(&h, &b);
    j0 = near_pair(&b);
    if (j0 < 0 || b.im[j0] > 0.5) continue;
    if (!map_for(&m, b.re[j0], slope_for(b.im[j0]))) continue;
    o.rtol = 1e-15;
    arclen_length_gauss(c, 2, &o, &len, NULL);
    n = rigorous_order(&h, &b, j0, &m, len);
    if (n == 0 || n > ARCLEN_GAUSS_MAX) continue;
    v = fabs(rule(c, n, &m) - len) / len;  /* the bound holds? */
    if (v > worst) worst = v;
    mapped++;
    if (n < better[i]) better[i] = n;
    {   /* the cheap test: the other pair 0.25 off [0, 1], b <= 0.15 */
      double re = b.re[2 - j0], dx = re < 0 ? -re : re > 1 ? re - 1 : 0;
      if (hypot(dx, b.im[2 - j0]) > 0.25 && b.im[j0] <= 0.15) tested[i] = n;
    }
  }
  printf("all %d curves, median of evaluations + 30 per extra piece:\n",
         NCURVES);
  printf("  default method                         %6.1f\n",
         bench_median(deflt, NCURVES));
  printf("  certified map where it asks fewer      %6.1f\n",
         bench_median(better, NCURVES));
  printf("  certified map by the cheap test        %6.1f\n",
         bench_median(tested, NCURVES));
  printf("the certified map's rule on the %d curves it serves errs by at "
         "most %.2g (tolerance 1e-12)\n", mapped, worst);
}

int main(void) {
  double chosen = 0, plain = 0, cut = 0, mapped = 0, bounded = 0;
  double crude = 0, certified = 0;
  int i, count = 0;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    arclen_opts o;
    arclen_info info, i0, i1;
    arclen_hodo h;
    arclen_branch b;
    cubic_map m;
    double len, v, foot, lowest;
    int j0;
    arclen_opts_init(&o);
    arclen_length_gauss(c, 2, &o, &v, &info);
    if (info.pieces != 1 || info.evals < 55 || info.evals > 95) continue;
    arclen_hodo_scaled(c, 2, &h);
    arclen_branch_points(&h, &b);
    j0 = near_pair(&b);
    if (j0 < 0) continue;
    foot = b.re[j0];
    lowest = b.im[j0];
    if (!map_for(&m, foot, SLOPE)) continue;
    o.rtol = 1e-15;
    arclen_length_gauss(c, 2, &o, &len, NULL);
    o.rtol = 1e-12;
    o.t1 = foot;
    arclen_length_gauss(c, 2, &o, &v, &i0);
    o.t0 = foot;
    o.t1 = 1;
    arclen_length_gauss(c, 2, &o, &v, &i1);
    chosen += info.evals;
    plain += oracle(c, len, NULL);
    cut += i0.evals + i1.evals;
    mapped += oracle(c, len, &m);
    bounded += ellipse_order(c, &b, &m, len);
    {
      double rs = rho_star(&b, &m), best = 200;
      int s;
      for (s = 1; s <= 20; s++) {     /* rho from just above 1 to rho* */
        int nn = crude_order(&h, &b, &m, 1 + (rs - 1) * s / 20, len);
        if (nn < best) best = nn;
      }
      crude += best;
    }
    {
      cubic_map mc;
      int n = map_for(&mc, foot, slope_for(lowest))
                  ? rigorous_order(&h, &b, j0, &mc, len)
                  : 0;
      certified += n > 0 && n < info.evals ? n : info.evals;
    }
    count++;
  }
  printf("%d one-piece curves with 55..95 evaluations at tol 1e-12 (mean):\n",
         count);
  printf("  default method, chosen                 %6.1f\n", chosen / count);
  printf("  plain rule on [0,1], oracle            %6.1f\n", plain / count);
  printf("  cut at the foot, default method        %6.1f\n", cut / count);
  printf("  cubic map (slope %.1f), oracle          %6.1f\n", SLOPE,
         mapped / count);
  printf("  cubic map, ellipse bound (M sampled)   %6.1f\n", bounded / count);
  printf("  cubic map, ellipse bound (M bounded)   %6.1f\n", crude / count);
  printf("  certified map, slope per curve, where  %6.1f\n"
         "    it asks fewer points than the default\n", certified / count);
  whole_set();
  return 0;
}
