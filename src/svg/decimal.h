/*
** decimal.h -- the numbers of SVG's grammars: [+-] (digits [. digits] |
** . digits) [e|E [+-] digits], scanned and converted to the nearest double.
*/
#ifndef ARCLEN_DECIMAL_H
#define ARCLEN_DECIMAL_H

#include <stddef.h>

/* The end of a number's mantissa starting at s[i] (i < n), or i when
** there is none; *exp_at is set to the index of an 'e'/'E' right after
** the mantissa (n when none), whether or not digits follow it. */
size_t arclen_decimal_mantissa(const char *s, size_t n, size_t i,
                               size_t *exp_at);

/* The end of the exponent [eE][+-]digits at s[i], or i when there is no
** complete one. */
size_t arclen_decimal_exponent(const char *s, size_t n, size_t i);

/* The value of a scanned number s[0 .. len-1], correctly rounded (as
** strtod in the C locale, in any locale); +-HUGE_VAL beyond the doubles.
** Returns 0 (-1 only if decimal_exact.c's fixed bounds were wrong). */
int arclen_decimal_value(const char *s, size_t len, double *v);

/* The same without the fast path (decimal_exact.c): the nearest double,
** ties to even, +-0 below half the least subnormal; NaN only if its fixed
** buffers were too small (they are not: see its bounds). */
double arclen_decimal_exact(const char *s, size_t len);

/* x as printf's "%.<digits>g" writes it in the C locale, whatever the
** process's LC_NUMERIC: "inf", "-inf" and "nan" when not finite.  buf has
** room for 32 bytes (digits <= 17); returns the length written. */
size_t arclen_decimal_print(char buf[32], double x, int digits);

/* The number at s[i] with its value in *v: returns the end, or i when
** there is none, when it is beyond the doubles, or without memory.  An
** 'e' without digits ends the number before it. */
size_t arclen_decimal_scan(const char *s, size_t n, size_t i, double *v);

/* A list of numbers separated by whitespace and at most one comma (points,
** viewBox): arclen_decimal_list_start skips the leading whitespace and
** commas; arclen_decimal_list_next reads the number at s[i] into *v and
** returns the index after it and its separator, or i when no number
** starts at s[i] (i < n). */
size_t arclen_decimal_list_start(const char *s, size_t n);
size_t arclen_decimal_list_next(const char *s, size_t n, size_t i, double *v);

#endif
