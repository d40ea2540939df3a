/*
** decimal_print.c -- numbers written as text (path data of the shapes,
** messages) the same in every locale: printf's "%g" digits, with the
** decimal point LC_NUMERIC put in them (one or more bytes, "," in de_DE)
** written back as '.'.  No localeconv(): its result is shared state.
*/
#include <math.h>
#include <stdio.h>

#include "svg/decimal.h"

/* The bytes of "%g" output of a finite number that are not its decimal
** point (no grouping: "%g" has no ' flag). */
static int g_byte(char c) {
  return (c >= '0' && c <= '9') || c == 'e' || c == '+' || c == '-';
}

size_t arclen_decimal_print(char buf[32], double x, int digits) {
  char raw[64];
  size_t i, n = 0;
  int r;
  if (x != x) return (size_t)snprintf(buf, 32, "nan");
  if (x == HUGE_VAL || x == -HUGE_VAL)
    return (size_t)snprintf(buf, 32, "%sinf", x < 0 ? "-" : "");
  if (digits < 1) digits = 1;
  if (digits > 17) digits = 17;        /* more are not needed for a double */
  r = snprintf(raw, sizeof raw, "%.*g", digits, x);
  if (r < 0 || (size_t)r >= sizeof raw) r = 0;   /* cannot happen: <= 24 + point */
  for (i = 0; i < (size_t)r && n < 31; i++) {
    if (g_byte(raw[i])) buf[n++] = raw[i];
    else if (n == 0 || buf[n - 1] != '.') buf[n++] = '.';
  }
  buf[n] = '\0';
  return n;
}
