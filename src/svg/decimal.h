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
** strtod in the C locale); +-HUGE_VAL beyond the doubles.  Returns 0, or
** -1 when memory for a very long number ran out. */
int arclen_decimal_value(const char *s, size_t len, double *v);

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
