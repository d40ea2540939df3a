/*
** fuzz_decimal.c -- SVG's numbers (svg/decimal.c, decimal_exact.c) against
** the C library's strtod in the C locale (this process never calls
** setlocale; glibc's strtod is correctly rounded): the same double, bit for
** bit, +-0 and +-inf included.  The first byte picks the form: the data
** itself, scanned as a number where one starts; or a number built from the
** data -- a sign, digits (each byte mod 10, or runs of 0, 9 or "50..0"
** that sit near halfway points), a decimal point and an exponent from the
** first bytes -- up to thousands of digits, past the 800 the reader keeps.
*/
#include "svg/decimal.h"
#include "fuzz_input.h"

#define MAXLEN 5000

static void compare(const char *s, size_t len) {
  char buf[MAXLEN + 64];
  double mine, theirs;
  char *end;
  if (len > MAXLEN) return;
  memcpy(buf, s, len);
  buf[len] = '\0';
  if (arclen_decimal_value(s, len, &mine) != 0)
    fz_fail("decimal", NULL, 0, "no value (len %g)%g", (double)len, 0);
  theirs = strtod(buf, &end);
  if ((size_t)(end - buf) != len)
    fz_fail("decimal", NULL, 0, "strtod read %g of %g bytes", (double)(end - buf),
            (double)len);
  if (memcmp(&mine, &theirs, sizeof mine) != 0) {
    fprintf(stderr, "text: %s\n", buf);
    fz_fail("decimal", NULL, 0, "%.17g, strtod %.17g", mine, theirs);
  }
}

static void built(const uint8_t *d, size_t n) {
  static const char *const RUN = "0950";
  char s[MAXLEN + 32];
  size_t len = 0, i, ndig, point;
  int mode, expo;
  if (n < 4) return;
  mode = d[0] >> 1;
  expo = ((int)d[1] << 8 | d[2]) % 1500 - 750;    /* far past both ends */
  point = d[3];
  d += 4, n -= 4;
  if (mode & 1) s[len++] = '-';
  else if (mode & 2) s[len++] = '+';
  ndig = n < MAXLEN - 16 ? n : MAXLEN - 16;
  if (ndig == 0) ndig = 1;
  if (point > ndig) point = ndig;
  for (i = 0; i < ndig; i++) {
    char c;
    if (i == point && (mode & 4)) s[len++] = '.';
    if ((mode >> 3) % 4 == 0 || i < 17) c = (char)('0' + (i < n ? d[i] % 10 : 1));
    else if ((mode >> 3) % 4 == 3) c = i == 17 ? '5' : '0';
    else c = RUN[(mode >> 3) % 4];
    s[len++] = c;
  }
  if ((mode & 4) && point == ndig) s[len++] = '.';
  len += (size_t)sprintf(s + len, "e%d", expo);
  compare(s, len);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  if (data[0] & 1) {
    built(data + 1, size - 1);
  } else {
    const char *s = (const char *)data + 1;
    size_t n = size - 1, exp_at, e;
    e = arclen_decimal_mantissa(s, n, 0, &exp_at);
    if (e == 0) return 0;
    if (exp_at < n) e = arclen_decimal_exponent(s, n, exp_at);
    compare(s, e);
  }
  return 0;
}
