/*
** fuzz_input.h -- what the libFuzzer harnesses share: a reader that turns
** the fuzzer's bytes into doubles shaped like real trouble (raw bit
** patterns, small integers that make points coincide or line up, values
** one ulp apart, powers of two from denormal to huge), and the geometric
** bounds every length must respect, computed in long double so that no
** finite curve overflows them.
*/
#ifndef ARCLEN_FUZZ_INPUT_H
#define ARCLEN_FUZZ_INPUT_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct fz_reader {
  const uint8_t *p;
  size_t n;
  double last;
} fz_reader;

static inline void fz_init(fz_reader *r, const uint8_t *data, size_t size) {
  r->p = data;
  r->n = size;
  r->last = 0;
}

static inline unsigned fz_byte(fz_reader *r) {
  if (r->n == 0) return 0;
  r->n--;
  return *r->p++;
}

static inline uint64_t fz_bits(fz_reader *r, int bytes) {
  uint64_t v = 0;
  int i;
  for (i = 0; i < bytes; i++) v = v << 8 | fz_byte(r);
  return v;
}

/* An integer in [lo, hi]. */
static inline long fz_range(fz_reader *r, long lo, long hi) {
  uint64_t span = (uint64_t)(hi - lo) + 1;
  return lo + (long)(fz_bits(r, span > 65536 ? 4 : span > 256 ? 2 : 1) % span);
}

/* A finite double.  The selector byte picks the shape of the value. */
static inline double fz_double(fz_reader *r) {
  unsigned sel = fz_byte(r);
  double v;
  switch (sel % 8) {
    case 0: {                               /* any finite bit pattern */
      uint64_t b = fz_bits(r, 8);
      memcpy(&v, &b, sizeof v);
      if (!isfinite(v)) v = 0;
      break;
    }
    case 1: case 2:                         /* small integers: coincidences */
      v = (double)(int8_t)fz_byte(r);
      break;
    case 3:                                 /* the previous value, k ulps off */
      v = r->last;
      {
        int k = (int8_t)fz_byte(r), i;
        for (i = 0; i < abs(k) && i < 8; i++)
          v = nextafter(v, k > 0 ? INFINITY : -INFINITY);
        if (!isfinite(v)) v = r->last;
      }
      break;
    case 4:                                 /* 16-bit fixed point in [-128, 128) */
      v = (double)(int16_t)fz_bits(r, 2) / 256.0;
      break;
    case 5:                                 /* +-2^e, e in [-1074, 1023] */
      v = ldexp((sel & 8) ? -1.0 : 1.0, (int)fz_range(r, -1074, 1023));
      break;
    case 6:                                 /* uniform in [0, 10) as the bench */
      v = 10.0 * (double)fz_bits(r, 4) / 4294967296.0;
      break;
    default:                                /* the previous value plus a small int */
      v = r->last + (double)(int8_t)fz_byte(r);
      if (!isfinite(v)) v = r->last;
      break;
  }
  r->last = v;
  return v;
}

/* A curve of dim 2 or 3: 4*dim coordinates, optionally scaled by 2^e and
** moved by an offset, as far-away or tiny drawings are. */
static inline void fz_curve(fz_reader *r, int dim, double *c) {
  int i, e;
  double off;
  unsigned mode = fz_byte(r);
  for (i = 0; i < 4 * dim; i++) c[i] = fz_double(r);
  if (mode & 1) {
    e = (int)fz_range(r, -600, 600);
    for (i = 0; i < 4 * dim; i++) {
      double v = ldexp(c[i], e);
      if (isfinite(v)) c[i] = v;
    }
  }
  if (mode & 2) {
    off = fz_double(r);
    for (i = 0; i < 4 * dim; i++) {
      double v = c[i] + off;
      if (isfinite(v)) c[i] = v;
    }
  }
}

/* |P_j - P_i| in long double (no overflow for finite doubles). */
static inline long double fz_dist(const double *c, int dim, int i, int j) {
  long double s = 0;
  int k;
  for (k = 0; k < dim; k++) {
    long double d = (long double)c[j * dim + k] - (long double)c[i * dim + k];
    s += d * d;
  }
  return sqrtl(s);
}

static inline long double fz_chord(const double *c, int dim) {
  return fz_dist(c, dim, 0, 3);
}

static inline long double fz_polygon(const double *c, int dim) {
  return fz_dist(c, dim, 0, 1) + fz_dist(c, dim, 1, 2) + fz_dist(c, dim, 2, 3);
}

/* A failed invariant: print what and where, then abort so libFuzzer keeps
** the input as a crash. */
static inline void fz_fail(const char *what, const double *c, int dim,
                           const char *fmt, double a, double b) {
  int i;
  fprintf(stderr, "INVARIANT FAILED: %s: ", what);
  fprintf(stderr, fmt, a, b);
  fprintf(stderr, "\ncurve (dim %d):", dim);
  if (c)
    for (i = 0; i < 4 * dim; i++) fprintf(stderr, " %.17g", c[i]);
  fprintf(stderr, "\n");
  abort();
}

#endif
