/*
** metapost.c -- MetaPost's arclength and arctime, operation by operation
** as mp.w does them in its double number system (arc_test, do_arc_test,
** solve_rising_cubic, get_arc_length, get_arc_time of MetaPost 2.x), so
** that the results are bit-identical to `mpost -numbersystem=double`.
** Lengths of vectors are sqrt(a*a + b*b) like mpmathdouble's pyth_add (not
** hypot), each square rounded before the sum whatever the compiler's
** contraction (pyth).
**
** MetaPost recurses without a depth limit; a collinear curve that reverses
** direction never becomes "simple" near the reversal and recurses until the
** hodograph underflows (~1100 levels).  Here the recursion is an explicit
** stack: a small one in the frame, a heap one only for such deep cases.
*/
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "arclen.h"

/* Builds that do not use our Makefile (LuaRocks' builtin backend) pass no
** -ffp-contract=off; on targets with FMA (aarch64, x86-64-v3) a fused
** multiply-add would round differently from mpost.  GCC ignores ISO C's
** STDC FP_CONTRACT pragma but honours its own; clang honours ISO C's
** unless -ffp-contract=fast (then pyth's volatile squares are the proof). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

/* mpmathdouble.w: EL_GORDO = DBL_MAX/2 - 1, "the largest value that MetaPost
** likes"; also MetaPost's "infinite" goal for arclength. */
#define EL_GORDO (DBL_MAX / 2.0 - 1.0)
/* mpmathdouble.w: fraction_four = 4 * fraction_multiplier (4096).  A leg
** |dz| at least this long makes do_arc_test raise "Arithmetic overflow". */
#define FRACTION_FOUR 16384.0
/* mpmathdouble.w: arc_tol_k = unity/4096, the absolute Simpson tolerance. */
#define ARC_TOL (1.0 / 4096.0)
/* mp.w number_add_scaled(v02, 2): two units of 2^-16 inherited from fixed
** point; it adds exactly 2^-17 to every segment's length. */
#define TWO_SCALED (2 / 65536.0)
/* mpmathdouble.w: epsilon = 2^-52, the step of solve_rising_cubic's time. */
#define MP_EPSILON DBL_EPSILON
/* Frames kept in the C frame before the stack moves to the heap; a depth
** cap far beyond the ~1100 levels that underflow allows. */
#define LOCAL_FRAMES 96
#define MAX_DEPTH 4096
/* Passes around a cyclic path after the wrap-around division (2.11 code
** needs at most a few; the cap only guards against a pathological goal). */
#define MAX_PASSES 64

/* pyth_add of mpmathdouble.w: sqrt(a*a + b*b) with both squares rounded
** before the sum, as in mpost.  It is our one product that meets an
** addition (halvings fused with a sum are exact), and clang's
** -ffp-contract=fast fuses it despite the pragmas above: the volatile
** stores round each square whatever the compiler's contraction. */
static double pyth(double a, double b) {
  volatile double aa = fabs(a) * fabs(a), bb = fabs(b) * fabs(b);
  return sqrt(aa + bb);
}

/* solve_rising_cubic: the tau in [0, 1] where B(0, a, a+b, a+b+c; tau) = x,
** one bit per step by bisecting the quadratic (a, b, c); 52 steps. */
static double solve_rising_cubic(double a, double b, double c, double x) {
  double abc = a + b, t, ab, bc, ac, xx;
  int k;
  abc = abc + c;
  if (x <= 0) return 0.0;
  if (x >= abc) return 1.0;
  t = MP_EPSILON;
  for (k = 0; k < 2100 && (a > EL_GORDO / 3.0 || b > EL_GORDO / 3.0 ||
                           c > EL_GORDO / 3.0); k++) {
    a = a / 2.0; b = b / 2.0; c = c / 2.0; x = x / 2.0;
  }
  do {      /* t doubles from 2^-52 to 1: exactly 52 passes */
    t = t + t;
    ab = (a + b) / 2.0;
    bc = (b + c) / 2.0;
    ac = (ab + bc) / 2.0;
    xx = x;
    xx = xx - a;
    xx = xx - ab;
    xx = xx - ac;
    if (xx < -x) {
      x = x * 2.0; b = ab; c = ac;
    } else {
      x = x + xx; a = ac; b = bc; t = t + MP_EPSILON;
    }
  } while (t < 1.0);
  return t - 1.0;
}

/* The arguments of one arc_test call. */
typedef struct mp_call {
  double d[6];              /* dx0 dy0 dx1 dy1 dx2 dy2 */
  double v0, v02, v2, goal, tol;
} mp_call;

/* A bisection waiting for its first half's result: the second half's call
** (its goal still to be reduced by the first half's length). */
typedef struct mp_frame {
  mp_call right;
  double a_aux, a;
  int second;               /* 0: first half running, 1: second half */
} mp_frame;

typedef struct mp_state {
  mp_frame local[LOCAL_FRAMES];
  mp_frame *frames;
  int cap, sp, overflow;
  long nodes, leaves;
  int depth;
} mp_state;

static mp_frame *push(mp_state *s) {
  if (s->sp == s->cap) {
    mp_frame *f;
    int i;
    if (s->cap >= MAX_DEPTH) return NULL;
    f = (mp_frame *)malloc(sizeof(mp_frame) * MAX_DEPTH);
    if (f == NULL) return NULL;
    for (i = 0; i < s->sp; i++) f[i] = s->frames[i];
    s->frames = f;
    s->cap = MAX_DEPTH;
  }
  return &s->frames[s->sp++];
}

/* The leaf's time estimate: the speed on each half is the quadratic through
** the Simpson samples; returns time - 2 (mp.w "set arc_test to that time
** minus two"). */
static double leaf_time(const mp_call *k, double arc1, double arc) {
  double tmp = k->v02 + TWO_SCALED, tmp2, tmp3, tau;
  tmp = tmp / 2.0;
  tmp = tmp / 2.0;                      /* (v02 + 2) / 4 */
  if (k->goal <= arc1) {
    tmp2 = k->v0 / 2.0;
    tmp3 = arc1 - tmp2;
    tmp3 = tmp3 - tmp;
    tau = solve_rising_cubic(tmp2, tmp3, tmp, k->goal) / 2.0;
    tau = tau - 1.0;
    return tau - 1.0;
  }
  tmp2 = k->v2 / 2.0;
  tmp3 = arc - arc1;
  tmp3 = tmp3 - tmp;
  tmp3 = tmp3 - tmp2;
  tau = solve_rising_cubic(tmp, tmp3, tmp2, k->goal - arc1) / 2.0;
  return (0.5 - 1.0 - 1.0) + tau;      /* (half_unit - two) + tau/2 */
}

/* Are the three vectors in one closed quadrant, or in one after a rotation
** by 45 degrees?  (mp.w: the test for a "simple" subpath.) */
static int simple(const double *d) {
  int s = (d[0] >= 0 && d[2] >= 0 && d[4] >= 0) ||
          (d[0] <= 0 && d[2] <= 0 && d[4] <= 0);
  if (s)
    s = (d[1] >= 0 && d[3] >= 0 && d[5] >= 0) ||
        (d[1] <= 0 && d[3] <= 0 && d[5] <= 0);
  if (!s) {
    s = (d[0] >= d[1] && d[2] >= d[3] && d[4] >= d[5]) ||
        (d[0] <= d[1] && d[2] <= d[3] && d[4] <= d[5]);
    if (s)
      s = (-d[0] >= d[1] && -d[2] >= d[3] && -d[4] >= d[5]) ||
          (-d[0] <= d[1] && -d[2] <= d[3] && -d[4] <= d[5]);
  }
  return s;
}

/* Returns an arc length (< goal) or a time - 2 (< 0); on overflow sets
** s->overflow.  The recursion of mp.w's arc_test, unrolled. */
static double arc_test(mp_state *s, mp_call k) {
  double ret;
  int depth = 0;
  for (;;) {
    /* ---- evaluate the call k at the current depth ---- */
    double d01[2], d12[2], d02[2], v002, v022, tmp, arc1, arc, simply;
    double arg1, arg2;
    int j;
    s->nodes++;
    if (depth > s->depth) s->depth = depth;
    for (j = 0; j < 2; j++) {           /* bisect the quadratic */
      d01[j] = (k.d[j] + k.d[2 + j]) / 2.0;
      d12[j] = (k.d[2 + j] + k.d[4 + j]) / 2.0;
      d02[j] = (d01[j] + d12[j]) / 2.0;
    }
    arg1 = (k.d[0] + d02[0]) / 2.0;
    arg1 = arg1 + d01[0];
    arg2 = (k.d[1] + d02[1]) / 2.0;
    arg2 = arg2 + d01[1];
    v002 = pyth(arg1, arg2);
    arg1 = (d02[0] + k.d[4]) / 2.0;
    arg1 = arg1 + d12[0];
    arg2 = (d02[1] + k.d[5]) / 2.0;
    arg2 = arg2 + d12[1];
    v022 = pyth(arg1, arg2);
    tmp = k.v02 + TWO_SCALED;
    tmp = tmp / 2.0;
    arc1 = (k.v0 + tmp) / 2.0;          /* two-panel Simpson per half */
    arc1 = arc1 - v002;
    arc1 = arc1 / 2.0;
    arc1 = v002 + arc1;
    arc = (k.v2 + tmp) / 2.0;
    arc = arc - v022;
    arc = arc / 2.0;
    arc = v022 + arc;
    if (arc < EL_GORDO - arc1) {
      arc = arc + arc1;
    } else {
      s->overflow = 1;
      ret = (k.goal == EL_GORDO) ? EL_GORDO : -2.0;
      goto done;
    }
    simply = (k.v0 + k.v2) / 2.0;
    simply = -simply;
    simply = simply + arc;
    simply = simply - k.v02;
    simply = fabs(simply);
    if (simple(k.d) && simply <= k.tol) {
      s->leaves++;
      ret = (arc < k.goal) ? arc : leaf_time(&k, arc1, arc);
      goto done;
    } else {                            /* two recursive calls */
      mp_frame *f = push(s);
      double a_new, a_aux, tol, half_v02;
      if (f == NULL) { s->overflow = 2; return 0.0; }
      a_aux = EL_GORDO - k.goal;        /* a_new + a_aux = 2 goal */
      if (k.goal > a_aux) {
        a_aux = k.goal - a_aux;
        a_new = EL_GORDO;
      } else {
        a_new = k.goal + k.goal;
        a_aux = 0.0;
      }
      tol = k.tol + k.tol / 2.0;        /* mp.w: sqrt(2), approximated 1.5 */
      half_v02 = k.v02 / 2.0;
      f->right.d[0] = d02[0]; f->right.d[1] = d02[1];
      f->right.d[2] = d12[0]; f->right.d[3] = d12[1];
      f->right.d[4] = k.d[4]; f->right.d[5] = k.d[5];
      f->right.v0 = half_v02;
      f->right.v02 = v022;
      f->right.v2 = k.v2;
      f->right.goal = a_new;
      f->right.tol = tol;
      f->a_aux = a_aux;
      f->second = 0;
      k.d[2] = d01[0]; k.d[3] = d01[1];
      k.d[4] = d02[0]; k.d[5] = d02[1];
      k.v02 = v002;
      k.v2 = half_v02;
      k.goal = a_new;
      k.tol = tol;
      depth++;
      continue;
    }
  done:
    /* ---- return ret to the pending bisections ---- */
    for (;;) {
      mp_frame *f;
      if (s->sp == 0) return ret;
      f = &s->frames[s->sp - 1];
      if (!f->second) {
        double a = ret;
        if (a < 0) {                    /* the goal fell in the first half */
          ret = 2.0 - a;
          ret = ret / 2.0;
          ret = -ret;
          s->sp--; depth--;
          continue;
        }
        if (a > f->a_aux) {             /* reduce a_new + a_aux by a */
          f->a_aux = f->a_aux - a;
          f->right.goal = f->right.goal + f->a_aux;
        }
        f->a = a;
        f->second = 1;
        k = f->right;
        break;                          /* evaluate the second half */
      } else {
        double b = ret, a = f->a;
        if (b < 0) {
          double t = -b;
          t = t / 2.0;
          t = -t;
          ret = t - 0.5;
        } else {
          ret = b - a;
          ret = ret / 2.0;
          ret = a + ret;
        }
        s->sp--; depth--;
      }
    }
  }
}

/* do_arc_test on one segment (8 numbers); *ret as arc_test's. */
static int do_arc_test(const double *c, double goal, double *ret,
                       long *nodes, long *leaves, int *depth) {
  mp_state s;
  mp_call k;
  double v1, arg1, arg2;
  int j;
  for (j = 0; j < 6; j++) k.d[j] = c[j + 2] - c[j];
  k.v0 = pyth(k.d[0], k.d[1]);
  v1 = pyth(k.d[2], k.d[3]);
  k.v2 = pyth(k.d[4], k.d[5]);
  if (k.v0 >= FRACTION_FOUR || v1 >= FRACTION_FOUR || k.v2 >= FRACTION_FOUR
      || k.v0 != k.v0 || v1 != v1 || k.v2 != k.v2) {
    *ret = (goal == EL_GORDO) ? EL_GORDO : -2.0;
    return ARCLEN_EOVERFLOW;
  }
  arg1 = (k.d[0] + k.d[4]) / 2.0;
  arg1 = arg1 + k.d[2];
  arg2 = (k.d[1] + k.d[5]) / 2.0;
  arg2 = arg2 + k.d[3];
  k.v02 = pyth(arg1, arg2);
  k.goal = goal;
  k.tol = ARC_TOL;
  s.frames = s.local;
  s.cap = LOCAL_FRAMES;
  s.sp = 0;
  s.overflow = 0;
  s.nodes = s.leaves = 0;
  s.depth = 0;
  *ret = arc_test(&s, k);
  if (s.frames != s.local) free(s.frames);
  *nodes += s.nodes;
  *leaves += s.leaves;
  if (s.depth > *depth) *depth = s.depth;
  if (s.overflow == 2) return ARCLEN_ENOCONV;
  return s.overflow ? ARCLEN_EOVERFLOW : ARCLEN_OK;
}

static void fill_info(arclen_info *info, long nodes, long leaves, int depth,
                      const char *branch) {
  if (info == NULL) return;
  info->evals = nodes;
  info->pieces = leaves;
  info->depth = depth;
  info->err = 0.0;
  info->branch = branch;
  info->calls = 0;
}

/* slow_add of mpmathdouble.w: saturating at EL_GORDO. */
static int slow_add(double x, double y, double *r) {
  if (x >= 0) {
    if (y <= EL_GORDO - x) { *r = x + y; return 0; }
    *r = EL_GORDO;
    return 1;
  }
  if (-y <= EL_GORDO + x) { *r = x + y; return 0; }
  *r = -EL_GORDO;
  return 1;
}

int arclen_mp_path_arclength(const double *seg, int n, int cyclic,
                             double *len, arclen_info *info) {
  double tot = 0.0, a;
  long nodes = 0, leaves = 0;
  int depth = 0, i, rc = ARCLEN_OK;
  (void)cyclic;             /* a cyclic path lists its closing segment */
  for (i = 0; i < n; i++) {
    int r = do_arc_test(seg + 8 * i, EL_GORDO, &a, &nodes, &leaves, &depth);
    if (r != ARCLEN_OK && rc == ARCLEN_OK) rc = r;
    if (slow_add(a, tot, &tot) && rc == ARCLEN_OK) rc = ARCLEN_EOVERFLOW;
  }
  fill_info(info, nodes, leaves, depth, "metapost");
  *len = (rc == ARCLEN_OK) ? tot : NAN;
  return rc;
}

/* get_arc_time on segments seg[0..n-1], walked forwards (step 1) or, for
** the reversed path htap_ypoc builds, backwards with each segment reversed. */
static int arc_time(const double *seg, int n, int cyclic, int reversed,
                    double arc0, double *t, long *nodes, long *leaves,
                    int *depth) {
  double t_tot = 0.0, arc, r, rev[8];
  int i = 0, passes = 0, rc = ARCLEN_OK;
  if (arc0 == EL_GORDO) arc0 = arc0 + (-1 / 65536.0);
  arc = arc0;
  while (arc > 0 && (cyclic || i < n)) {
    const double *c;
    if (reversed) {
      /* htap_ypoc keeps the first knot: segments n-1, ..., 0, each reversed */
      const double *o = seg + 8 * (n - 1 - i);
      int j;
      for (j = 0; j < 4; j++) {
        rev[2 * j] = o[6 - 2 * j];
        rev[2 * j + 1] = o[7 - 2 * j];
      }
      c = rev;
    } else {
      c = seg + 8 * i;
    }
    rc = do_arc_test(c, arc, &r, nodes, leaves, depth);
    if (rc != ARCLEN_OK) return rc;
    if (r < 0) {
      t_tot = t_tot + r;
      t_tot = t_tot + 2.0;
      arc = 0.0;
    } else {
      t_tot = t_tot + 1.0;
      arc = arc - r;
    }
    i++;
    if (cyclic && i == n) {
      i = 0;
      if (arc > 0) {        /* MetaPost 2.11: skip whole turns at once */
        double d1 = arc0 - arc, n1, v1;
        if (++passes > MAX_PASSES) return ARCLEN_ENOCONV;
        if (d1 > arc) {
          n1 = 0.0;
        } else {
          n1 = arc / d1;
          n1 = floor(n1);
        }
        v1 = n1 + 1.0;      /* mp.w: number_to_int(n) + 1, exact here */
        n1 = n1 * d1;
        arc = arc - n1;
        if (t_tot > EL_GORDO / v1) return ARCLEN_EOVERFLOW;
        t_tot = t_tot * v1;
      }
    }
  }
  *t = t_tot;
  return ARCLEN_OK;
}

int arclen_mp_path_arctime(const double *seg, int n, int cyclic, double goal,
                           double *t, arclen_info *info) {
  long nodes = 0, leaves = 0;
  int depth = 0, rc;
  double r = 0.0;
  if (goal < 0) {
    if (!cyclic) {
      rc = ARCLEN_OK;
    } else {
      rc = arc_time(seg, n, 1, 1, -goal, &r, &nodes, &leaves, &depth);
      r = -r;
      if (r == 0) r = 0.0;  /* mpmathdouble's negate turns -0 into 0 */
    }
  } else {
    rc = arc_time(seg, n, cyclic, 0, goal, &r, &nodes, &leaves, &depth);
  }
  fill_info(info, nodes, leaves, depth, "metapost");
  *t = (rc == ARCLEN_OK) ? r : NAN;
  return rc;
}

int arclen_mp_arclength(const double c[8], double *len, arclen_info *info) {
  return arclen_mp_path_arclength(c, 1, 0, len, info);
}

int arclen_mp_arctime(const double c[8], double goal, double *t,
                      arclen_info *info) {
  return arclen_mp_path_arctime(c, 1, 0, goal, t, info);
}

/* The method table's entry points ("metapost").  Over the whole curve the
** result is mpost's; over a sub-range the curve is cut first (arclen_subcurve),
** which is what `subpath` would give only up to rounding. */
int arclen_length_metapost(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info) {
  double t0 = o ? o->t0 : 0.0, t1 = o ? o->t1 : 1.0, sub[8];
  int rc, neg = 0;
  if (dim != 2) { *len = NAN; return ARCLEN_EDIM; }
  if (t0 == 0.0 && t1 == 1.0) return arclen_mp_arclength(c, len, info);
  if (t0 > t1) { double w = t0; t0 = t1; t1 = w; neg = 1; }
  arclen_subcurve(c, 2, t0, t1, sub);
  rc = arclen_mp_arclength(sub, len, info);
  if (rc == ARCLEN_OK && neg) *len = -*len;
  return rc;
}

int arclen_time_metapost(const double *c, int dim, double s,
                         const arclen_opts *o, double *t, arclen_info *info) {
  (void)o;
  if (dim != 2) { *t = NAN; return ARCLEN_EDIM; }
  return arclen_mp_arctime(c, s, t, info);
}
