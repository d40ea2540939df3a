/*
** attrs.c -- the attributes the reader interprets: lengths with units
** (SVG 2 section 4.3, CSS Values 3 section 5.2), the transform list (SVG
** 1.1 section 7.6), viewBox and preserveAspectRatio (SVG 2 section 8.2),
** the properties it reads, cascaded from the presentation attributes,
** the style sheets (css.c) and style="" (SVG 2 section 6), and the
** font-size that em, ex and rem refer to (CSS Fonts 4 section 2.5).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "svg/decimal.h"
#include "svgdoc/css.h"
#include "svgdoc/internal.h"
#include "svgdoc/paint.h"

#define FONT_SIZE 16.0   /* the initial font-size (CSS "medium") */

/* The C locale's character classes, whatever LC_CTYPE the host sets:
** tolower('I') is 'I' under tr_TR.UTF-8 (0xFD under tr_TR.ISO-8859-9), so
** "1IN" would be an unknown unit, and 8-bit locales make bytes above 127
** letters. */
static int is_letter(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
static unsigned char lower(unsigned char c) {
  return c >= 'A' && c <= 'Z' ? (unsigned char)(c - 'A' + 'a') : c;
}
#define space svgdoc_space

const char *svgdoc_attr(const char **atts, const char *name) {
  for (; *atts; atts += 2)   /* the first byte first (a strcmp a pair was
                              ** 5% of a drawing of circles) */
    if (atts[0][0] == name[0] && strcmp(atts[0], name) == 0) return atts[1];
  return NULL;
}

int svgdoc_blank(const char *s) {
  for (; *s; s++)
    if (!space((unsigned char)*s)) return 0;
  return 1;
}

void svgdoc_num(char buf[32], double x) { arclen_decimal_print(buf, x, 17); }

double svgdoc_nonneg(svgdoc *D, unsigned long line, unsigned long col,
                     double v, const char *what) {
  if (v < 0) {
    char num[32];
    svgdoc_num(num, v);
    svgdoc_fail(D, line, col, "%s must not be negative (%s)", what, num);
  }
  return v;
}

int svgdoc_negative(svgdoc *D, unsigned long line, unsigned long col,
                    const char *tag, const char *name, double v,
                    const char *consequence) {
  char num[32];
  if (!(v < 0)) return 0;
  svgdoc_num(num, v);
  svgdoc_lenient(D, line, col, svgdoc_format(D, "<%s>: %s must not be "
                 "negative (%s)", tag, name, num), consequence);
  return 1;
}

/* ---- lengths -------------------------------------------------------- */

/* A length's unit and what it is in px, px / div (CSS: 1in = 96px); px 0
** for the percentage, -1 for em and ex (the element's font-size, ex half
** of it, as renderers without font metrics take it), -2 for rem (the
** root's). */
static const struct { const char *name; double px, div; } UNITS[] = {
  {"", 1, 1}, {"px", 1, 1}, {"in", 96.0, 1}, {"cm", 96 / 2.54, 1},
  {"mm", 96 / 25.4, 1}, {"pt", 96.0 / 72, 1}, {"pc", 96.0 / 6, 1},
  {"q", 96 / 101.6, 1}, {"em", -1, 1}, {"ex", -1, 2}, {"rem", -2, 1},
  {"%", 0, 1}};

/* The entry of UNITS that u[0 .. n-1] names, in any case; -1 if none. */
static int unit_of(const char *u, size_t n) {
  int k;
  size_t i;
  for (k = 0; k < (int)(sizeof UNITS / sizeof UNITS[0]); k++) {
    if (strlen(UNITS[k].name) != n) continue;
    for (i = 0; i < n && lower((unsigned char)u[i]) == UNITS[k].name[i]; i++) {}
    if (i == n) return k;
  }
  return -1;
}

double svgdoc_length(svgdoc *D, unsigned long line, unsigned long col,
                     const char *s, int kind, const svgdoc_viewport *vp,
                     const char *what) {
  size_t n = strlen(s), i = 0, e, u;
  int k;
  double v;
  while (i < n && space((unsigned char)s[i])) i++;
  if (i == n) i = 0;
  e = i < n ? arclen_decimal_scan(s, n, i, &v) : i;
  if (e == i) goto bad;
  for (u = e; u < n && is_letter((unsigned char)s[u]); u++) {}
  if (u < n && s[u] == '%') u++;
  for (i = u; i < n && space((unsigned char)s[i]); i++) {}
  if (i < n) goto bad;
  k = unit_of(s + e, u - e);
  if (k >= 0 && UNITS[k].px > 0) return v * UNITS[k].px / UNITS[k].div;
  if (k >= 0 && UNITS[k].px < 0)
    return v * (UNITS[k].px == -1 ? vp->em : vp->rem) / UNITS[k].div;
  if (k >= 0) {                                  /* a percentage */
    double ref;
    if (!vp->has)
      svgdoc_fail(D, line, col, "%s='%s': a percentage needs a viewport (the "
                  "root has neither viewBox nor width and height)", what, s);
    if (kind == 'x') ref = vp->w;
    else if (kind == 'y') ref = vp->h;
    else ref = sqrt((vp->w * vp->w + vp->h * vp->h) / 2);
    return v / 100 * ref;
  }
  {
    char *unit = svgdoc_strdup(D, s + e, u - e);
    for (i = 0; unit[i]; i++) unit[i] = (char)lower((unsigned char)unit[i]);
    svgdoc_fail(D, line, col, "%s='%s': unknown unit '%s'", what, s, unit);
  }
bad:
  svgdoc_fail(D, line, col, "%s='%s' is not a length", what, s);
}

int svgdoc_length_try(const char *s, int kind, const svgdoc_viewport *vp,
                      double *v) {
  size_t n = strlen(s), i = 0, e, u;
  int k;
  while (i < n && space((unsigned char)s[i])) i++;
  e = i < n ? arclen_decimal_scan(s, n, i, v) : i;
  if (e == i) return 0;
  for (u = e; u < n && is_letter((unsigned char)s[u]); u++) {}
  if (u < n && s[u] == '%') u++;
  for (i = u; i < n && space((unsigned char)s[i]); i++) {}
  if (i < n || (k = unit_of(s + e, u - e)) < 0) return 0;
  if (UNITS[k].px > 0) *v = *v * UNITS[k].px / UNITS[k].div;
  else if (UNITS[k].px < 0)
    *v = *v * (UNITS[k].px == -1 ? vp->em : vp->rem) / UNITS[k].div;
  else if (!vp->has) return 0;
  else if (kind == 'x') *v = *v / 100 * vp->w;
  else if (kind == 'y') *v = *v / 100 * vp->h;
  else *v = *v / 100 * sqrt((vp->w * vp->w + vp->h * vp->h) / 2);
  return isfinite(*v);
}

int svgdoc_len_attr(svgdoc *D, unsigned long line, unsigned long col,
                    const char **atts, const char *name, int kind,
                    const svgdoc_viewport *vp, double *v) {
  const char *s = svgdoc_attr(atts, name);
  if (s == NULL || svgdoc_blank(s)) return 0;
  *v = svgdoc_length(D, line, col, s, kind, vp, name);
  return 1;
}

/* ---- transforms ------------------------------------------------------- */

static const struct {
  const char *name;
  int counts[2];        /* the argument counts it takes (0: none more) */
} FUNCS[] = {
  {"matrix", {6, 0}}, {"translate", {1, 2}}, {"scale", {1, 2}},
  {"rotate", {1, 3}}, {"skewX", {1, 0}}, {"skewY", {1, 0}}};

/* Lua's float modulo (the sign of the divisor), as the reader had it. */
static double lua_fmod(double a, double b) {
  double m = fmod(a, b);
  if (m != 0 && (m < 0) != (b < 0)) m += b;
  return m;
}

static double rad(double deg) {
  return deg * (3.141592653589793238462643383279502884 / 180.0);
}

/* One transform function to a matrix (angles in degrees). */
static void transform_function(int f, const double *a, int na,
                               svgdoc_matrix R) {
  switch (f) {
  case 0:
    memcpy(R, a, 6 * sizeof *a);
    break;
  case 1:
    svgdoc_translate(a[0], na > 1 ? a[1] : 0, R);
    break;
  case 2:
    R[0] = a[0], R[1] = 0, R[2] = 0, R[3] = na > 1 ? a[1] : a[0];
    R[4] = 0, R[5] = 0;
    break;
  case 3: {
    double t = rad(a[0]), c = cos(t), s = sin(t);
    /* exact at multiples of 90 degrees, as a renderer's matrix is meant
    ** to be */
    if (lua_fmod(a[0], 90) == 0) {
      static const double C[4] = {1, 0, -1, 0}, S[4] = {0, 1, 0, -1};
      int q = (int)lua_fmod(floor(a[0] / 90), 4);
      c = C[q], s = S[q];
    }
    R[0] = c, R[1] = s, R[2] = -s, R[3] = c, R[4] = 0, R[5] = 0;
    if (na == 3) {     /* translate(cx cy) rotate(a) translate(-cx -cy) */
      svgdoc_matrix A, B;
      svgdoc_translate(a[1], a[2], A);
      svgdoc_mul(A, R, A);
      svgdoc_translate(-a[1], -a[2], B);
      svgdoc_mul(A, B, R);
    }
    break;
  }
  case 4:
    R[0] = 1, R[1] = 0, R[2] = tan(rad(a[0])), R[3] = 1, R[4] = 0, R[5] = 0;
    break;
  default:
    R[0] = 1, R[1] = tan(rad(a[0])), R[2] = 0, R[3] = 1, R[4] = 0, R[5] = 0;
  }
}

/* Whitespace, at most one comma, whitespace from s[i]: the end, and
** whether a comma was among them. */
static size_t separator(const char *s, size_t n, size_t i, int *comma) {
  while (i < n && space((unsigned char)s[i])) i++;
  *comma = i < n && s[i] == ',';
  if (*comma) i++;
  while (i < n && space((unsigned char)s[i])) i++;
  return i;
}

/* Read as browsers do: functions separated by optional whitespace and at
** most one comma, arguments by comma-wsp, spaces allowed around the
** parentheses; a comma before ')' or after the last function is an
** error.  Positions in messages count from 1. */
void svgdoc_transform(svgdoc *D, unsigned long line, unsigned long col,
                      const char *s, svgdoc_matrix T) {
  size_t n = strlen(s), i = 0, turn, k;
  const char *why = NULL;
  char whybuf[96];
  svgdoc_translate(0, 0, T);
  while (i < n && space((unsigned char)s[i])) i++;
  for (turn = 0; turn < n && i < n; turn++) {     /* one function a turn */
    size_t e = i, len, at = i;          /* at: the function's start */
    int f, na = 0, comma, ok;
    double a[7];
    svgdoc_matrix R;
    while (e < n && is_letter((unsigned char)s[e])) e++;
    if (e == i) { why = "a transform function expected"; goto bad; }
    len = e - i;
    for (f = 0; f < 6; f++)
      if (strlen(FUNCS[f].name) == len && memcmp(FUNCS[f].name, s + i, len) == 0)
        break;
    if (f == 6) {
      snprintf(whybuf, sizeof whybuf, "unknown transform '%.*s'",
               (int)(len > 64 ? 64 : len), s + i);
      if (len > 64) {
        svgdoc_fail(D, line, col, "transform='%s': unknown transform '%.*s' "
                    "at character %lu", s, (int)len, s + i,
                    (unsigned long)(i + 1));
      }
      why = whybuf;
      goto bad;
    }
    i = e;
    while (e < n && space((unsigned char)s[e])) e++;
    if (e == n || s[e] != '(') {
      snprintf(whybuf, sizeof whybuf, "'(' expected after %s", FUNCS[f].name);
      why = whybuf;
      goto bad;
    }
    e++;
    while (e < n && space((unsigned char)s[e])) e++;
    i = e;
    for (k = 0; k < 7; k++) {
      double v;
      size_t j;
      if (i < n && s[i] == ')') break;
      j = i < n ? arclen_decimal_scan(s, n, i, &v) : i;
      if (j == i) {
        snprintf(whybuf, sizeof whybuf, "a number or ')' expected in %s(...)",
                 FUNCS[f].name);
        why = whybuf;
        goto bad;
      }
      a[na++] = v;
      e = separator(s, n, j, &comma);
      if (e < n && s[e] == ')' && comma) {
        i = e;
        why = "comma before ')'";
        goto bad;
      }
      i = e;
    }
    if (i >= n || s[i] != ')') {
      snprintf(whybuf, sizeof whybuf, "too many arguments to %s", FUNCS[f].name);
      why = whybuf;
      goto bad;
    }
    ok = na == FUNCS[f].counts[0] || na == FUNCS[f].counts[1];
    if (!ok) {
      if (FUNCS[f].counts[1])
        snprintf(whybuf, sizeof whybuf, "%s takes %d or %d arguments, got %d",
                 FUNCS[f].name, FUNCS[f].counts[0], FUNCS[f].counts[1], na);
      else
        snprintf(whybuf, sizeof whybuf, "%s takes %d arguments, got %d",
                 FUNCS[f].name, FUNCS[f].counts[0], na);
      why = whybuf;
      goto bad;
    }
    if (f >= 4 && fabs(fmod(a[0], 180)) == 90) {
      /* tan 90 degrees is infinite: no matrix (double's tan gives 1.6e16) */
      char num[32];
      svgdoc_num(num, a[0]);
      snprintf(whybuf, sizeof whybuf, "%s(%s) is undefined (a skew angle "
               "must not be 90 degrees modulo 180)", FUNCS[f].name, num);
      why = whybuf;
      i = at;
      goto bad;
    }
    transform_function(f, a, na, R);
    svgdoc_mul(T, R, T);
    e = separator(s, n, i + 1, &comma);
    if (e >= n && comma) {
      i = i + 1;
      why = "comma after the last transform";
      goto bad;
    }
    i = e;
  }
  for (k = 0; k < 6; k++)
    if (!isfinite(T[k]))
      svgdoc_fail(D, line, col, "transform='%s' overflows", s);
  return;
bad:
  svgdoc_fail(D, line, col, "transform='%s': %s at character %lu", s, why,
              (unsigned long)(i + 1));
}

/* ---- viewBox ------------------------------------------------------------ */

int svgdoc_viewbox(svgdoc *D, unsigned long line, unsigned long col,
                   const char *s, double vb[4]) {
  size_t n, i, count = 0;
  if (s == NULL || svgdoc_blank(s)) return 0;
  n = strlen(s);
  for (i = arclen_decimal_list_start(s, n); i < n;) {
    double v;
    size_t e;
    if (++count > 8) svgdoc_fail(D, line, col, "viewBox: too many numbers");
    e = arclen_decimal_list_next(s, n, i, &v);
    if (e == i) break;
    if (count <= 4) vb[count - 1] = v;
    i = e;
  }
  if (i < n || count != 4)
    svgdoc_fail(D, line, col, "viewBox='%s' is not four numbers", s);
  if (vb[2] < 0 || vb[3] < 0)
    svgdoc_fail(D, line, col, "viewBox='%s': negative width or height", s);
  return 1;
}

/* Min, Mid or Max at s: 0, 1, 2; -1 for anything else. */
static int align_of(const char *s) {
  if (strncmp(s, "Min", 3) == 0) return 0;
  if (strncmp(s, "Mid", 3) == 0) return 1;
  if (strncmp(s, "Max", 3) == 0) return 2;
  return -1;
}

void svgdoc_viewbox_matrix(svgdoc *D, unsigned long line, unsigned long col,
                           const double vb[4], const char *par, double ex,
                           double ey, double ew, double eh, svgdoc_matrix M) {
  int none = 0, slice = 0, ax = 1, ay = 1;
  double sx = ew / vb[2], sy = eh / vb[3], tx, ty;
  if (par && !svgdoc_blank(par)) {
    const char *w[4];
    size_t wl[4], nw = 0, i = 0, n = strlen(par);
    int ok, more;
    for (;;) {                            /* the first four words */
      while (i < n && space((unsigned char)par[i])) i++;
      if (i == n || nw == 4) break;
      w[nw] = par + i;
      while (i < n && !space((unsigned char)par[i])) i++;
      wl[nw] = (size_t)(par + i - w[nw]);
      nw++;
    }
    more = i < n;
    if (nw > 0 && wl[0] == 5 && memcmp(w[0], "defer", 5) == 0) {
      memmove(w, w + 1, 3 * sizeof *w);
      memmove(wl, wl + 1, 3 * sizeof *wl);
      nw--;
    }
    ok = !more && nw >= 1 && nw <= 2;
    if (ok && wl[0] == 4 && memcmp(w[0], "none", 4) == 0) {
      none = 1;
    } else if (ok) {
      ok = wl[0] == 8 && w[0][0] == 'x' && w[0][4] == 'Y';
      if (ok) {
        ax = align_of(w[0] + 1), ay = align_of(w[0] + 5);
        ok = ax >= 0 && ay >= 0;
      }
    }
    if (ok && nw == 2) {
      if (wl[1] == 5 && memcmp(w[1], "slice", 5) == 0) slice = 1;
      else if (!(wl[1] == 4 && memcmp(w[1], "meet", 4) == 0)) ok = 0;
    }
    if (!ok)
      svgdoc_fail(D, line, col, "preserveAspectRatio='%s' is not valid", par);
  }
  if (!none) {
    sx = slice ? (sx > sy ? sx : sy) : (sx < sy ? sx : sy);
    sy = sx;
  }
  tx = ex - vb[0] * sx, ty = ey - vb[1] * sy;
  if (!none) {
    if (ax == 1) tx = tx + (ew - vb[2] * sx) / 2;
    if (ax == 2) tx = tx + (ew - vb[2] * sx);
    if (ay == 1) ty = ty + (eh - vb[3] * sy) / 2;
    if (ay == 2) ty = ty + (eh - vb[3] * sy);
  }
  M[0] = sx, M[1] = 0, M[2] = 0, M[3] = sy, M[4] = tx, M[5] = ty;
}

/* ---- properties ------------------------------------------------------ */

static const char *const PROPS[SVGDOC_NPROPS] = {
  "display", "visibility", "stroke", "stroke-width", "fill", "fill-opacity",
  "stroke-opacity", "opacity", "color", "font-size", "marker-start",
  "marker-mid", "marker-end", "overflow"};

int svgdoc_prop_index(const char *name) {
  int k;
  for (k = 0; k < SVGDOC_NPROPS; k++)
    if (strcmp(PROPS[k], name) == 0) return k;
  return -1;
}

const char *svgdoc_prop_name(int k) { return PROPS[k]; }

/* May byte c precede a property's name?  (The name must be whole.) */
static int name_byte(unsigned char c) {
  return is_letter(c) || (c >= '0' && c <= '9') || c == '-';
}

/* Trimmed and lower-cased s[0 .. n-1] into b, but for what url( ... )
** holds (ids are case-sensitive), or all of it when cased. */
static const char *normalised(svgdoc *D, svgdoc_buffer *b, const char *s,
                              size_t n, int cased) {
  size_t i;
  int in_url = 0;
  while (n > 0 && space((unsigned char)*s)) s++, n--;
  while (n > 0 && space((unsigned char)s[n - 1])) n--;
  svgdoc_reserve(D, b, n + 1);
  for (i = 0; i < n; i++) {
    char c = cased || in_url ? s[i] : (char)lower((unsigned char)s[i]);
    b->s[i] = c;
    if (c == '(' && i >= 3 && memcmp(b->s + i - 3, "url", 3) == 0) in_url = 1;
    else if (c == ')') in_url = 0;
  }
  b->s[n] = '\0';
  return b->s;
}

/* The value of the last whole declaration "name: value" in style s that
** is !important (important) or not (the last one wins, as in CSS),
** "!important" and trailing space removed; 0 when none. */
static int style_value(const char *s, const char *name, int important,
                       const char **v, size_t *vn) {
  size_t nl = strlen(name);
  const char *p = s;
  int found = 0;
  while ((p = strstr(p, name)) != NULL) {
    const char *q = p + nl, *e;
    size_t n, m;
    int imp = 0;
    if (p != s && name_byte((unsigned char)p[-1])) { p++; continue; }
    while (*q && space((unsigned char)*q)) q++;
    if (*q != ':') { p++; continue; }
    q++;
    while (*q && space((unsigned char)*q)) q++;
    for (e = q; *e && *e != ';'; e++) {}
    p = e;
    n = (size_t)(e - q), m = n;   /* "%s*!%s*important%s*$" then trailing space */
    while (m > 0 && space((unsigned char)q[m - 1])) m--;
    if (m >= 9) {
      size_t k = m - 9, j;
      for (j = 0; j < 9 && lower((unsigned char)q[k + j]) == "important"[j]; j++) {}
      while (j == 9 && k > 0 && space((unsigned char)q[k - 1])) k--;
      if (j == 9 && k > 0 && q[k - 1] == '!') {
        k--;
        while (k > 0 && space((unsigned char)q[k - 1])) k--;
        n = k, imp = 1;
      }
    }
    while (n > 0 && space((unsigned char)q[n - 1])) n--;
    if (imp != important) continue;
    *v = q, *vn = n, found = 1;
  }
  return found;
}

static int font_size_of(const char *s, double em, double rem, double *px);

/* The reader reads only some keywords of display (none) and visibility,
** but an unknown word is still a valid display (CSS Display 3 has many);
** a number is not. */
int svgdoc_prop_valid(int k, const char *s) {
  double em;
  if (strcmp(s, "inherit") == 0 || strcmp(s, "initial") == 0 ||
      strcmp(s, "unset") == 0)
    return 1;
  if (k == SVGDOC_DISPLAY) {
    for (; *s; s++)
      if (!is_letter((unsigned char)*s) && *s != '-' && !space((unsigned char)*s))
        return 0;
    return 1;
  }
  if (k == SVGDOC_VISIBILITY)
    return strcmp(s, "visible") == 0 || strcmp(s, "hidden") == 0 ||
           strcmp(s, "collapse") == 0;
  if (k == SVGDOC_FONT_SIZE) return font_size_of(s, 16, 16, &em);
  return svgdoc_paint_valid(k, s);
}

/* style_value of property k, where a marker longhand also takes the
** shorthand `marker`: the later declaration of the two wins (CSS Cascade 4
** section 6: a shorthand sets its longhands where it stands). */
static int style_of(const char *s, int k, int important, const char **v,
                    size_t *vn) {
  const char *w;
  size_t wn;
  int found = style_value(s, PROPS[k], important, v, vn);
  if (SVGDOC_CASED_PROP(k) && style_value(s, "marker", important, &w, &wn) &&
      (!found || w > *v)) {
    *v = w, *vn = wn;
    found = 1;
  }
  return found;
}

void svgdoc_properties(svgdoc *D, unsigned long line, unsigned long col,
                       const char **atts, const struct svgdoc_css_match *sheet,
                       const char *out[]) {
  const char *style = svgdoc_attr(atts, "style");
  /* styles rarely name the marker properties or overflow: one scan says */
  int marked = style && strstr(style, "marker") != NULL;
  int over = style && strstr(style, "overflow") != NULL;
  int k, origin;
  for (k = 0; k < SVGDOC_NPROPS; k++) {
    const char *st = style;
    if ((SVGDOC_CASED_PROP(k) && !marked) || (k == SVGDOC_OVERFLOW && !over))
      st = NULL;
    out[k] = NULL;
    /* from the strongest down (SVG 2 section 6.3; Cascade 4 section 6); an
    ** invalid value is dropped and the next origin's applies (CSS Syntax 3
    ** section 5: an invalid declaration is ignored; SVG 2 section 6.6 for a
    ** presentation attribute) */
    for (origin = 0; origin < 5 && out[k] == NULL; origin++) {
      const char *v = NULL, *n;
      size_t vn = 0;
      if (origin == 0 && st && style_of(st, k, 1, &v, &vn)) {
      } else if (origin == 1 && sheet && (v = sheet->important[k]) != NULL) {
        vn = strlen(v);
      } else if (origin == 2 && st && style_of(st, k, 0, &v, &vn)) {
      } else if (origin == 3 && sheet && (v = sheet->normal[k]) != NULL) {
        vn = strlen(v);
      } else if (origin == 4 && (v = svgdoc_attr(atts, PROPS[k])) != NULL) {
        vn = strlen(v);
      }
      if (v == NULL) continue;
      n = normalised(D, &D->props[k], v, vn, SVGDOC_CASED_PROP(k));
      if (svgdoc_prop_valid(k, n)) out[k] = n;
      else
        svgdoc_warn(D, line, col, svgdoc_format(D, "%s '%s' is not a valid "
                                                "value: ignored", PROPS[k], n));
    }
  }
}

/* ---- font-size -------------------------------------------------------- */

/* The absolute sizes' scaling factors from medium (CSS Fonts 4 2.5). */
static const struct { const char *name; double f; } SIZES[] = {
  {"xx-small", 3.0 / 5}, {"x-small", 3.0 / 4}, {"small", 8.0 / 9},
  {"medium", 1}, {"large", 6.0 / 5}, {"x-large", 3.0 / 2}, {"xx-large", 2},
  {"xxx-large", 3}};

/* The font-size (px) of value s, not a CSS-wide keyword, under a parent of
** font-size em and a root of rem: 1 with *px, 0 when s is not a size. */
static int font_size_of(const char *s, double em, double rem, double *px) {
  size_t n, e, u, i;
  int k;
  double v;
  for (k = 0; k < (int)(sizeof SIZES / sizeof SIZES[0]); k++)
    if (strcmp(s, SIZES[k].name) == 0) return *px = FONT_SIZE * SIZES[k].f, 1;
  /* the relative sizes: a ratio of 1.2 (CSS 2 section 15.7) */
  if (strcmp(s, "larger") == 0) return *px = em * 1.2, 1;
  if (strcmp(s, "smaller") == 0) return *px = em / 1.2, 1;
  n = strlen(s);
  e = arclen_decimal_scan(s, n, 0, &v);
  if (e == 0 || v < 0) return 0;
  for (u = e; u < n && is_letter((unsigned char)s[u]); u++) {}
  if (u < n && s[u] == '%') u++;
  for (i = u; i < n && space((unsigned char)s[i]); i++) {}
  k = i == n ? unit_of(s + e, u - e) : -1;
  if (k >= 0 && UNITS[k].px > 0) v = v * UNITS[k].px / UNITS[k].div;
  else if (k >= 0 && UNITS[k].px == 0) v = v / 100 * em;   /* of the parent's */
  else if (k >= 0) v = v * (UNITS[k].px == -1 ? em : rem) / UNITS[k].div;
  if (k < 0 || !isfinite(v)) return 0;
  *px = v;
  return 1;
}

double svgdoc_font_size(svgdoc *D, unsigned long line, unsigned long col,
                        const char *s, double em, double rem) {
  double px;
  if (s == NULL || strcmp(s, "inherit") == 0 || strcmp(s, "unset") == 0)
    return em;
  if (strcmp(s, "initial") == 0) return FONT_SIZE;
  if (font_size_of(s, em, rem, &px)) return px;
  /* only an overflow gets here: the cascade dropped what is not a size */
  svgdoc_warn(D, line, col, svgdoc_format(D, "font-size '%s' is too large: "
                                          "the parent's is used", s));
  return em;
}
