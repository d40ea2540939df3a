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
**     cheap, and a bound once rho is.
** "Truth" is the default method's length at tol 1e-15.  An exploration,
** not a test: run by `make bench-explore`.
*/
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "arclen.h"
#include "bench_util.h"
#include "cubic.h"
#include "gauss_tables.h"

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
  double lo = -0.999, hi = 0.999, z1;
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
  z1 = 1 - m->up;
  m->k = (1 - p - a * z1) / (z1 * z1 * z1);
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

/* The order the ellipse bound asks for with M bounded by the triangle
** inequality (see the head), in scaled units (h), on the ellipse rho. */
static int crude_order(const arclen_hodo *h, const arclen_branch *b,
                       const cubic_map *m, double rho, double len) {
  double a = (rho + 1 / rho) / 2, r = a + fabs(m->up);
  double far = m->a * r + m->k * r * r * r, big = sqrt(b->lead2);
  int k, n;
  for (k = 0; k < b->n; k++)   /* |map(u) - r_k| <= far + |p - r_k| */
    big *= sqrt(far + hypot(m->p - b->re[k], b->im[k]));
  big *= m->a + 3 * m->k * r * r;
  len = ldexp(len, -h->exp);
  for (n = 2; n < 200; n++)
    if ((64.0 / 15.0) * big * pow(rho, 2 - 2 * n) / (rho * rho - 1) <=
        1e-12 * len)
      break;
  return n;
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
  int j, n;
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
  for (n = 2; n < 200; n++)
    if ((64.0 / 15.0) * big * pow(rho, 2 - 2 * n) / (rho * rho - 1) <=
        1e-12 * len)
      break;
  return n;
}

int main(void) {
  double chosen = 0, plain = 0, cut = 0, mapped = 0, bounded = 0;
  double crude = 0;
  int i, count = 0;
  bench_random_curves(curves, NCURVES, 20261121);
  for (i = 0; i < NCURVES; i++) {
    const double *c = curves + 8 * i;
    arclen_opts o;
    arclen_info info, i0, i1;
    arclen_hodo h;
    arclen_branch b;
    cubic_map m;
    double len, v, foot = -1, lowest = HUGE_VAL;
    int k;
    arclen_opts_init(&o);
    arclen_length_gauss(c, 2, &o, &v, &info);
    if (info.pieces != 1 || info.evals < 55 || info.evals > 95) continue;
    arclen_hodo_scaled(c, 2, &h);
    arclen_branch_points(&h, &b);
    for (k = 0; k < b.n; k += 2)
      if (b.re[k] > 0.02 && b.re[k] < 0.98 && b.im[k] < lowest) {
        lowest = b.im[k];
        foot = b.re[k];
      }
    if (foot < 0 || !map_for(&m, foot, SLOPE)) continue;
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
  return 0;
}
