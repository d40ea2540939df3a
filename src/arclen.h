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

#define ARCLEN_VERSION "arclen 0.1.0"

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

/* ---- methods.c: methods by name ------------------------------------ */
typedef struct arclen_method {
  const char *name;
  arclen_length_fn length;
  arclen_time_fn time;      /* NULL when the method has no inverse */
} arclen_method;
const arclen_method *arclen_find_method(const char *name);
const arclen_method *arclen_method_list(void);   /* ends with name NULL */

/* ---- cubic.c: geometry of one cubic -------------------------------- */
int arclen_check_curve(const double *c, int dim);        /* 0 or EINVAL */
void arclen_point(const double *c, int dim, double t, double *p);
void arclen_derivative(const double *c, int dim, double t, double *d);
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

/* ---- quadrature.c: the default method ("gauss") -------------------- */
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
/* A fixed n-point Gauss-Legendre rule on [0,1] (n = 24: the speed floor). */
double arclen_length_gl(const double *c, int dim, int n);

/* ---- carlson.c: Carlson's symmetric elliptic integrals -------------- */

/* ---- roots.c: real-coefficient polynomial roots --------------------- */

/* ---- elliptic.c: exact length by Carlson's [1,1,1,1] ---------------- */

/* ---- gravesen.c, metapost.c, baseline.c: Henkel's other rows -------- */

/* ---- lenfit.c: length-versus-t fits --------------------------------- */

/* ---- conic.c: cubic approximation of conics ------------------------- */

#endif
