/*
** speed_sum.c -- the weighted sum of the speed over a rule's symmetric
** pairs of nodes, the loop where quadrature spends its time.
**
** The loop is bound by its square roots, and the hardware takes two, four
** or eight of them in one packed instruction about as often as one: SSE2
** (every x86-64) puts the two points of a pair in one register, AVX two
** pairs, AVX-512 four.  Each lane does the scalar code's operations in its
** order (c + (-half_width) x is c - half_width x exactly) and each pair's
** two speeds are added as the scalar code adds them.  The pairs go to four sums in turn, added up as (s0 + s1) + (s2 +
** s3) at the end -- one sum in a chain of additions would bound the wide
** kernels -- and every kernel keeps that order, so every kernel gives the
** same result to the bit and results do not depend on the machine
** (fuzz/fuzz_kernels.c checks them against each other) in a build without
** contraction, the Makefile's; one that fuses a*b+c may fuse lanes and
** scalar code apart, within a rounding (make check-builds).
*/
#include <math.h>

#include "gauss/speed_sum.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
/* -DARCLEN_NO_AVX builds without the AVX and AVX-512 kernels, and
** -DARCLEN_NO_AVX512 without the latter (to measure the narrower ones on a
** machine that has the wider). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(ARCLEN_NO_AVX)
#include <immintrin.h>
#define HAVE_AVX_KERNEL 1
#endif

/* Pair i: w_i (f(c - half_width x_i) + f(c + half_width x_i)). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double pair_scalar(const arclen_hodo *h, const double *x,
                                 const double *w, int i, double c,
                                 double half_width) {
  return w[i] * (arclen_hodo_speed(h, c - half_width * x[i]) +
                 arclen_hodo_speed(h, c + half_width * x[i]));
}

/* The pairs from i (a multiple of 4 after i0) to half, into acc[0..] in
** turn, and the four sums added up. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double finish(const arclen_hodo *h, const double *x,
                            const double *w, int i, int half, double c,
                            double half_width, double acc[4]) {
  int k;
  for (k = 0; i < half; i++, k++) acc[k] += pair_scalar(h, x, w, i, c, half_width);
  return (acc[0] + acc[1]) + (acc[2] + acc[3]);
}

static double pairs_scalar(const arclen_hodo *h, const double *x,
                           const double *w, int i, int half, double c,
                           double half_width, double s) {
  double acc[4];
  acc[0] = s;
  acc[1] = acc[2] = acc[3] = 0;
  for (; i + 3 < half; i += 4) {
    acc[0] += pair_scalar(h, x, w, i, c, half_width);
    acc[1] += pair_scalar(h, x, w, i + 1, c, half_width);
    acc[2] += pair_scalar(h, x, w, i + 2, c, half_width);
    acc[3] += pair_scalar(h, x, w, i + 3, c, half_width);
  }
  return finish(h, x, w, i, half, c, half_width, acc);
}

#if defined(__SSE2__)
/* The squares of one coordinate (coefficients broadcast in a2, a1, a0) at
** the times in t. */
#define SQUARE2(a2, a1, a0, t) \
  _mm_mul_pd(_mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(a2, t), a1), t), a0), \
             _mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(a2, t), a1), t), a0))

/* The coefficients of the hodograph, each broadcast to all lanes. */
typedef struct coef2 { __m128d x2, x1, x0, y2, y1, y0, z2, z1, z0; } coef2;

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void broadcast2(const arclen_hodo *h, coef2 *k) {
  k->x2 = _mm_set1_pd(h->a2[0]);
  k->x1 = _mm_set1_pd(h->a1[0]);
  k->x0 = _mm_set1_pd(h->a0[0]);
  k->y2 = _mm_set1_pd(h->a2[1]);
  k->y1 = _mm_set1_pd(h->a1[1]);
  k->y0 = _mm_set1_pd(h->a0[1]);
  k->z2 = _mm_set1_pd(h->a2[2]);
  k->z1 = _mm_set1_pd(h->a1[2]);
  k->z0 = _mm_set1_pd(h->a0[2]);
}

/* Pair i in the two lanes, c - half_width x_i in the low one; dim3 is a constant
** in each caller. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double pair_sse2(const coef2 *k, __m128d cc, __m128d lanes,
                               const double *x, const double *w, int i,
                               int dim3) {
  __m128d t = _mm_add_pd(cc, _mm_mul_pd(lanes, _mm_set1_pd(x[i])));
  __m128d q = _mm_add_pd(SQUARE2(k->x2, k->x1, k->x0, t),
                         SQUARE2(k->y2, k->y1, k->y0, t));
  __m128d f;
  if (dim3) q = _mm_add_pd(q, SQUARE2(k->z2, k->z1, k->z0, t));
  f = _mm_sqrt_pd(q);
  return w[i] * (_mm_cvtsd_f64(f) + _mm_cvtsd_f64(_mm_unpackhi_pd(f, f)));
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double pairs_sse2_dim(const arclen_hodo *h, const double *x,
                                    const double *w, int i, int half,
                                    double c, double half_width, double s, int dim3) {
  const __m128d cc = _mm_set1_pd(c), lanes = _mm_set_pd(half_width, -half_width);
  coef2 k;
  double acc[4];
  broadcast2(h, &k);
  acc[0] = s;
  acc[1] = acc[2] = acc[3] = 0;
  for (; i + 3 < half; i += 4) {
    acc[0] += pair_sse2(&k, cc, lanes, x, w, i, dim3);
    acc[1] += pair_sse2(&k, cc, lanes, x, w, i + 1, dim3);
    acc[2] += pair_sse2(&k, cc, lanes, x, w, i + 2, dim3);
    acc[3] += pair_sse2(&k, cc, lanes, x, w, i + 3, dim3);
  }
  return finish(h, x, w, i, half, c, half_width, acc);
}

static double pairs_sse2(const arclen_hodo *h, const double *x,
                         const double *w, int i, int half, double c,
                         double half_width, double s) {
  return h->dim == 3 ? pairs_sse2_dim(h, x, w, i, half, c, half_width, s, 1)
                     : pairs_sse2_dim(h, x, w, i, half, c, half_width, s, 0);
}
#else
#define pairs_sse2 pairs_scalar
#endif

#if defined(HAVE_AVX_KERNEL)
#define SQUARE4(a2, a1, a0, t)                                              \
  _mm256_mul_pd(                                                            \
      _mm256_add_pd(_mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(a2, t), a1),  \
                                  t), a0),                                  \
      _mm256_add_pd(_mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(a2, t), a1),  \
                                  t), a0))

/* The coefficients of the hodograph, each broadcast to all lanes. */
typedef struct coef4 { __m256d x2, x1, x0, y2, y1, y0, z2, z1, z0; } coef4;

/* Pairs i and i + 1 in one register -- lanes c - half_width x_i, c - half_width x_i+1,
** c + half_width x_i, c + half_width x_i+1 -- so that adding its halves gives both pairs'
** sums at once. */
__attribute__((target("avx"), always_inline))
static inline __m128d two_pairs_avx(const coef4 *k, __m256d cc,
                                    __m256d lanes, const double *x,
                                    const double *w, int i, int dim3) {
  __m256d xx = _mm256_broadcast_pd((const __m128d *)(x + i));
  __m256d t = _mm256_add_pd(cc, _mm256_mul_pd(lanes, xx));
  __m256d q = _mm256_add_pd(SQUARE4(k->x2, k->x1, k->x0, t),
                            SQUARE4(k->y2, k->y1, k->y0, t));
  __m256d f;
  if (dim3) q = _mm256_add_pd(q, SQUARE4(k->z2, k->z1, k->z0, t));
  f = _mm256_sqrt_pd(q);
  return _mm_mul_pd(_mm_loadu_pd(w + i),
                    _mm_add_pd(_mm256_castpd256_pd128(f),
                               _mm256_extractf128_pd(f, 1)));
}

/* Four pairs a step: sums 0 and 1 in one register, 2 and 3 in another. */
__attribute__((target("avx"), always_inline))
static inline double pairs_avx_dim(const arclen_hodo *h, const double *x,
                                   const double *w, int i, int half,
                                   double c, double half_width, double s, int dim3) {
  const __m256d cc = _mm256_set1_pd(c);
  const __m256d lanes = _mm256_set_pd(half_width, half_width, -half_width, -half_width);
  __m128d s01 = _mm_set_pd(0, s), s23 = _mm_setzero_pd();
  coef4 k;
  double acc[4];
  k.x2 = _mm256_set1_pd(h->a2[0]);
  k.x1 = _mm256_set1_pd(h->a1[0]);
  k.x0 = _mm256_set1_pd(h->a0[0]);
  k.y2 = _mm256_set1_pd(h->a2[1]);
  k.y1 = _mm256_set1_pd(h->a1[1]);
  k.y0 = _mm256_set1_pd(h->a0[1]);
  k.z2 = _mm256_set1_pd(h->a2[2]);
  k.z1 = _mm256_set1_pd(h->a1[2]);
  k.z0 = _mm256_set1_pd(h->a0[2]);
  for (; i + 3 < half; i += 4) {
    s01 = _mm_add_pd(s01, two_pairs_avx(&k, cc, lanes, x, w, i, dim3));
    s23 = _mm_add_pd(s23, two_pairs_avx(&k, cc, lanes, x, w, i + 2, dim3));
  }
  _mm_storeu_pd(acc, s01);
  _mm_storeu_pd(acc + 2, s23);
  return finish(h, x, w, i, half, c, half_width, acc);
}

__attribute__((target("avx")))
static double pairs_avx(const arclen_hodo *h, const double *x,
                        const double *w, int i, int half, double c,
                        double half_width, double s) {
  return h->dim == 3 ? pairs_avx_dim(h, x, w, i, half, c, half_width, s, 1)
                     : pairs_avx_dim(h, x, w, i, half, c, half_width, s, 0);
}

#define SQUARE8(a2, a1, a0, t)                                              \
  _mm512_mul_pd(                                                            \
      _mm512_add_pd(_mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(a2, t), a1),  \
                                  t), a0),                                  \
      _mm512_add_pd(_mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(a2, t), a1),  \
                                  t), a0))

/* Four pairs in one register, the c - half_width x half below, and the four sums
** in the lanes of one accumulator. */
__attribute__((target("avx512f"), always_inline))
static inline double pairs_avx512_dim(const arclen_hodo *h, const double *x,
                                      const double *w, int i, int half,
                                      double c, double half_width, double s,
                                      int dim3) {
  const __m512d cc = _mm512_set1_pd(c);
  const __m512d lanes = _mm512_set_pd(half_width, half_width, half_width, half_width, -half_width, -half_width, -half_width, -half_width);
  const __m512d x2 = _mm512_set1_pd(h->a2[0]), x1 = _mm512_set1_pd(h->a1[0]);
  const __m512d x0 = _mm512_set1_pd(h->a0[0]), y2 = _mm512_set1_pd(h->a2[1]);
  const __m512d y1 = _mm512_set1_pd(h->a1[1]), y0 = _mm512_set1_pd(h->a0[1]);
  const __m512d z2 = _mm512_set1_pd(h->a2[2]), z1 = _mm512_set1_pd(h->a1[2]);
  const __m512d z0 = _mm512_set1_pd(h->a0[2]);
  __m256d sums = _mm256_set_pd(0, 0, 0, s);
  double acc[4];
  for (; i + 3 < half; i += 4) {
    __m512d xx = _mm512_broadcast_f64x4(_mm256_loadu_pd(x + i));
    __m512d t = _mm512_add_pd(cc, _mm512_mul_pd(lanes, xx));
    __m512d q = _mm512_add_pd(SQUARE8(x2, x1, x0, t), SQUARE8(y2, y1, y0, t));
    __m512d f;
    if (dim3) q = _mm512_add_pd(q, SQUARE8(z2, z1, z0, t));
    f = _mm512_sqrt_pd(q);
    sums = _mm256_add_pd(sums, _mm256_mul_pd(_mm256_loadu_pd(w + i),
        _mm256_add_pd(_mm512_castpd512_pd256(f),
                      _mm512_extractf64x4_pd(f, 1))));
  }
  _mm256_storeu_pd(acc, sums);
  return finish(h, x, w, i, half, c, half_width, acc);
}

__attribute__((target("avx512f")))
static double pairs_avx512(const arclen_hodo *h, const double *x,
                           const double *w, int i, int half, double c,
                           double half_width, double s) {
  return h->dim == 3 ? pairs_avx512_dim(h, x, w, i, half, c, half_width, s, 1)
                     : pairs_avx512_dim(h, x, w, i, half, c, half_width, s, 0);
}

static int have_avx(void) {
  return __builtin_cpu_supports("avx");
}
static int have_avx512(void) {
#if defined(ARCLEN_NO_AVX512)
  return 0;
#else
  return __builtin_cpu_supports("avx512f");
#endif
}
#endif

double arclen_speed_pairs_by(int kernel, const arclen_hodo *h,
                             const double *x, const double *w, int i0,
                             int half, double c, double half_width, double s) {
  switch (kernel) {
    case ARCLEN_KERNEL_SCALAR:
      return pairs_scalar(h, x, w, i0, half, c, half_width, s);
    case ARCLEN_KERNEL_SSE2:
      return pairs_sse2(h, x, w, i0, half, c, half_width, s);
#if defined(HAVE_AVX_KERNEL)
    case ARCLEN_KERNEL_AVX:
      if (have_avx()) return pairs_avx(h, x, w, i0, half, c, half_width, s);
      return pairs_sse2(h, x, w, i0, half, c, half_width, s);
    case ARCLEN_KERNEL_AVX512:
      if (have_avx512()) return pairs_avx512(h, x, w, i0, half, c, half_width, s);
      return pairs_sse2(h, x, w, i0, half, c, half_width, s);
#endif
    default:
      return arclen_speed_pairs(h, x, w, i0, half, c, half_width, s);
  }
}

const char *arclen_speed_kernel(void) {
#if defined(HAVE_AVX_KERNEL)
  if (have_avx512()) return "avx512";
  if (have_avx()) return "avx";
#endif
#if defined(__SSE2__)
  return "sse2";
#else
  return "scalar";
#endif
}

double arclen_speed_pairs(const arclen_hodo *h, const double *x,
                          const double *w, int i0, int half, double c,
                          double half_width, double s) {
#if defined(HAVE_AVX_KERNEL)
  if (have_avx512()) return pairs_avx512(h, x, w, i0, half, c, half_width, s);
  if (have_avx()) return pairs_avx(h, x, w, i0, half, c, half_width, s);
#endif
  return pairs_sse2(h, x, w, i0, half, c, half_width, s);
}

double arclen_speed_rule(const arclen_hodo *h, const double *x,
                         const double *w, int i0, int half, double c,
                         double half_width, double s) {
  return half_width * arclen_speed_pairs(h, x, w, i0, half, c, half_width, s);
}
