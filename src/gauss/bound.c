/*
** bound.c -- how many Gauss-Legendre points a piece needs, from the
** branch points of the speed.
**
** On a piece t = c + half_width u, u in [-1, 1], write F(w) = f(c + half_width J(w)) with
** J(w) = (w + 1/w)/2.  The Chebyshev coefficients of f are
**     a_k = (1 / pi i) \oint_{|w|=1} F(w) w^(-k-1) dw,
** and the contour may be pushed out to infinity except around the cuts
** from each branch point's image w_j (|w_j| = rho_j > 1) radially out:
** F grows like w^2, and across a cut F changes sign, so
**     |a_k| <= (4/pi) sum_pairs \int_{rho_j}^inf |F(r e^{i arg w_j})| r^(-k-1) dr
** (a pair and its conjugate give equal terms).  The n-point rule is exact
** to degree 2n - 1, and symmetric, so exact on every odd T_k too; on even
** k >= 2n its error E_n(T_k) is about pi/2 in size for k = 2n and 2n + 2,
** tiny up to 3n and beyond, and never above 2 + 2/(k^2 - 1) <= 32/15
** (ellipse_table.h: bounds for every stored rule).  So its error is at
** most sum_{k even >= 2n} |E_n(T_k)| |a_k| (times half_width for the t integral).
**
** Along the cut, with r = s rho_j and x = s - 1, |J(s w_j) - J(w_j)| <=
** x a_j (a_j = (rho_j + 1/rho_j)/2, the ellipse's semi-axis), and every
** other root R_m lies at most D_m + x half_width a_j from the point; the speed is
** lead prod |t - R_m|^(1/2), so with Z = sqrt(half_width a_j), q_m = sqrt(D_m):
**     |F| <= lead Z x^(1/2) prod_m (q_m + Z x^(1/2)).
** Summing over k, sum_{k even >= 2n} |E_n(T_k)| r^(-k-1) dr <= rho_j^(-2n)
** C_j(n) s^(-2n-1) ds, with C_j(n) the aliasing tail of ellipse_table.h
** (3.3 for rho = 1.12, where the sum over all k with 32/15 for every
** |E_n(T_k)|, (32/15) rho_j/(rho_j - 1), is 20), and each power of x
** integrates to a Beta function (tabulated, gauss_tables.c):
**     E <= half_width (4 / pi) lead sum_j rho_j^(-2n) C_j(n)
**                 sum_i sym_j[i] Z_j^(i+1) B((i+1)/2 + 1, 2n - (i+1)/2).
** C_j(n) falls with n: the orders' estimates take C_j(REF_ORDER) from the
** reference order on, and C_j(2) below it.  Unlike the Bernstein-ellipse
** bound (|f| <= M on the whole ellipse) this sees that f vanishes like a
** square root at the branch point.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "gauss/bound.h"
#include "gauss/ellipse_table.h"
#include "gauss/gauss_tables.h"

/* For the helpers on the path to the first evaluation: one call each
** would cost more than its body. */
#if defined(__GNUC__)
#define ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define ALWAYS_INLINE inline
#endif

#define rough_log2 arclen_rough_log2
#define LOG2_ERR ARCLEN_LOG2_ERR

/* Roots beyond this (scaled units; the hodograph's largest coefficient is
** in [0.5, 1)) would overflow the products below: such curves take the
** ellipse bound. */
#define FAR_ROOT 0x1p100
#define BOUND_MARGIN (1 + 0x1p-40)  /* rounding in the sums below */
#define FAR_PAIR 0x1p40           /* a branch point this many half-widths off */
#define REF_ORDER 32              /* the estimates' order, then 16, 8, 4 */

/* 2^x, never below: 2^k times the degree-4 Taylor polynomial of 2^f (f in
** [0, 1); its remainder is positive and below 0.08%, hence the 1.001). */
static double exp2_above(double x) {
  uint64_t u;
  double k, f, p, s;
  if (!(x > -1000)) return x == x ? 0x1p-1000 : HUGE_VAL;
  if (x > 1000) return HUGE_VAL;
  k = (double)(int64_t)x;
  if (k > x) k -= 1;
  f = x - k;
  p = 1 + f * (0.6931471805599453 + f * (0.2402265069591007 +
          f * (0.0555041086648216 + f * 0.0096181291076285)));
  u = (uint64_t)((int64_t)k + 1023) << 52;
  memcpy(&s, &u, sizeof s);
  return 1.001 * p * s;
}

/* sqrt(x) from above for x >= 0, at most 6.1% high, from the bits: halving
** them (exponent and mantissa together) and adding half the bias gives
** 2^k (1 + f/2) for x = 2^2k (1 + f) and 2^k (3/2 + f/2) for x = 2^(2k+1)
** (1 + f), and (1 + f/2)^2 >= 1 + f, (3/2 + f/2)^2 - 2 (1 + f) = (1/2 -
** f/2)^2 >= 0; the 1 rounds the halving up.  Zero and subnormals come out
** above their root.  For the distances between branch points, which only
** scale the bound (the ellipse's, where a - 1 cancels, take sqrt). */
static double sqrt_above(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  u = (u >> 1) + 0x1ff8000000000000ULL + 1;
  memcpy(&x, &u, sizeof x);
  return x;
}

/* sqrt(hypot(x, y)) from above: hypot(x, y) <= M + (sqrt 2 - 1) m for M, m
** the larger and smaller of |x|, |y| (equal at m = 0 and m = M; at most 8%
** high); the constant is rounded up and the factor covers the sum's
** rounding. */
static double sqrt_hypot_above(double x, double y) {
  double ax = fabs(x), ay = fabs(y);
  double big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
  return sqrt_above((big + 0.41421356237309515 * small) * (1 + 0x1p-50));
}

/* log2(x) from above for x >= 0, within 0.0861: read as an integer, the
** bits of x = 2^e (1 + t) are (e + 1023 + t) 2^52, and log2(1 + t) - t <=
** 0.086071... (at t = 1/ln 2 - 1); zero and subnormals come out above
** -1023.9, which is above their log.  Shorter than rough_log2 (no
** polynomial), for the terms whose absolute error costs a fraction of a
** point; inf and NaN give inf. */
static double log2_above(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  if (!(x < HUGE_VAL)) return HUGE_VAL;
  return (double)(int64_t)u * 0x1p-52 - 1023 + 0.0861;
}

/* Whether root k (and its conjugate, k + 1) is near enough for this bound. */
static int root_near(const arclen_branch *br, int k) {
  return fabs(br->re[k]) <= FAR_ROOT && br->im[k] <= FAR_ROOT;
}

/* Branch pair j of cc from its upper root re + i im, with qx the square
** roots of its distances to the other pair's roots (NULL: no other pair):
** sym holds Z prod_m (q_m + Z) = sum_i e_{nq - i}(q) Z^(i+1), q_0 the root
** of the distance to its conjugate; symref the same times the Beta
** integrals at the reference order. */
static ALWAYS_INLINE void set_pair(arclen_cut_curve *cc, int j, double re,
                                   double im, const double *qx) {
  double q0 = sqrt_above(2 * im), sym[4];
  int i;
  cc->re[j] = re;
  cc->im[j] = im;
  if (!qx) {
    sym[0] = q0;
    sym[1] = 1;
    sym[2] = sym[3] = 0;
  } else {
    sym[0] = q0 * qx[0] * qx[1];
    sym[1] = q0 * (qx[0] + qx[1]) + qx[0] * qx[1];
    sym[2] = q0 + qx[0] + qx[1];
    sym[3] = 1;
  }
  for (i = 0; i < 4; i++) {   /* from the local copy: no stores read back */
    cc->sym[j][i] = sym[i];
    cc->symref[j][i] = sym[i] * arclen_gauss_beta[i][REF_ORDER];
  }
}

/* Between the pairs of roots 0 and 2: sqrt |R1 - R2|, sqrt |R1 - conj R2|. */
static ALWAYS_INLINE void pair_distances(const arclen_branch *br,
                                         double qx[2]) {
  double dx = br->re[2] - br->re[0];
  double dm = br->im[2] - br->im[0], dp = br->im[2] + br->im[0];
  qx[0] = sqrt_hypot_above(dx, dm);
  qx[1] = sqrt_hypot_above(dx, dp);
}

void arclen_cut_prepare(const arclen_branch *br, arclen_cut_curve *cc) {
  double qx[2] = {0, 0};
  int k;
  cc->br = br;
  cc->ok = 1;
  cc->has_real = 0;
  cc->npair = 0;
  for (k = 0; k < br->n; k += 2)      /* k + 1 holds the conjugate */
    if (!root_near(br, k)) cc->ok = 0;
  if (!cc->ok) return;
  if (br->n == 4) pair_distances(br, qx);
  for (k = 0; k < br->n; k += 2) {
    if (br->im[k] == 0) {                /* a real root: no branch point */
      cc->has_real = 1;
      continue;
    }
    set_pair(cc, cc->npair++, br->re[k], br->im[k], br->n == 4 ? qx : NULL);
  }
}

/* Z (s[0] + s[1] Z + s[2] Z^2 + s[3] Z^3), in Estrin's order: the two
** halves side by side (it lies on the path to the first evaluation). */
static double horner_z(const double s[4], double z) {
  double z2 = z * z;
  return z * ((s[0] + s[1] * z) + z2 * (s[2] + s[3] * z));
}

/* Term j of the bound but for 2^(-n lam_j): C_j(2) times the sum over i of
** sym_j[i] Z_j^(i+1) and the Beta integral at order n. */
static ALWAYS_INLINE double term_sum(const double sym[4], int n, double c,
                                     double z) {
  double s[4];
  int i;
  for (i = 0; i < 4; i++) s[i] = sym[i] * arclen_gauss_beta[i][n];
  return c * horner_z(s, z);
}

/* log2 of term j's sum at order n, from above (log2_above: the estimates
** below the reference order run on pieces cut at a foot, of ~20 points) */
static ALWAYS_INLINE double term_log2(const arclen_cut_curve *cc,
                                      const arclen_cut_piece *pbound, int j,
                                      int n) {
  return log2_above(term_sum(cc->sym[j], n, pbound->cc[j], pbound->z[j]));
}

/* The ellipse's quantities for x = a - 1 (rounded down) from the table:
** lines on x's cell (arclen_ellipse_cell_of), no square root or division
** on the way to the order.  0 when x lies off the table. */
static ALWAYS_INLINE int from_table(double am1, double sqrthh,
                                    arclen_cut_piece *pbound, int j) {
  double dx;
  const arclen_ellipse_cell *e = arclen_ellipse_cell_of(am1, &dx);
  if (!e) return 0;
  pbound->lam[j] = e->lam + dx * e->dlam;
  pbound->ilam[j] = e->ilam + dx * e->dilam;
  pbound->cc[j] = e->c2 + dx * e->dc2;
  pbound->cref[j] = e->cref + dx * e->dcref;
  pbound->z[j] = sqrthh * (e->sa + dx * e->dsa);
  return 1;
}

/* The same from their formulas, for x off the table (C(2) for both C's).
** b = sqrt(a^2 - 1) and rho = a + b; next to the interval a - 1 cancels,
** so x is rounded down by the sum's rounding (r1, r2 are each within 2
** ulps), and rho is never above the true one; g = rho^2 - 1 = 2 b rho. */
static void from_formulas(double am1, double s12, double half_width,
                          arclen_cut_piece *pbound, int j) {
  const double *al = arclen_gauss_alias;
  double b, rho, g, r;
  if (!(am1 > 0)) am1 = 0;             /* on the interval, or NaN */
  b = sqrt(am1 * (am1 + 2));
  rho = 1 + am1 + b;
  g = 2 * b * rho;
  if (g < 4) {
    /* ln(1 + g) = 2 atanh(y), y = g/(2 + g) < 2/3, whose series has
    ** positive terms: cut after y^9/9 it is below, by at most 0.12%;
    ** g carries some 6 ulps of rounding, the margin is 64 */
    double y = g / (2 + g), y2 = y * y;
    pbound->lam[j] = 2 * y * (1 + y2 * (1.0 / 3 + y2 * (0.2 + y2 * (1.0 / 7 +
                 y2 * (1.0 / 9))))) * (1.4426950408889634 * (1 - 0x1p-46));
  } else {
    pbound->lam[j] = rough_log2(1 + g) - LOG2_ERR;
  }
  pbound->ilam[j] = 1 / pbound->lam[j];
  /* C(2) with r = rho^-2 = 1/(1 + g), 1/(1 - r) = (1 + g)/g (inf when
  ** g = 0: lam = 0 too), the roundings covered by the factor */
  r = 1 / (1 + g);
  pbound->cc[j] = (al[0] + al[1] * r + (al[2] * r * r + (32.0 / 15) * r / rho) *
               ((1 + g) / g)) * (1 + 0x1p-44);
  pbound->cref[j] = pbound->cc[j];
  pbound->z[j] = sqrt(half_width * s12 * (0.5 + 0x1p-50));   /* a rounded up */
}

/* Term j of the bound of the piece [c - half_width, c + half_width] (inv = 1/half_width, sqrthh =
** sqrt(half_width)). */
static ALWAYS_INLINE void pair_bound(const arclen_cut_curve *cc, int j,
                                     double c, double half_width, double inv,
                                     double sqrthh, arclen_cut_piece *pbound) {
  /* The Bernstein ellipse through the branch point z = u + iv (piece
  ** units): a - 1 from below (arclen_ellipse_am1), and all else taken from
  ** it, from the table or the formulas, each erring on the safe side. */
  double dr = cc->re[j] - c, im = cc->im[j];
  if (fabs(dr) + im > FAR_PAIR * half_width) {
    /* Far from the piece (|z| >= 2^39; for a piece of subnormal width u
    ** and v would overflow): rho >= a >= |z| >= max(|dr|, im)/half_width, so
    ** C(n) <= alias[0] + 2^-70, and half_width a <= half_width (|z| + 1) <= |dr| + im +
    ** half_width bounds Z^2. */
    double dmax = fabs(dr) > im ? fabs(dr) : im;
    pbound->lam[j] = 2 * (rough_log2(dmax) - rough_log2(half_width) - 2 * LOG2_ERR);
    pbound->cc[j] = pbound->cref[j] = arclen_gauss_alias[0] * (1 + 0x1p-40);
    pbound->z[j] = sqrt((fabs(dr) + im + half_width) * (1 + 0x1p-50));
    pbound->ilam[j] = 1 / pbound->lam[j];
  } else {
    double s12, am1 = arclen_ellipse_am1(dr * inv, im * inv, &s12);
    if (!from_table(am1, sqrthh, pbound, j))
      from_formulas(am1, s12, half_width, pbound, j);
  }
  /* log2 of term j's sum at REF_ORDER (Beta integrals taken in
  ** prepare), from above */
  pbound->lref[j] = log2_above(pbound->cref[j] *
                           horner_z(cc->symref[j], pbound->z[j]));
}

/* 1/half_width and sqrt(half_width), known for the whole range ([0, 1] or [-1, 1]). */
static double inverse_of(double half_width) {
  return half_width == 0.5 ? 2 : half_width == 1 ? 1 : 1 / half_width;
}
static double sqrt_of(double half_width) {
  return half_width == 0.5 ? 0.70710678118654757 : half_width == 1 ? 1 : sqrt(half_width);
}

void arclen_cut_bound(const arclen_cut_curve *cc, double c, double half_width,
                      arclen_cut_piece *pbound) {
  double inv = inverse_of(half_width), sqrthh = sqrt_of(half_width);
  int j, k;
  pbound->nt = cc->npair;
  pbound->inside = 0;
  if (cc->has_real) {
    const arclen_branch *br = cc->br;
    for (k = 0; k < br->n; k += 2)
      if (br->im[k] == 0 && fabs(br->re[k] - c) < half_width * (1 - 1e-12))
        pbound->inside = 1;                  /* a kink: the rule cannot see it */
  }
  for (j = 0; j < cc->npair; j++) pair_bound(cc, j, c, half_width, inv, sqrthh, pbound);
}

/* The bound at order n over 2^lgoal. */
double arclen_cut_ratio(const arclen_cut_curve *cc,
                        const arclen_cut_piece *pbound, double lgoal, int n) {
  double r = 0;
  int j;
  for (j = 0; j < pbound->nt; j++)
    r += exp2_above(-n * pbound->lam[j] - lgoal) *
         term_sum(cc->sym[j], n, n >= REF_ORDER ? pbound->cref[j] : pbound->cc[j],
                  pbound->z[j]);
  return r * BOUND_MARGIN;
}

/* ceil(x) for the order estimates, in [2, 1000] (NaN: 1000); ceil() is a
** call on baseline x86-64. */
static int order_ceil(double x) {
  int n;
  if (!(x < 1000)) return 1000;
  if (x < 2) return 2;
  n = (int)x;
  return n < x ? n + 1 : n;
}

/* The least order n >= m at which the terms, bounded by 2^(l_j - n lam_j)
** (l_j: log2 of term j's Beta sum at order m, an upper bound for every
** n >= m since the Beta integrals fall with n), sum to at most 2^lgoal; or
** a smaller n when that is below m (not yet a bound).  Each term gets
** 63/64 of the goal; a second term must then lie below 1/64 of it, else
** each gets half. */
#define SHARE_LOG2 0.0228         /* log2(64/63) = 0.02272..., rounded up */
static ALWAYS_INLINE int order_at(const arclen_cut_piece *pbound,
                                  const double *l, double lgoal) {
  double n0 = (l[0] - lgoal + SHARE_LOG2) * pbound->ilam[0], n1;
  int n;
  if (pbound->nt == 1) return order_ceil(n0);
  n1 = (l[1] - lgoal + SHARE_LOG2) * pbound->ilam[1];
  n = order_ceil(n0 > n1 ? n0 : n1);
  if (l[0] - n * pbound->lam[0] <= lgoal - 6 || l[1] - n * pbound->lam[1] <= lgoal - 6)
    return n;
  n0 = (l[0] - lgoal + 1) / pbound->lam[0];
  n1 = (l[1] - lgoal + 1) / pbound->lam[1];
  return order_ceil(n0 > n1 ? n0 : n1);
}

static ALWAYS_INLINE int order_of(const arclen_cut_curve *cc,
                                  const arclen_cut_piece *pbound, double lgoal,
                                  int nmax, double *ratio) {
  int j, n, m;
  if (pbound->inside) return 0;
  if (pbound->nt == 0) {                     /* a polynomial: exact from n = 2 */
    if (ratio) *ratio = 0;
    return 2;
  }
  for (j = 0; j < pbound->nt; j++)
    if (!(pbound->lam[j] > 0)) return 0;     /* rho ~ 1: no order will do */
  /* From the reference order down by halves: an estimate n >= m is a
  ** bound and too high by about 1.5 log2(n/m) / lam points. */
  n = order_at(pbound, pbound->lref, lgoal);
  for (m = REF_ORDER / 2; n < 2 * m && m >= 4; m /= 2) {
    double l[2] = {0, 0};   /* l[1] is read only when nt = 2 */
    for (j = 0; j < pbound->nt; j++) l[j] = term_log2(cc, pbound, j, m);
    n = order_at(pbound, l, lgoal);
  }
  if (n < 2 * m)                         /* below all: the sum itself */
    while (n < 2 * m && arclen_cut_ratio(cc, pbound, lgoal, n) > 1) n++;
  if (n > nmax) return 0;
  if (ratio) *ratio = arclen_cut_ratio(cc, pbound, lgoal, n);
  return n;
}

int arclen_cut_order(const arclen_cut_curve *cc, const arclen_cut_piece *pbound,
                     double lgoal, int nmax, double *ratio) {
  return order_of(cc, pbound, lgoal, nmax, ratio);
}

/* arclen_cut_prepare for the common case (two complex pairs within reach,
** so no real root and no far one), then arclen_cut_bound and
** arclen_cut_order for each piece, in one frame: the records stay local,
** and the compiler keeps most of them in registers. */
static ALWAYS_INLINE int orders_of(const arclen_branch *br, int np,
                                   const double *c, const double *half_width,
                                   double lgoal, int nmax, int *n) {
  arclen_cut_curve cc;
  arclen_cut_piece pbound[ARCLEN_CUT_PIECES];
  double qx[2];
  int i;
  if (br->n != 4 || !(br->im[0] > 0 && br->im[2] > 0)) return 0;
  if (!root_near(br, 0) || !root_near(br, 2)) return 0;
  cc.br = br;
  cc.ok = 1;
  cc.has_real = 0;
  cc.npair = 2;
  pair_distances(br, qx);
  set_pair(&cc, 0, br->re[0], br->im[0], qx);
  set_pair(&cc, 1, br->re[2], br->im[2], qx);
  for (i = 0; i < np; i++) {      /* the pieces' chains side by side */
    double inv = inverse_of(half_width[i]), sqrthh = sqrt_of(half_width[i]);
    pbound[i].nt = 2;
    pbound[i].inside = 0;
    pair_bound(&cc, 0, c[i], half_width[i], inv, sqrthh, &pbound[i]);
    pair_bound(&cc, 1, c[i], half_width[i], inv, sqrthh, &pbound[i]);
  }
  for (i = 0; i < np; i++)
    if (!(n[i] = order_of(&cc, &pbound[i], lgoal, nmax, NULL))) return 0;
  return 1;
}

int arclen_cut_orders(const arclen_branch *br, int np, const double *c,
                      const double *half_width, double lgoal, int nmax, int *n) {
  if (np == 1)            /* the commonest case: the loops unrolled */
    return orders_of(br, 1, c, half_width, lgoal, nmax, n);
  return np > 1 && np <= ARCLEN_CUT_PIECES &&
         orders_of(br, np, c, half_width, lgoal, nmax, n);
}
