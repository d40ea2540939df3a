/*
** segment.h -- what the files of segment/ share: each kind's length over
** [t0, t1], point and derivative, and the safeguarded inverse they all use.
** Not part of the public API (arclen.h has the dispatch by kind).
*/
#ifndef ARCLEN_SEGMENT_H
#define ARCLEN_SEGMENT_H

/* A function kept out of line, or inlined at each call, where the
** compiler can be told so. */
#if defined(__GNUC__)
#define ARCLEN_NOINLINE __attribute__((noinline))
#define ARCLEN_INLINE __attribute__((always_inline)) inline
#elif defined(_MSC_VER)
#define ARCLEN_NOINLINE __declspec(noinline)
#define ARCLEN_INLINE __forceinline
#else
#define ARCLEN_NOINLINE
#define ARCLEN_INLINE inline
#endif

/* Euclidean norm of v[0 .. dim-1] without overflow or underflow. */
double arclen_seg_norm(const double *v, int dim);

/* line.c: P0 P1 (2 dim numbers). */
int arclen_line_length(const double *p, int dim, double t0, double t1,
                       double *len);
void arclen_line_point(const double *p, int dim, double t, double *out);
void arclen_line_derivative(const double *p, int dim, double *out);
void arclen_line_sub(const double *p, int dim, double t0, double t1,
                     double *out);

/* quad.c: P0 P1 P2 (3 dim numbers).  *gauss (may be NULL) is set to 1
** when the short Gauss rule was used instead of the closed form. */
int arclen_quad_length(const double *p, int dim, double t0, double t1,
                       double *len, int *gauss);
/* Its length over [0, 1] (arclen_quad_length's, and the time's total):
** infinite where it overflows. */
double arclen_quad_whole(const double *p, int dim, int *gauss);
/* A quadratic set up once for its lengths from 0 (quad.c) and its time at
** a length (quad_time.c): the legs a = P1 - P0, c = P2 - P1, scaled by a
** power of two into [1/2, 1) where their largest component lies outside
** [2^-100, 2^100] (halved first where a difference overflows), b = c - a,
** B = |b|^2, q = |b|, k = |a x c|, and v(0) = a's u0 = a.b, m0 = |a|^2, S0
** = |a|; Cs = |c_1| + |c_2| (+ |c_3|) >= |c| = |v(1)|; up = 2^scale, down
** = 2^-scale where both are doubles (|scale| < 1000; else 1).  Lengths of
** the scaled form times 2^scale are the segment's.  zero: all three
** points equal (S0, Cs -1).  p: the points, for the total
** (arclen_quad_whole). */
typedef struct arclen_quad_form {
  double a[3], c[3], b[3], B, q, k, u0, m0, S0, Cs, up, down;
  const double *p;
  int dim, scale, zero;
} arclen_quad_form;
void arclen_quad_setup(const double *p, int dim, arclen_quad_form *f);
/* The scaled form's length over [0, t], t in (0, 1), bit for bit
** arclen_quad_length's over [0, t] (before the scale): |v(t)|^2 into *m1
** and |v(t)| into *S1 where the closed form took it (else -1); *gauss as
** below. */
double arclen_quad_form_length(const arclen_quad_form *f, double t,
                               double *m1, double *S1, int *gauss);
/* |v(t)| of the scaled form, v = (1 - t) a + t c (half the speed). */
double arclen_quad_form_speed(const arclen_quad_form *f, double t);
/* Whether the form's length over [0, 1] takes the short Gauss rule. */
int arclen_quad_form_gauss(const arclen_quad_form *f);
/* quad_time.c: the time at the length s on the set-up form (*total: the
** segment's length as the caller has it, or NAN: measured and stored
** where the search needs it; rtol relative to it; from: as
** arclen_seg_invert's, below; *evals: the lengths measured at points
** inside), all in the segment's units; ARCLEN_EOVERFLOW where the length
** overflows. */
int arclen_quad_time(const arclen_quad_form *f, double *total, double s,
                     double rtol, double from[3], double *t, long *evals);
void arclen_quad_point(const double *p, int dim, double t, double *out);
void arclen_quad_derivative(const double *p, int dim, double t,
                            double *out);
void arclen_quad_sub(const double *p, int dim, double t0, double t1,
                     double *out);

/* conic_seg.c: P0 P1 P2 w (3 dim + 1 numbers). */
int arclen_rquad_length(const double *p, int dim, double t0, double t1,
                        double *len, arclen_info *info);
void arclen_rquad_point(const double *p, int dim, double t, double *out);
void arclen_rquad_derivative(const double *p, int dim, double t,
                             double *out);
void arclen_rquad_sub(const double *p, int dim, double t0, double t1,
                      double *out);

/* conic_circle.c: 1 and *len when the 2D conic (q = P0 P1 P2; w) is a
** circular arc to within 2^-30 (its length in closed form, within a few
** ulps), else 0 (the general path, arclen_conic_length). */
int arclen_rquad_circular(const double q[6], double w, double *len);

/* invert.c: a conic's t in [0, 1] with |len(0, t) - s| <= tol, for
** len(0, t) increasing with derivative speed(t) >= 0: Newton's method on
** a Gauss-Legendre model of the length, certified by the model's own
** error bound (bound: the n-point rule's error over [a, b], HUGE_VAL
** where it has none; order: the fewest nodes up to max whose bound over
** [a, b] is within target, and that bound, 0 where none, for a long range
** taken again by such rules; both required) or else by an exact length,
** kept inside a shrinking bracket, bisection when a step leaves it
** (capped).  *total is len(0, 1) as the caller has it, or NAN: unknown,
** measured by len(ctx, 1) where the search needs it and stored there
** (counted in *evals).  tol: the caller's, or NAN: rtol times *total; a
** first search (from {0, 0, 0}) with no total and its guess inside (0,
** 1) takes rtol times a certified lower bound of the length (below: one
** at least lenx + the rest's chord from x, for lenx at most len(0, x))
** and measures the total only where s may reach it.  guess: the first t
** tried (outside the bracket: by the length fraction).  from:
** a known point (t, len(0, t), the bound of that length's error) at or
** before the answer ({0, 0, 0} to start afresh), which a sweep over
** ascending distances passes on: it comes back as the answer's.  Returns
** 0 or the length function's error code; *evals (may be NULL) counts
** exact length evaluations. */
typedef int (*arclen_seg_lenfn)(const void *ctx, double t, double *len);
typedef double (*arclen_seg_speedfn)(const void *ctx, double t);
typedef double (*arclen_seg_boundfn)(const void *ctx, double a, double b,
                                     int n);
typedef int (*arclen_seg_orderfn)(const void *ctx, double a, double b,
                                  double target, int max, double *err);
typedef double (*arclen_seg_belowfn)(const void *ctx, double x,
                                     double lenx);
/* int_a^b speed by the n-point Gauss-Legendre rule (signed; n <= 128). */
double arclen_seg_rule(arclen_seg_speedfn speed, const void *ctx, int n,
                       double a, double b);
/* A piece [a, b] of a cover: its rule's value v and that value's error
** bound e (the kind's bound and the sum's rounding). */
typedef struct arclen_seg_piece { double a, b, v, e; } arclen_seg_piece;
/* The cover of [a, b] by pieces whose rules (the fewest nodes up to
** ARCLEN_SEG_COVER_NODES) order certifies within their share: the whole
** range within share, else its halves within half of it each, depth
** levels down at most; appended in order to pc (room for 2^depth) at
** *np.  0 where some part has no such rule at the last level. */
#define ARCLEN_SEG_COVER_NODES 24
/* Below this relative tolerance the roundings' allowances (32 eps of each
** piece's sum, the nodes' own) leave a bound no room: random conics found
** no cover at 3e-14 and below, three in four at 1e-13 (2026-12-03). */
#define ARCLEN_SEG_COVER_RTOL 1e-13
int arclen_seg_cover(arclen_seg_speedfn speed, arclen_seg_orderfn order,
                     const void *ctx, double a, double b, double share,
                     int depth, arclen_seg_piece *pc, int *np);
int arclen_seg_invert(arclen_seg_lenfn len, arclen_seg_speedfn speed,
                      arclen_seg_boundfn bound, arclen_seg_orderfn order,
                      arclen_seg_belowfn below, const void *ctx,
                      double *total, double s, double rtol, double tol,
                      double guess, double from[3], double *t, long *evals);

#endif
