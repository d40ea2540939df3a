/*
** speed_sum.c -- the weighted sum of the speed over a rule's symmetric
** pairs of nodes, the loop where quadrature spends its time.
**
** The loop is bound by its square roots, and the hardware takes two or four
** of them in one packed instruction about as often as one: SSE2 (every
** x86-64) puts the two points of a pair in one register, AVX two pairs.
** Each lane does the scalar code's operations in its order (c + (-hh) x is
** c - hh x exactly; no FMA contraction, see the Makefile), each pair's two
** speeds are added as the scalar code adds them, and the pairs are added to
** the sum one at a time in increasing i: every kernel gives the scalar
** loop's sum to the bit, so results do not depend on the machine.  The
** one sum is also what bounds a wider kernel: its additions in a chain
** take about as long as the square roots of a pair at AVX width.
*/
#include <math.h>

#include "speed_sum.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
/* -DARCLEN_NO_AVX builds without the AVX kernel (to measure the SSE2
** one on a machine that has AVX). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(ARCLEN_NO_AVX)
#include <immintrin.h>
#define HAVE_AVX_KERNEL 1
#endif

static double pairs_scalar(const arclen_hodo *h, const double *x,
                           const double *w, int i, int half, double c,
                           double hh, double s) {
  for (; i < half; i++)
    s += w[i] * (arclen_hodo_speed(h, c - hh * x[i]) +
                 arclen_hodo_speed(h, c + hh * x[i]));
  return s;
}

#if defined(__SSE2__)
/* The squares of one coordinate (coefficients broadcast in a2, a1, a0) at
** the times in t. */
#define SQUARE2(a2, a1, a0, t) \
  _mm_mul_pd(_mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(a2, t), a1), t), a0), \
             _mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(a2, t), a1), t), a0))

/* A pair in the two lanes, c - hh x in the low one.  The coefficients are
** broadcast once; dim3 is a constant in each caller. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double pairs_sse2_dim(const arclen_hodo *h, const double *x,
                                    const double *w, int i, int half,
                                    double c, double hh, double s, int dim3) {
  const __m128d cc = _mm_set1_pd(c), lanes = _mm_set_pd(hh, -hh);
  const __m128d x2 = _mm_set1_pd(h->a2[0]), x1 = _mm_set1_pd(h->a1[0]);
  const __m128d x0 = _mm_set1_pd(h->a0[0]), y2 = _mm_set1_pd(h->a2[1]);
  const __m128d y1 = _mm_set1_pd(h->a1[1]), y0 = _mm_set1_pd(h->a0[1]);
  const __m128d z2 = _mm_set1_pd(h->a2[2]), z1 = _mm_set1_pd(h->a1[2]);
  const __m128d z0 = _mm_set1_pd(h->a0[2]);
  for (; i < half; i++) {
    __m128d t = _mm_add_pd(cc, _mm_mul_pd(lanes, _mm_set1_pd(x[i])));
    __m128d q = _mm_add_pd(SQUARE2(x2, x1, x0, t), SQUARE2(y2, y1, y0, t));
    __m128d f;
    if (dim3) q = _mm_add_pd(q, SQUARE2(z2, z1, z0, t));
    f = _mm_sqrt_pd(q);
    s += w[i] * (_mm_cvtsd_f64(f) + _mm_cvtsd_f64(_mm_unpackhi_pd(f, f)));
  }
  return s;
}

static double pairs_sse2(const arclen_hodo *h, const double *x,
                         const double *w, int i, int half, double c,
                         double hh, double s) {
  return h->dim == 3 ? pairs_sse2_dim(h, x, w, i, half, c, hh, s, 1)
                     : pairs_sse2_dim(h, x, w, i, half, c, hh, s, 0);
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

/* Pairs i and i + 1 in one register: lanes c - hh x_i, c - hh x_i+1,
** c + hh x_i, c + hh x_i+1, so that adding its halves gives both pairs'
** sums at once; an odd last pair goes to the SSE2 loop. */
__attribute__((target("avx"), always_inline))
static inline double pairs_avx_dim(const arclen_hodo *h, const double *x,
                                   const double *w, int i, int half,
                                   double c, double hh, double s, int dim3) {
  const __m256d cc = _mm256_set1_pd(c);
  const __m256d lanes = _mm256_set_pd(hh, hh, -hh, -hh);
  const __m256d x2 = _mm256_set1_pd(h->a2[0]), x1 = _mm256_set1_pd(h->a1[0]);
  const __m256d x0 = _mm256_set1_pd(h->a0[0]), y2 = _mm256_set1_pd(h->a2[1]);
  const __m256d y1 = _mm256_set1_pd(h->a1[1]), y0 = _mm256_set1_pd(h->a0[1]);
  const __m256d z2 = _mm256_set1_pd(h->a2[2]), z1 = _mm256_set1_pd(h->a1[2]);
  const __m256d z0 = _mm256_set1_pd(h->a0[2]);
  for (; i + 1 < half; i += 2) {
    __m256d xx = _mm256_broadcast_pd((const __m128d *)(x + i));
    __m256d t = _mm256_add_pd(cc, _mm256_mul_pd(lanes, xx));
    __m256d q = _mm256_add_pd(SQUARE4(x2, x1, x0, t), SQUARE4(y2, y1, y0, t));
    __m256d f;
    __m128d p;
    if (dim3) q = _mm256_add_pd(q, SQUARE4(z2, z1, z0, t));
    f = _mm256_sqrt_pd(q);
    p = _mm_mul_pd(_mm_loadu_pd(w + i),
                   _mm_add_pd(_mm256_castpd256_pd128(f),
                              _mm256_extractf128_pd(f, 1)));
    s += _mm_cvtsd_f64(p);
    s += _mm_cvtsd_f64(_mm_unpackhi_pd(p, p));
  }
  return s;
}

__attribute__((target("avx")))
static double pairs_avx(const arclen_hodo *h, const double *x,
                        const double *w, int i, int half, double c,
                        double hh, double s) {
  int even = i + ((half - i) & ~1);           /* the pairs done two by two */
  s = h->dim == 3 ? pairs_avx_dim(h, x, w, i, even, c, hh, s, 1)
                  : pairs_avx_dim(h, x, w, i, even, c, hh, s, 0);
  return even < half ? pairs_sse2(h, x, w, even, half, c, hh, s) : s;
}

static int have_avx(void) {
  return __builtin_cpu_supports("avx");
}
#endif

double arclen_speed_pairs_by(int kernel, const arclen_hodo *h,
                             const double *x, const double *w, int i0,
                             int half, double c, double hh, double s) {
  switch (kernel) {
    case ARCLEN_KERNEL_SCALAR:
      return pairs_scalar(h, x, w, i0, half, c, hh, s);
    case ARCLEN_KERNEL_SSE2:
      return pairs_sse2(h, x, w, i0, half, c, hh, s);
    default:
#if defined(HAVE_AVX_KERNEL)
      if (have_avx()) return pairs_avx(h, x, w, i0, half, c, hh, s);
#endif
      return pairs_sse2(h, x, w, i0, half, c, hh, s);
  }
}

const char *arclen_speed_kernel(void) {
#if defined(HAVE_AVX_KERNEL)
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
                          double hh, double s) {
#if defined(HAVE_AVX_KERNEL)
  if (have_avx()) return pairs_avx(h, x, w, i0, half, c, hh, s);
#endif
  return pairs_sse2(h, x, w, i0, half, c, hh, s);
}
