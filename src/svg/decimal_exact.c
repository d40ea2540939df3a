/*
** decimal_exact.c -- the nearest double of any decimal number, without
** strtod (whose decimal point follows LC_NUMERIC): the significant digits
** as a big integer D, the value x = D * 10^E, and x = (q + f) * 2^k with q
** the top 57 bits of the exact value and f only known as 0 or in (0, 1),
** so that the rounding of q to 53 bits is exact.  E >= 0: D * 10^E is an
** integer; E < 0: the quotient by 10^-E = 2^-E * 5^-E, by short divisions
** by 5^13 up to 10^-350, else by a binary long division.  No locale, no
** allocation, no state: fixed buffers on the stack and bounded loops.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "svg/decimal.h"

/* Digits kept: a halfway point between two doubles has at most 767
** significant digits, so a number cut after 800 (and marked inexact when
** a dropped digit is not 0) lies on the same side of every halfway point
** as the whole number does. */
#define KEPT_DIGITS 800

/* Beyond these decimal exponents P (x in [10^(P-1), 10^P)) the result is
** known: 10^310 > DBL_MAX, and below P_UNDERFLOW x < 10^-324 < 2^-1075,
** half the least subnormal. */
#define P_OVERFLOW 310
#define P_UNDERFLOW (-323)

/* The quotient's bits: q in [2^55, 2^57) leaves at least two bits below
** the 53 kept ones, for the rounding bit and the sticky rest. */
#define QUOTIENT_SHIFT 56

/* Big integers of 4096 bits.  The largest: 10^(800 + 323) (< 2^3731) in
** the long division, shifted by QUOTIENT_SHIFT + 1 bits. */
#define LIMBS 128

/* Below 10^-SHORT_DIVISION_MAX the short divisions by 5^13, whose number
** and length both grow with the exponent, cost more than the binary long
** division (bench/bench_decimal.lua, doc/benchmarks.md). */
#define SHORT_DIVISION_MAX 350

typedef struct big {
  uint32_t w[LIMBS];   /* little-endian limbs */
  int n;               /* limbs in use; w[n-1] != 0 unless n == 0 */
} big;

static uint32_t pow5(int r) {        /* 5^r, r <= 13 */
  uint32_t p = 1;
  while (r-- > 0) p *= 5;
  return p;
}

static void big_set(big *a, uint32_t v) {
  a->w[0] = v;
  a->n = v != 0;
}

/* a = a * m + add; -1 when it would not fit. */
static int big_muladd(big *a, uint32_t m, uint32_t add) {
  uint64_t carry = add;
  int i;
  for (i = 0; i < a->n; i++) {
    uint64_t t = (uint64_t)a->w[i] * m + carry;
    a->w[i] = (uint32_t)t;
    carry = t >> 32;
  }
  if (carry != 0) {
    if (a->n == LIMBS) return -1;
    a->w[a->n++] = (uint32_t)carry;
  }
  return 0;
}

/* a = a * 10^e. */
static int big_mul_pow10(big *a, long e) {
  static const uint32_t P10[10] = {1u, 10u, 100u, 1000u, 10000u, 100000u,
                                   1000000u, 10000000u, 100000000u,
                                   1000000000u};
  for (; e >= 9; e -= 9)
    if (big_muladd(a, P10[9], 0) != 0) return -1;
  return e > 0 ? big_muladd(a, P10[e], 0) : 0;
}

static int big_bits(const big *a) {
  int b = 0;
  uint32_t top;
  if (a->n == 0) return 0;
  for (top = a->w[a->n - 1]; top != 0; top >>= 1) b++;
  return 32 * (a->n - 1) + b;
}

/* a = a * 2^s. */
static int big_shl(big *a, int s) {
  int limbs = s / 32, bits = s % 32, i, n;
  if (a->n == 0 || s == 0) return 0;
  n = a->n + limbs + 1;
  if (n > LIMBS) {
    if (big_bits(a) + s > 32 * LIMBS) return -1;
    n = LIMBS;
  }
  for (i = n - 1; i >= limbs; i--) {
    int j = i - limbs;
    uint32_t hi = j < a->n ? a->w[j] : 0;
    uint32_t lo = j >= 1 && j - 1 < a->n ? a->w[j - 1] : 0;
    a->w[i] = bits == 0 ? hi : (hi << bits) | (lo >> (32 - bits));
  }
  for (i = 0; i < limbs; i++) a->w[i] = 0;
  a->n = n;
  while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
  return 0;
}

/* a = a / 2 (here only on multiples of 2). */
static void big_half(big *a) {
  int i;
  for (i = 0; i < a->n; i++)
    a->w[i] = (a->w[i] >> 1) | (i + 1 < a->n ? a->w[i + 1] << 31 : 0);
  while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
}

static int big_cmp(const big *a, const big *b) {
  int i;
  if (a->n != b->n) return a->n < b->n ? -1 : 1;
  for (i = a->n - 1; i >= 0; i--)
    if (a->w[i] != b->w[i]) return a->w[i] < b->w[i] ? -1 : 1;
  return 0;
}

/* a = a - b, for a >= b. */
static void big_sub(big *a, const big *b) {
  uint32_t borrow = 0;
  int i;
  for (i = 0; i < a->n; i++) {
    uint64_t bi = (i < b->n ? b->w[i] : 0) + (uint64_t)borrow;
    borrow = a->w[i] < bi;
    a->w[i] = (uint32_t)((uint64_t)a->w[i] - bi);
  }
  while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
}

/* a = a / d, the remainder returned (d > 0). */
static uint32_t big_divsmall(big *a, uint32_t d) {
  uint64_t r = 0;
  int i;
  for (i = a->n - 1; i >= 0; i--) {
    uint64_t cur = r << 32 | a->w[i];
    a->w[i] = (uint32_t)(cur / d);
    r = cur % d;
  }
  while (a->n > 0 && a->w[a->n - 1] == 0) a->n--;
  return (uint32_t)r;
}

/* a's top QUOTIENT_SHIFT + 1 bits as q (shifted up when a has fewer), with
** a = (q + f) * 2^k, *inexact set when a bit below them is 1.  a != 0. */
static void top_bits(const big *a, uint64_t *q, int *k, int *inexact) {
  int sh = big_bits(a) - (QUOTIENT_SHIFT + 1), i;
  if (sh <= 0) {                       /* a < 2^57: two limbs at most */
    uint64_t v = a->w[0];
    if (a->n > 1) v |= (uint64_t)a->w[1] << 32;
    *q = v << -sh;
  } else {                             /* bits sh .. sh + 56: 3 limbs */
    int l = sh / 32, b = sh % 32;
    uint64_t mid = l + 1 < a->n ? a->w[l + 1] : 0;
    uint64_t hi = l + 2 < a->n ? a->w[l + 2] : 0;
    uint64_t v = (uint64_t)(a->w[l] >> b) | mid << (32 - b);
    if (b > 0) v |= hi << (64 - b);
    *q = v;
    if ((a->w[l] & ((UINT32_C(1) << b) - 1)) != 0) *inexact = 1;
    for (i = 0; i < l && !*inexact; i++)
      if (a->w[i] != 0) *inexact = 1;
  }
  *k = sh;
}

/* x = a / 10^f = (a * 2^s / 5^f) * 2^(-s-f): the quotient by 5^f in short
** divisions by 5^13 (< 2^32) and a last 5^r -- the floor of successive
** floors is the floor of the whole, and the whole divides exactly only if
** every step does. */
static int by_five(big *a, int f, uint64_t *q, int *k, int *inexact) {
  big p5;
  int s, left;
  big_set(&p5, 1);
  for (left = f; left > 0; left -= 13)
    if (big_muladd(&p5, left >= 13 ? 1220703125u : pow5(left), 0) != 0) return -1;
  s = QUOTIENT_SHIFT - (big_bits(a) - big_bits(&p5));
  if (s > 0 && big_shl(a, s) != 0) return -1;
  if (s < 0) s = 0;           /* a long mantissa: a longer quotient, cut by top_bits */
  for (left = f; left > 0; left -= 13)
    if (big_divsmall(a, left >= 13 ? 1220703125u : pow5(left)) != 0) *inexact = 1;
  top_bits(a, q, k, inexact);
  *k -= s + f;
  return 0;
}

/* The double nearest to (q + f) * 2^k, with f in (0, 1) when inexact
** and 0 otherwise; ties to even (IEEE 754 section 4.3.1).  q >= 2^55; a q
** that top_bits shifted up by one bit has f in (0, 2) with q even, which
** rounds the same (the rounding bit is at least the fourth). */
static double nearest(uint64_t q, int k, int inexact) {
  int bits = 0, lead, low, drop;
  uint64_t m, rest, half, t;
  for (t = q; t >= 256; t >>= 8) bits += 8;
  for (; t != 0; t >>= 1) bits++;
  lead = bits - 1 + k;                  /* x in [2^lead, 2^(lead+1)) */
  low = lead - 52 < -1074 ? -1074 : lead - 52;   /* the last bit kept */
  drop = low - k;                       /* >= 3, as q has >= 56 bits */
  if (drop > 64) return 0.0;            /* x < 2^(low-1): below half */
  m = drop == 64 ? 0 : q >> drop;
  rest = drop == 64 ? q : q & ((UINT64_C(1) << drop) - 1);
  half = UINT64_C(1) << (drop - 1);
  if (rest > half || (rest == half && (inexact || (m & 1) != 0))) m++;
  return ldexp((double)m, low);         /* exact, or HUGE_VAL beyond */
}

double arclen_decimal_exact(const char *s, size_t len) {
  big a, b;
  size_t i = 0;
  int neg = 0, inexact = 0, seen_dot = 0, started = 0, shift, k;
  long kept = 0, expo = 0;
  long long point = 0;               /* x = 0.d1d2... * 10^point */
  uint32_t chunk = 0;
  int in_chunk = 0;
  uint64_t q = 0;
  big_set(&a, 0);
  if (i < len && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  for (; i < len && s[i] != 'e' && s[i] != 'E'; i++) {
    int d = s[i] - '0';
    if (s[i] == '.') { seen_dot = 1; continue; }
    if (!started && d == 0) {         /* leading zeros */
      if (seen_dot) point--;
      continue;
    }
    started = 1;
    if (!seen_dot) point++;
    if (kept == KEPT_DIGITS) {        /* beyond: only whether it is 0 */
      if (d != 0) inexact = 1;
      continue;
    }
    kept++;
    chunk = chunk * 10 + (uint32_t)d;
    if (++in_chunk == 9) {
      if (big_muladd(&a, 1000000000u, chunk) != 0) return NAN;
      chunk = 0, in_chunk = 0;
    }
  }
  if (in_chunk > 0) {
    uint32_t p = 1;
    int j;
    for (j = 0; j < in_chunk; j++) p *= 10;
    if (big_muladd(&a, p, chunk) != 0) return NAN;
  }
  if (i < len) {                      /* the exponent, saturated */
    int eneg = 0;
    i++;
    if (i < len && (s[i] == '+' || s[i] == '-')) eneg = s[i++] == '-';
    for (; i < len; i++)
      if (expo < 100000000L) expo = expo * 10 + (s[i] - '0');
    point += eneg ? -expo : expo;
  }
  if (!started || point < P_UNDERFLOW) return neg ? -0.0 : 0.0;
  if (point > P_OVERFLOW) return neg ? -HUGE_VAL : HUGE_VAL;
  /* x = a * 10^(point - kept) = a / b, both integers */
  if (point - kept >= 0) {             /* an integer: its top bits */
    if (big_mul_pow10(&a, (long)(point - kept)) != 0) return NAN;
    top_bits(&a, &q, &k, &inexact);
  } else if (kept - point <= SHORT_DIVISION_MAX) {
    if (by_five(&a, (int)(kept - point), &q, &k, &inexact) != 0) return NAN;
  } else {
    big_set(&b, 1);
    if (big_mul_pow10(&b, (long)(kept - point)) != 0) return NAN;
    /* a / b in [2^(QUOTIENT_SHIFT-1), 2^(QUOTIENT_SHIFT+1)) after the shift */
    shift = QUOTIENT_SHIFT - (big_bits(&a) - big_bits(&b));
    if (shift > 0 ? big_shl(&a, shift) : big_shl(&b, -shift)) return NAN;
    k = -shift;                         /* x = (a / b) * 2^k */
    if (big_shl(&b, QUOTIENT_SHIFT) != 0) return NAN;
    for (i = QUOTIENT_SHIFT + 1; i-- > 0;) {   /* restoring division */
      if (big_cmp(&a, &b) >= 0) {
        big_sub(&a, &b);
        q |= UINT64_C(1) << i;
      }
      if (i > 0) big_half(&b);
    }
    if (a.n != 0) inexact = 1;
  }
  {
    double v = nearest(q, k, inexact);
    return neg ? -v : v;
  }
}
