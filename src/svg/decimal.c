/*
** decimal.c -- scanning SVG's numbers and converting them to doubles.  Most
** numbers of real documents have few digits: those are converted exactly
** by one multiplication or division (Clinger's fast path), the rest by
** decimal_exact.c: never strtod, whose decimal point is LC_NUMERIC's.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "svg/decimal.h"

static int is_digit(char c) { return c >= '0' && c <= '9'; }

static size_t digits(const char *s, size_t n, size_t i) {
  while (i < n && is_digit(s[i])) i++;
  return i;
}

size_t arclen_decimal_mantissa(const char *s, size_t n, size_t i,
                               size_t *exp_at) {
  size_t j = i, k;
  *exp_at = n;
  if (j < n && (s[j] == '+' || s[j] == '-')) j++;
  k = digits(s, n, j);
  if (k > j) {                                   /* digits [. digits] */
    if (k < n && s[k] == '.') k = digits(s, n, k + 1);
  } else if (j + 1 < n && s[j] == '.' && is_digit(s[j + 1])) {
    k = digits(s, n, j + 1);                     /* . digits */
  } else {
    return i;
  }
  if (k < n && (s[k] == 'e' || s[k] == 'E')) *exp_at = k;
  return k;
}

size_t arclen_decimal_exponent(const char *s, size_t n, size_t i) {
  size_t j = i + 1, k;
  if (i >= n || (s[i] != 'e' && s[i] != 'E')) return i;
  if (j < n && (s[j] == '+' || s[j] == '-')) j++;
  k = digits(s, n, j);
  return k > j ? k : i;
}

/* 10^0 .. 10^22: every one exact in a double. */
static const double POW10[23] = {
  1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
  1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
};

/* The fast path: m (at most 2^53) and 10^|e| (|e| <= 22) are exact, so one
** correctly rounded operation gives the correctly rounded value. */
static int exact_value(const char *s, size_t len, double *v) {
  uint64_t m = 0;
  int sig = 0, e = 0, neg = 0, seen_dot = 0;
  size_t i = 0;
  if (i < len && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  for (; i < len && s[i] != 'e' && s[i] != 'E'; i++) {
    if (s[i] == '.') { seen_dot = 1; continue; }
    if (m == 0 && s[i] == '0') { if (seen_dot) e--; continue; }
    if (++sig > 16) return 0;                   /* may exceed 2^53 */
    m = m * 10 + (uint64_t)(s[i] - '0');
    if (seen_dot) e--;
  }
  if (i < len) {                                /* the exponent */
    int eneg = 0, x = 0;
    i++;
    if (s[i] == '+' || s[i] == '-') eneg = s[i++] == '-';
    for (; i < len; i++) {
      if (x > 1000) return 0;                   /* far out: the slow path */
      x = x * 10 + (s[i] - '0');
    }
    e += eneg ? -x : x;
  }
  if (m > (1ULL << 53) || e < -22 || e > 22) return 0;
  *v = e < 0 ? (double)m / POW10[-e] : (double)m * POW10[e];
  if (neg) *v = -*v;
  return 1;
}

int arclen_decimal_value(const char *s, size_t len, double *v) {
  if (exact_value(s, len, v)) return 0;
  *v = arclen_decimal_exact(s, len);
  return *v == *v ? 0 : -1;
}

size_t arclen_decimal_scan(const char *s, size_t n, size_t i, double *v) {
  size_t exp_at, e = arclen_decimal_mantissa(s, n, i, &exp_at);
  if (e == i) return i;
  if (exp_at < n) e = arclen_decimal_exponent(s, n, exp_at);
  if (arclen_decimal_value(s + i, e - i, v) != 0) return i;
  return *v > -HUGE_VAL && *v < HUGE_VAL ? e : i;
}

/* C's isspace in the C locale, whatever LC_CTYPE the host sets. */
static int is_space(unsigned char c) {
  return c == ' ' || (c >= '\t' && c <= '\r');   /* \t \n \v \f \r */
}

size_t arclen_decimal_list_start(const char *s, size_t n) {
  size_t i = 0;
  while (i < n && (is_space((unsigned char)s[i]) || s[i] == ',')) i++;
  return i;
}

size_t arclen_decimal_list_next(const char *s, size_t n, size_t i, double *v) {
  size_t e = arclen_decimal_scan(s, n, i, v);
  if (e == i) return i;
  while (e < n && is_space((unsigned char)s[e])) e++;
  if (e < n && s[e] == ',') e++;
  while (e < n && is_space((unsigned char)s[e])) e++;
  return e;
}
