/*
** arclen.h -- the public C API of arclen: arc length of cubic Bezier
** curves and what goes with it.  No Lua dependency; link with -lm.
**
** A cubic is given by its control points, flattened:
**   2D: c[8]  = x0 y0 x1 y1 x2 y2 x3 y3
**   3D: c[12] = x0 y0 z0 x1 y1 z1 x2 y2 z2 x3 y3 z3
** Tolerances are relative unless a name says otherwise.
*/
#ifndef ARCLEN_H
#define ARCLEN_H

#include <stddef.h>

#define ARCLEN_VERSION "arclen 1.0.0"

/* Tolerance range accepted by every error-controlled method. */
#define ARCLEN_RTOL_MIN 1e-15
#define ARCLEN_RTOL_MAX 0.1

/* Error codes of the reporting variants (0 is success). */
enum {
  ARCLEN_OK = 0,
  ARCLEN_EINVAL = -1,     /* non-finite coordinate or argument */
  ARCLEN_ETOL = -2,       /* tolerance outside [RTOL_MIN, RTOL_MAX] */
  ARCLEN_ERANGE = -3,     /* parameter range outside [0, 1] */
  ARCLEN_EDIM = -4,       /* dimension not supported by this method */
  ARCLEN_EDOMAIN = -5,    /* argument outside a function's domain */
  ARCLEN_EOVERFLOW = -6,  /* arithmetic overflow (e.g. MetaPost's limit) */
  ARCLEN_ENOCONV = -7     /* iteration cap reached before the tolerance */
};

const char *arclen_strerror(int code);

/* What a computation cost and how good it thinks it is. */
typedef struct arclen_info {
  long evals;          /* integrand (speed) evaluations */
  long pieces;         /* final subintervals, subdivisions or leaves */
  int depth;           /* deepest bisection level reached */
  double err;          /* absolute error estimate (0 for closed forms) */
  const char *branch;  /* method-specific branch taken, or NULL */
  long calls;          /* special-function calls (e.g. R-functions) */
} arclen_info;

/* Options common to every method. */
typedef struct arclen_opts {
  double rtol;         /* relative tolerance */
  double t0, t1;       /* parameter sub-range, 0 <= t0, t1 <= 1 */
  long steps;          /* fixed step count for the baseline methods (0: default) */
} arclen_opts;

void arclen_opts_init(arclen_opts *o);   /* rtol 1e-12, [0, 1], steps 0 */
void arclen_info_init(arclen_info *info);

/* A method computes the length of a cubic of dimension dim (2 or 3) over
** [o->t0, o->t1] (t0 > t1 gives the negative of the reversed range).
** Returns 0 or an error code; *len is NaN on error.  info may be NULL. */
typedef int (*arclen_length_fn)(const double *c, int dim,
                                const arclen_opts *o, double *len,
                                arclen_info *info);
/* A time method: t in [0, 1] with s(t) = s, where s(t) is the length from
** parameter 0.  s <= 0 gives 0, s >= L gives 1. */
typedef int (*arclen_time_fn)(const double *c, int dim, double s,
                              const arclen_opts *o, double *t,
                              arclen_info *info);

/* ---- methods/: methods by name --------------------------------------- */
typedef struct arclen_method {
  const char *name;
  arclen_length_fn length;
  arclen_time_fn time;      /* NULL when the method has no inverse */
} arclen_method;
const arclen_method *arclen_find_method(const char *name);
const arclen_method *arclen_method_list(void);   /* ends with name NULL */

/* ---- curve/: the geometry of one cubic ------------------------------- */
int arclen_check_curve(const double *c, int dim);        /* 0 or EINVAL */
void arclen_point(const double *c, int dim, double t, double *p);
void arclen_derivative(const double *c, int dim, double t, double *d);
/* The unit tangent at t (dim numbers into v): z'(t) normalised; where z'
** vanishes the limit direction (z'', negated at t = 1, then z'''); a
** curve that is a point gets zeros. */
void arclen_unit_tangent(const double *c, int dim, double t, double *v);
void arclen_split(const double *c, int dim, double t, double *left,
                  double *right);
void arclen_subcurve(const double *c, int dim, double t0, double t1,
                     double *out);
/* Hodograph z'(t) = a2 t^2 + a1 t + a0 (per coordinate, dim each). */
void arclen_hodograph(const double *c, int dim, double a2[3], double a1[3],
                      double a0[3]);
/* Real roots in the open interval (0, 1) of the cubic Q'.Q'' (the speed's
** critical points: minima, maxima, cusps), ascending; returns the count. */
int arclen_critical_points(const double *c, int dim, double roots[3]);

/* ---- gauss/: the default method ("gauss") ---------------------------- */
double arclen_length(const double c[8], double rtol);
double arclen_length_range(const double c[8], double t0, double t1,
                           double rtol);
double arclen_time(const double c[8], double s, double rtol);
double arclen_length3(const double c[12], double rtol);
double arclen_length3_range(const double c[12], double t0, double t1,
                            double rtol);
double arclen_time3(const double c[12], double s, double rtol);
int arclen_length_gauss(const double *c, int dim, const arclen_opts *o,
                        double *len, arclen_info *info);
int arclen_time_gauss(const double *c, int dim, double s,
                      const arclen_opts *o, double *t, arclen_info *info);
/* The parameters t[i] at the lengths s[i] (i < n, ascending) from the
** start of the cubic, each within rtol times the length as
** arclen_time_gauss's, in one pass: the curve's set-up and the pieces'
** rules serve every distance, and a distance's search starts where the
** previous one's ended; the t are ascending.  s <= 0 gives 0, s >= the
** length 1.  pts and tan (dim n numbers each, may be NULL) get the points
** and unit tangents (at a zero derivative the limit direction; a point
** has zeros).  Returns ARCLEN_EDOMAIN for n < 0 or s not ascending,
** ARCLEN_EINVAL for a NaN distance (t then all NaN), or the curve's and
** tolerance's codes. */
int arclen_times(const double *c, int dim, const double *s, long n,
                 double rtol, double *t, double *pts, double *tan);
/* A fixed n-point Gauss-Legendre rule on [0,1] (n = 24: the speed floor). */
double arclen_length_gl(const double *c, int dim, int n);

/* ---- elliptic/: Carlson's symmetric elliptic integrals ---------------- */
/* Carlson (1995) duplication.  Arguments >= 0 unless stated; NaN on a
** domain error (negative argument, a non-finite one, or an infinite
** integral: two zeros in R_F, x = y = 0 or z = 0 in R_D, y = 0 in R_C,
** p = 0 or two zeros in R_J).  y < 0 in R_C and p < 0 in R_J give the
** Cauchy principal values. */
double arclen_rf(double x, double y, double z);
double arclen_rd(double x, double y, double z);
double arclen_rc(double x, double y);
double arclen_rj(double x, double y, double z, double p);
double arclen_rg(double x, double y, double z);

/* ---- gauss/: many curves at once ------------------------------------- */
/* out[i] = the length of cubic i of n, whose 4 dim numbers start at
** c + 4 dim i, by method m with options o.  Stops at the first failure:
** returns its code, sets *failed (may be NULL; -1 on success) to its index
** and out[i..n-1] to NaN.  EDIM for dim other than 2 and 3. */
int arclen_lengths(const double *c, long n, int dim, const arclen_method *m,
                   const arclen_opts *o, double *out, long *failed);

/* ---- roots/: real-coefficient polynomial roots ----------------------- */
/* All roots of a real quadratic, cubic, quartic (highest coefficient
** first); complex roots come as conjugate pairs (re, +-im).  Returns the
** number of roots (fewer when leading coefficients are 0).  Any finite
** coefficients (subnormal to 1e308): the cubic and quartic solve each group
** of the Newton polygon in its own power-of-two scale, so a root beyond the
** double range (5e-324 x^3 - 6 x^2 + ...: 1.2e324) comes out as +-inf in re
** or im, never NaN; the others keep their accuracy. */
int arclen_quadratic(double a2, double a1, double a0, double re[2],
                     double im[2]);
int arclen_cubic(double a3, double a2, double a1, double a0, double re[3],
                 double im[3]);
int arclen_quartic(double a4, double a3, double a2, double a1, double a0,
                   double re[4], double im[4]);
/* The quartic / a4 as (x^2 + q0 x + q1)(x^2 + q2 x + q3), real q
** (Algorithm 1010 style, Newton-polished; roots spread over the Newton
** polygon pair up conjugates together, reals by size); q beyond the double
** range is +-inf.  0, or ARCLEN_EDOMAIN for a4 == 0 or a non-finite a_k. */
int arclen_quartic_factor(double a4, double a3, double a2, double a1,
                          double a0, double q[4]);

/* ---- elliptic/: exact length by Carlson's [1,1,1,1] ------------------ */
/* Method "elliptic": the exact length integral by Carlson's [1,1,1,1]
** (2D: complex hodograph roots; 3D: the quartic split by roots.c), with
** closed forms for cusps, collinear curves and points and series for far
** roots.  info->branch names the branch, info->calls the R-calls. */
int arclen_length_elliptic(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info);

/* ---- baseline/, metapost/: Henkel's other rows ----------------------- */
/* Gravesen (1997) adaptive subdivision: on de Casteljau halves the length
** estimate (2 chord + (n-1) polygon)/(n+1), n = 3; info->pieces counts
** subdivisions (Henkel's "Steps").  2D and 3D. */
int arclen_length_gravesen(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info);
/* The same with Richardson's extrapolation (16 S_{k+1} - S_k)/15, since the
** estimate's error falls 16-fold per halving. */
int arclen_length_gravesen_richardson(const double *c, int dim,
                                      const arclen_opts *o, double *len,
                                      arclen_info *info);

/* MetaPost's arclength and arctime (mp.w arc_test) in mpost's double number
** system, bit-identical to `mpost -numbersystem=double`.  2D only.  A leg
** |P1-P0|, |P2-P1| or |P3-P2| >= 16384 gives ARCLEN_EOVERFLOW where mpost
** reports "Arithmetic overflow".  info: evals = arc_test calls, pieces =
** Simpson leaves, depth = deepest bisection. */
int arclen_mp_arclength(const double c[8], double *len, arclen_info *info);
int arclen_mp_arctime(const double c[8], double goal, double *t,
                      arclen_info *info);
/* A MetaPost path of n >= 1 cubic segments, 8 numbers each (segment k ends
** where k+1 starts); cyclic != 0 when the last segment closes the path.
** Times are MetaPost's: segment index + parameter; negative goals, goals
** beyond the end and turns around a cycle as MetaPost 2.11. */
int arclen_mp_path_arclength(const double *seg, int n, int cyclic,
                             double *len, arclen_info *info);
int arclen_mp_path_arctime(const double *seg, int n, int cyclic, double goal,
                           double *t, arclen_info *info);
/* As the method "metapost" (a sub-range is cut out with arclen_subcurve). */
int arclen_length_metapost(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info);
int arclen_time_metapost(const double *c, int dim, double s,
                         const arclen_opts *o, double *t, arclen_info *info);

/* Henkel's fixed-step rows with N = o->steps (0: ARCLEN_BASELINE_STEPS). */
#define ARCLEN_BASELINE_STEPS 1000000L
/* Sum of the N chords ("hypotenuse sum", Henkel's Eqn 3).  2D and 3D. */
int arclen_length_polyline(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info);
/* Trapezoid rule on sqrt of the quartic radicand (Eqn 7).  2D and 3D. */
int arclen_length_trapezoid(const double *c, int dim, const arclen_opts *o,
                            double *len, arclen_info *info);
/* Trapezoid rule on the factored speed |A2| |t - s1| |t - s2| (Eqn 10), with
** s1, s2 the complex roots of z'(t).  2D only. */
int arclen_length_trapezoid_factored(const double *c, int dim,
                                     const arclen_opts *o, double *len,
                                     arclen_info *info);

/* ---- curve/: Gauss-Legendre rules of any order ----------------------- */
/* The n-point Gauss-Legendre rule on [0, 1], computed by
** Newton's method on P_n (no tables): nodes x ascending, weights w
** summing to 1.  n in [1, ARCLEN_GL_MAXN]; returns 0 or ARCLEN_EDOMAIN. */
#define ARCLEN_GL_MAXN 64
int arclen_gauss_legendre(int n, double *x, double *w);

/* ---- fit/: length-versus-t fits --------------------------------------- */

/* A fit of s(t)/s(1) by cubic functional Bezier spans: span i covers
** [t0, t1] with x-controls t0, t0+h/3, t0+2h/3, t1 (so no root finding
** in t) and ordinates y[0..3] (Walter & Fournier 1996, Eqns 3-5). */
enum { ARCLEN_FIT_HERMITE = 0, ARCLEN_FIT_PAPER = 1 };
#define ARCLEN_FIT_MAXSPANS 512    /* cap on adaptive refinement */
#define ARCLEN_FIT_TOL_MIN 1e-9    /* 1e-10 can need more than MAXSPANS */
typedef struct arclen_fit_opts {
  int method;      /* ARCLEN_FIT_HERMITE (default) or ARCLEN_FIT_PAPER */
  int n;           /* Gauss-Legendre points: per node (paper, default 10)
                      or per piece (hermite, default 2); 0 = default */
  double tol;      /* hermite: max error in s/s(1); 0 = fixed knots */
  int monotone;    /* paper: project each span onto the monotone set */
} arclen_fit_opts;
typedef struct arclen_fit_span {
  double t0, t1;   /* parameter range */
  double y[4];     /* Bezier ordinates of s/s(1) */
} arclen_fit_span;
/* A fit.  Read dim .. span; the fields from itotal on are the fit's
** working state (the curve in internal units), used by fit/ only. */
typedef struct arclen_fit {
  int dim, method, n;
  int ncrit;             /* speed's critical points in (0,1) */
  double crit[3];        /* ("inflexion points" of s(t) in the paper) */
  double total;          /* s(1) used for normalising, curve units */
  double itotal;         /* the same in internal units (never overflows) */
  int scale_exp;         /* curve units = 2^scale_exp internal units */
  double tol;            /* requested tolerance (0: fixed knots) */
  long evals;            /* speed evaluations spent building */
  double c[12];          /* the curve, as given */
  double cs[12];         /* (c - P0) / 2^scale_exp: magnitudes <= 1 */
  double hod[9];         /* hodograph of cs: a2, a1, a0 (3 each) */
  int nspans;
  arclen_fit_span *span; /* nspans spans, ascending in t */
} arclen_fit;
void arclen_fit_opts_init(arclen_fit_opts *o);
/* Build the fit of c into f, with room for cap spans at spans (f->span
** points there).  Returns 0, ARCLEN_EINVAL, ARCLEN_EDIM, ARCLEN_EDOMAIN
** (bad n or method), ARCLEN_ETOL, or ARCLEN_ENOCONV (tol needs > cap). */
int arclen_fit_build(const double *c, int dim, const arclen_fit_opts *o,
                     arclen_fit *f, arclen_fit_span *spans, int cap);
/* The speed of cs at t (times 2^scale_exp: curve units). */
double arclen_fit_speed(const arclen_fit *f, double t);
/* O(1) evaluation.  t is clamped to [0, 1]; s to
** [0, total]. */
double arclen_fit_value(const arclen_fit *f, double t);   /* ~ s(t)/s(1) */
double arclen_fit_slope(const arclen_fit *f, double t);   /* d/dt of it */
double arclen_fit_length(const arclen_fit *f, double t);  /* ~ s(t) */
double arclen_fit_time(const arclen_fit *f, double s);    /* inverse */
double arclen_fit_invert(const arclen_fit *f, double v);  /* of value */
/* 1 when every span is non-decreasing (exact Bernstein test). */
int arclen_fit_monotone(const arclen_fit *f);
int arclen_fit_span_monotone(const arclen_fit_span *sp);
/* The paper's error measurement (Eqn 9).
** Truth: Numerical Recipes' qsimp at fractional accuracy 1e-4 (as the
** paper), or the accurate length (arclen_length_gauss, rtol 1e-13).
** Grid: npts = 0 is the paper's t = 0, 0.05, ..., 0.95 (its loop
** "t += 0.05" in double); npts > 0 is t = k/npts, k = 0..npts.
** inverse = 1 measures |s_true(t_fit(u))/s(1) - u| at the grid's u
** instead.  Fills max, mean and the grid point of the max. */
enum { ARCLEN_TRUTH_SIMPSON = 0, ARCLEN_TRUTH_EXACT = 1 };
int arclen_fit_error(const arclen_fit *f, int truth, int inverse, int npts,
                     double *max, double *mean, double *argmax);

/* ---- conic/: cubic approximation of conics --------------------------- */
/* Floater (1996).  A conic is the rational quadratic Bezier curve with
** control points p[6] = x0 y0 x1 y1 x2 y2 and weight w > 0 (eq. 1):
** ellipse w < 1, parabola w = 1, hyperbola w > 1; any finite w > 0 (w ->
** inf: the control polygon, w -> 0: the chord; A, B, bounds ~ w^2 are inf
** beyond the double range, never NaN).  Level r: the 2^r pieces
** of the subdivision scheme (eq. 4), each replaced by one cubic. */
enum {
  ARCLEN_CONIC_QUADRATIC,   /* Prop 3: lambda = 2/3 */
  ARCLEN_CONIC_G2,          /* Prop 4: G2 Hermite */
  ARCLEN_CONIC_MIDPOINT,    /* Prop 5: mid-point Hermite (the default) */
  ARCLEN_CONIC_C2,          /* Prop 8: C2 spline */
  ARCLEN_CONIC_G4,          /* Props 9-10: G4 spline */
  ARCLEN_CONIC_NSCHEMES
};
#define ARCLEN_CONIC_MAXLEVEL 16   /* 65536 pieces */
int arclen_conic_scheme(const char *name);          /* -1 when unknown */
const char *arclen_conic_scheme_name(int scheme);   /* NULL when out of range */
double arclen_conic_lambda(int scheme, double w);
/* Prop 2's A, B for w and delta = lambda - 2/3 (cancellation-free near 1). */
void arclen_conic_AB(double w, double delta, double *A, double *B);
void arclen_conic_scheme_AB(int scheme, double w, double *A, double *B);
double arclen_conic_gnorm(double A, double B);       /* Prop 13 */
double arclen_conic_weight(double w, int level);     /* w_r of eq. (4) */
/* 1 when p0 = p1, p1 = p2 or the three are collinear (to rounding). */
int arclen_conic_degenerate(const double p[6]);
/* ARCLEN_OK, EINVAL (non-finite point) or EDOMAIN (bad w, degenerate). */
int arclen_conic_check(const double p[6], double w);
/* Theorem 1 / eq. (18) at a level: +inf when lambda(w_r) > 1 (the theorem
** does not apply).  Return 0, EINVAL, EDOMAIN, ERANGE (level outside
** [0, MAXLEVEL]) or EINVAL (unknown scheme). */
int arclen_conic_bound(const double p[6], double w, int scheme, int level,
                       double *bound);
/* Smallest level whose bound is <= tol (absolute distance); ENOCONV when
** even MAXLEVEL's is not (then *level = MAXLEVEL). */
int arclen_conic_level(const double p[6], double w, int scheme, double tol,
                       int *level, double *bound);
/* The 2^level cubics of eq. (6) into out[8 << level]; *bound (may be NULL)
** as arclen_conic_bound.  The first and last points are p0, p2 exactly.
** EOVERFLOW when a control point lies beyond DBL_MAX (only the mid-point
** scheme, whose lambda exceeds 1 for w > 2, leaves the triangle). */
int arclen_conic_cubics(const double p[6], double w, int scheme, int level,
                        double *out, double *bound);
void arclen_conic_point(const double p[6], double w, double t, double pt[2]);
/* The exact length of the whole arc (R_F, R_D; parabola
** in closed form).  info (may be NULL): branch ellipse/parabola/hyperbola,
** calls = R-function calls.  0, EINVAL, EDOMAIN or EOVERFLOW (the length
** exceeds DBL_MAX: only when the control polygon does). */
int arclen_conic_length(const double p[6], double w, double *len,
                        arclen_info *info);
/* Other descriptions reduced to (p0, p1, p2; w). */
int arclen_conic_normal_weight(double w0, double w1, double w2, double *w);
/* Elliptic arc: centre, semi-axes, rotation phi, parametric angles theta
** .. theta + dtheta (radians, |dtheta| <= 2 pi) -> n <= 4 conics of at
** most 90 degrees, 7 numbers each (p0 p1 p2 w); returns n or an error. */
int arclen_ellipse_conics(double cx, double cy, double rx, double ry,
                          double phi, double theta, double dtheta,
                          double out[28]);
/* SVG 1.1 F.6.5 with F.6.6: c = cx cy rx ry phi(radians) theta1 dtheta. */
enum { ARCLEN_SVGARC_NONE, ARCLEN_SVGARC_LINE, ARCLEN_SVGARC_ARC };
int arclen_svg_arc_center(double x1, double y1, double rx, double ry,
                          double phi_deg, int large, int sweep, double x2,
                          double y2, double c[7]);
/* The same arc as at most four conics in c[28] (7 numbers each), its ends
** (x1, y1) and (x2, y2) themselves and each control point from its
** piece's ends, not from the centre: ARCLEN_SVGARC_NONE, _LINE (*n = 0),
** _ARC (*n conics) or a negative error code. */
int arclen_svg_arc_conics(double x1, double y1, double rx, double ry,
                          double phi_deg, int large, int sweep, double x2,
                          double y2, double c[28], int *n);

/* ---- segment/: path segments of four kinds --------------------------- */
/* A path segment is a line (P0 P1), a quadratic Bezier (P0 P1 P2), a cubic
** (P0 P1 P2 P3, as above) or a conic: the rational quadratic Bezier P0 P1
** P2 with weights (1, w, 1), w > 0 finite (Floater's eq. 1: circles,
** ellipses and their arcs exactly).  Its numbers are the points, dim each,
** then (conic) w: 2 dim, 3 dim, 4 dim or 3 dim + 1 of them. */
enum {
  ARCLEN_SEG_LINE,          /* "line",  letter 'L' */
  ARCLEN_SEG_QUAD,          /* "quad",  letter 'Q' */
  ARCLEN_SEG_CUBIC,         /* "cubic", letter 'C' */
  ARCLEN_SEG_CONIC,         /* "conic", letter 'R' (rational) */
  ARCLEN_SEG_NKINDS
};
#define ARCLEN_SEG_MAXN 12   /* numbers of the largest segment, a 3D cubic */
int arclen_segment_kind(const char *name);        /* -1 when unknown */
int arclen_segment_kind_of_letter(int letter);    /* -1 when unknown */
const char *arclen_segment_kind_name(int kind);   /* NULL out of range */
int arclen_segment_letter(int kind);              /* 0 out of range */
/* The count of numbers of a kind in dimension dim; 0 for a bad kind or dim. */
int arclen_segment_count(int kind, int dim);
/* 0, ARCLEN_EDOMAIN (unknown kind), ARCLEN_EDIM (dim not 2 or 3) or
** ARCLEN_EINVAL (a non-finite number, or w <= 0). */
int arclen_segment_check(int kind, int dim, const double *seg);
/* The length over [o->t0, o->t1] (negative when t0 > t1), as a method's.
** Cubics go to method m (NULL: the default method, "gauss") with o; lines
** and quadratics have closed forms (quadratics: a few ulps), conics the
** exact length of arclen_conic_length (any sub-range is again a conic);
** o->rtol matters for cubics only (but is checked).  o may be NULL
** (defaults).  info (may be NULL): branch "line", "quad", "quad-gauss"
** (the short rule of a nearly straight quadratic) or the conic's. */
int arclen_segment_length(int kind, int dim, const double *seg,
                          const arclen_method *m, const arclen_opts *o,
                          double *len, arclen_info *info);
/* The t in [0, 1] with |s(t) - s| <= o->rtol L (s(t) the length from 0, L
** the whole length; s <= 0 gives 0, s >= L gives 1).  Cubics by m's time
** (ARCLEN_EDOMAIN when m has none); the others by a safeguarded Newton
** iteration on their exact length.  o->t0, o->t1 must be 0, 1. */
int arclen_segment_time(int kind, int dim, const double *seg, double s,
                        const arclen_method *m, const arclen_opts *o,
                        double *t, arclen_info *info);
/* arclen_times for any kind (cubics: arclen_times itself): the t at the
** ascending lengths s[0 .. n-1], each as arclen_segment_time's; pts and tan
** (may be NULL) get the points and unit tangents. */
int arclen_segment_times(int kind, int dim, const double *seg,
                         const double *s, long n, double rtol, double *t,
                         double *pts, double *tan);
/* arclen_segment_times with the segment's length len as the caller has it
** (a path's cumulative lengths; NaN or <= 0: measured): the scale of the
** tolerance and of the first guesses, each time still certified by an
** exact length of its own.  Cubics ignore it. */
int arclen_segment_times_of(int kind, int dim, const double *seg,
                            double len, const double *s, long n, double rtol,
                            double *t, double *pts, double *tan);
/* Point, derivative (of the curve in t; a conic's is the rational one) and
** unit tangent at t in [0, 1] (where the derivative vanishes, the limit
** direction; a segment that is a point gets zeros): dim numbers each. */
void arclen_segment_point(int kind, int dim, const double *seg, double t,
                          double *p);
void arclen_segment_derivative(int kind, int dim, const double *seg,
                               double t, double *d);
void arclen_segment_unit_tangent(int kind, int dim, const double *seg,
                                 double t, double *v);
/* The piece from t0 to t1 (t0 > t1: reversed) as a segment of the same kind
** into out (a conic's weights renormalized to (1, w', 1)). */
void arclen_segment_sub(int kind, int dim, const double *seg, double t0,
                        double t1, double *out);

#endif
