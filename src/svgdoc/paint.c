/*
** paint.c -- does a shape's stroke or fill show?  The paint properties
** (SVG 2 section 13: fill, stroke, fill-opacity, stroke-opacity,
** stroke-width; CSS Color 4: color, the colour syntax; CSS Color 4
** section 3.2 / SVG 2 section 14.5: opacity) read into a few flags that
** frames inherit.  Only what decides "paints nothing" is kept: a colour's
** alpha, not its hue.  A value that does not parse is ignored, as CSS
** ignores an invalid declaration: the inherited value stays.
*/
#include <stdlib.h>
#include <string.h>

#include "svg/decimal.h"
#include "svgdoc/internal.h"
#include "svgdoc/paint.h"

/* CSS Color 4 section 6.1, the named colours (all opaque), sorted. */
static const char *const NAMED[] = {
  "aliceblue", "antiquewhite", "aqua", "aquamarine", "azure", "beige",
  "bisque", "black", "blanchedalmond", "blue", "blueviolet", "brown",
  "burlywood", "cadetblue", "chartreuse", "chocolate", "coral",
  "cornflowerblue", "cornsilk", "crimson", "cyan", "darkblue", "darkcyan",
  "darkgoldenrod", "darkgray", "darkgreen", "darkgrey", "darkkhaki",
  "darkmagenta", "darkolivegreen", "darkorange", "darkorchid", "darkred",
  "darksalmon", "darkseagreen", "darkslateblue", "darkslategray",
  "darkslategrey", "darkturquoise", "darkviolet", "deeppink", "deepskyblue",
  "dimgray", "dimgrey", "dodgerblue", "firebrick", "floralwhite",
  "forestgreen", "fuchsia", "gainsboro", "ghostwhite", "gold", "goldenrod",
  "gray", "green", "greenyellow", "grey", "honeydew", "hotpink", "indianred",
  "indigo", "ivory", "khaki", "lavender", "lavenderblush", "lawngreen",
  "lemonchiffon", "lightblue", "lightcoral", "lightcyan",
  "lightgoldenrodyellow", "lightgray", "lightgreen", "lightgrey", "lightpink",
  "lightsalmon", "lightseagreen", "lightskyblue", "lightslategray",
  "lightslategrey", "lightsteelblue", "lightyellow", "lime", "limegreen",
  "linen", "magenta", "maroon", "mediumaquamarine", "mediumblue",
  "mediumorchid", "mediumpurple", "mediumseagreen", "mediumslateblue",
  "mediumspringgreen", "mediumturquoise", "mediumvioletred", "midnightblue",
  "mintcream", "mistyrose", "moccasin", "navajowhite", "navy", "oldlace",
  "olive", "olivedrab", "orange", "orangered", "orchid", "palegoldenrod",
  "palegreen", "paleturquoise", "palevioletred", "papayawhip", "peachpuff",
  "peru", "pink", "plum", "powderblue", "purple", "rebeccapurple", "red",
  "rosybrown", "royalblue", "saddlebrown", "salmon", "sandybrown",
  "seagreen", "seashell", "sienna", "silver", "skyblue", "slateblue",
  "slategray", "slategrey", "snow", "springgreen", "steelblue", "tan",
  "teal", "thistle", "tomato", "turquoise", "violet", "wheat", "white",
  "whitesmoke", "yellow", "yellowgreen"};

/* CSS Color 4 section 6.2, the system colours, current and deprecated
** (opaque), lower-cased and sorted. */
static const char *const SYSTEM[] = {
  "accentcolor", "accentcolortext", "activeborder", "activecaption",
  "activetext", "appworkspace", "background", "buttonborder", "buttonface",
  "buttonhighlight", "buttonshadow", "buttontext", "canvas", "canvastext",
  "captiontext", "field", "fieldtext", "graytext", "highlight",
  "highlighttext", "inactiveborder", "inactivecaption",
  "inactivecaptiontext", "infobackground", "infotext", "linktext", "mark",
  "marktext", "menu", "menutext", "scrollbar", "selecteditem",
  "selecteditemtext", "threeddarkshadow", "threedface", "threedhighlight",
  "threedlightshadow", "threedshadow", "visitedtext", "window",
  "windowframe", "windowtext"};

/* The colour functions whose arguments are three components and an alpha. */
static const char *const FUNCTIONS[] = {"rgb", "rgba", "hsl", "hsla", "hwb",
                                        "lab", "lch", "oklab", "oklch"};

static int compare(const void *key, const void *item) {
  return strcmp((const char *)key, *(const char *const *)item);
}
#define listed(list, s)                                                    \
  (bsearch(s, list, sizeof list / sizeof *list, sizeof *list, compare) != \
   NULL)

static int hex_digit(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
}

static int space(char c) { return svgdoc_space((unsigned char)c); }

/* s[i .. e-1] trimmed: the new i and e. */
static void trim(const char *s, size_t *i, size_t *e) {
  while (*i < *e && space(s[*i])) ++*i;
  while (*e > *i && space(s[*e - 1])) --*e;
}

/* One component or alpha, s[i .. e-1] trimmed: a number with an optional
** unit (hue's deg, rad, grad, turn) or %, or none.  1 with *v (percent
** divided by 100, none as 0, per CSS Color 4 section 4.4) when it is one. */
static int component(const char *s, size_t i, size_t e, double *v) {
  size_t j;
  trim(s, &i, &e);
  if (e - i == 4 && memcmp(s + i, "none", 4) == 0) {
    *v = 0;
    return 1;
  }
  j = i < e ? arclen_decimal_scan(s, e, i, v) : i;
  if (j == i) return 0;
  if (j + 1 == e && s[j] == '%') {
    *v /= 100;
    return 1;
  }
  for (; j < e; j++)
    if (s[j] < 'a' || s[j] > 'z') return 0;
  return 1;
}

/* The arguments of a colour function, s[i .. e-1] between the
** parentheses: three components, then an alpha after a comma (the legacy
** syntax: commas between all) or a slash; 1 with *alpha (1 when absent)
** when they are well formed. */
static int arguments(const char *s, size_t i, size_t e, double *alpha) {
  size_t at[5], k, n = 0, j;
  int commas = memchr(s + i, ',', e - i) != NULL;
  double v;
  *alpha = 1;
  at[n++] = i;
  if (commas) {                       /* a, b, c[, alpha] */
    for (j = i; j < e; j++) {
      if (s[j] != ',') continue;
      if (n == 4) return 0;
      at[n++] = j + 1;
    }
    at[n] = e + 1;
    if (n < 3) return 0;
    for (k = 0; k < n; k++)
      if (!component(s, at[k], at[k + 1] - 1, &v)) return 0;
    if (n == 4) *alpha = v;
    return 1;
  }
  {                                   /* a b c[ / alpha] */
    const char *slash = memchr(s + i, '/', e - i);
    size_t end = slash ? (size_t)(slash - s) : e, count = 0;
    for (j = i; j < end;) {           /* each component, space-separated */
      size_t start;
      while (j < end && space(s[j])) j++;
      if (j == end) break;
      start = j;
      while (j < end && !space(s[j])) j++;
      if (++count > 3 || !component(s, start, j, &v)) return 0;
    }
    if (count != 3) return 0;
    if (slash && !component(s, end + 1, e, alpha)) return 0;
  }
  return 1;
}

int svgdoc_color(const char *s, int *clear) {
  size_t n = strlen(s), k;
  *clear = 0;
  if (n == 0) return 0;
  if (s[0] == '#') {                  /* #rgb #rgba #rrggbb #rrggbbaa */
    for (k = 1; k < n; k++)
      if (!hex_digit(s[k])) return 0;
    if (n == 5) *clear = s[4] == '0';
    else if (n == 9) *clear = s[7] == '0' && s[8] == '0';
    else if (n != 4 && n != 7) return 0;
    return 1;
  }
  if (strcmp(s, "transparent") == 0) {
    *clear = 1;
    return 1;
  }
  if (listed(NAMED, s) || listed(SYSTEM, s)) return 1;
  for (k = 0; k < sizeof FUNCTIONS / sizeof *FUNCTIONS; k++) {
    size_t m = strlen(FUNCTIONS[k]), i = m;
    double alpha;
    if (strncmp(s, FUNCTIONS[k], m) != 0 || (s[m] != '(' && !space(s[m])))
      continue;                       /* rgb is no prefix of rgba */
    while (i < n && space(s[i])) i++;
    if (i == n || s[i] != '(' || s[n - 1] != ')') return 0;
    if (!arguments(s, i + 1, n - 1, &alpha)) return 0;
    *clear = !(alpha > 0);
    return 1;
  }
  return 0;
}

/* An <alpha-value> (a number or a percentage), s trimmed and lower-case:
** 1 with *zero when it is 0 or less (clamped to [0, 1]). */
static int alpha_value(const char *s, int *zero) {
  size_t n = strlen(s), j;
  double v;
  j = n ? arclen_decimal_scan(s, n, 0, &v) : 0;
  if (j == 0 || !(j == n || (j + 1 == n && s[j] == '%'))) return 0;
  *zero = !(v > 0);
  return 1;
}

/* A paint (SVG 2 section 13.2): none, a colour, currentColor, url(...)
** with an optional fallback, context-fill or context-stroke.  The kind,
** or -1 when s is none of them.  A paint server is taken to exist and to
** paint (its stops' opacities are not read); its fallback is read only
** to reject what is not a paint. */
static int paint_value(const char *s, int context_fill, int context_stroke) {
  int clear;
  if (strcmp(s, "none") == 0) return SVGDOC_PAINT_NONE;
  if (strcmp(s, "currentcolor") == 0) return SVGDOC_PAINT_CURRENT;
  if (strcmp(s, "context-fill") == 0) return context_fill;
  if (strcmp(s, "context-stroke") == 0) return context_stroke;
  if (strncmp(s, "url(", 4) == 0) {
    const char *e = strchr(s, ')');
    if (e == NULL) return -1;
    for (e++; space(*e); e++) {}
    if (*e && strcmp(e, "none") != 0 && strcmp(e, "currentcolor") != 0 &&
        !svgdoc_color(e, &clear))
      return -1;
    return SVGDOC_PAINT_SHOWN;
  }
  if (svgdoc_color(s, &clear))
    return clear ? SVGDOC_PAINT_NONE : SVGDOC_PAINT_SHOWN;
  return -1;
}

/* A stroke-width (a length or percentage, SVG 2 section 13.5.2): 1 with
** *zero when it is 0; a negative one is invalid (0). */
static int width_value(const char *s, int *zero) {
  size_t n = strlen(s), j;
  double v;
  j = n ? arclen_decimal_scan(s, n, 0, &v) : 0;
  if (j == 0 || v < 0) return 0;
  for (; j < n; j++)
    if (!((s[j] >= 'a' && s[j] <= 'z') || (s[j] == '%' && j + 1 == n)))
      return 0;
  *zero = v == 0;
  return 1;
}

int svgdoc_paint_valid(int k, const char *s) {
  int zero;
  switch (k) {
    case SVGDOC_COLOR:
      return strcmp(s, "currentcolor") == 0 || svgdoc_color(s, &zero);
    case SVGDOC_FILL: case SVGDOC_STROKE:
      return paint_value(s, SVGDOC_PAINT_SHOWN, SVGDOC_PAINT_SHOWN) >= 0;
    case SVGDOC_FILL_OPACITY: case SVGDOC_STROKE_OPACITY: case SVGDOC_OPACITY:
      return alpha_value(s, &zero);
    case SVGDOC_STROKE_WIDTH:
      return width_value(s, &zero);
    default:
      return 1;
  }
}

const char *svgdoc_paint_server(const svgdoc *D, const char *s) {
  const char *id, *e, *f;
  if (s == NULL || strncmp(s, "url(", 4) != 0) return s;
  if ((e = strchr(s, ')')) == NULL) return s;
  for (id = s + 4; space(*id); id++) {}
  for (f = e; f > id && space(f[-1]); f--) {}
  if (f > id && (*id == '"' || *id == '\'') && f[-1] == *id) id++, f--;
  if (*id != '#') return s;                    /* another file's: not read */
  id++;
  if (f <= id || !svgdoc_bloom_absent(D, id, (size_t)(f - id), 1)) return s;
  for (e++; space(*e); e++) {}
  return *e ? e : "none";
}

void svgdoc_paint_initial(svgdoc_paint *p) {
  memset(p, 0, sizeof *p);
  p->fill = SVGDOC_PAINT_SHOWN;        /* black */
  p->stroke = SVGDOC_PAINT_NONE;
}

/* CSS's global keywords: inherit and unset keep the inherited value (all
** but opacity are inherited properties), initial takes the initial one. */
static int keeps(const char *s) {
  return strcmp(s, "inherit") == 0 || strcmp(s, "unset") == 0;
}
static int initial(const char *s) { return strcmp(s, "initial") == 0; }

void svgdoc_paint_apply(svgdoc_paint *p, const char *const *P,
                        const svgdoc_paint *context) {
  svgdoc_paint init;
  const char *s;
  int v, zero;
  /* context-fill / context-stroke: the <use>'s paint; none without one
  ** (SVG 2 section 13.2: no context element) */
  int cf = context ? (context->fill_clear ? SVGDOC_PAINT_NONE : context->fill)
                   : SVGDOC_PAINT_NONE;
  int cs = context ? (context->stroke_clear || context->width_zero
                          ? SVGDOC_PAINT_NONE : context->stroke)
                   : SVGDOC_PAINT_NONE;
  if (cf == SVGDOC_PAINT_CURRENT && context->color_clear) cf = SVGDOC_PAINT_NONE;
  if (cs == SVGDOC_PAINT_CURRENT && context->color_clear) cs = SVGDOC_PAINT_NONE;
  svgdoc_paint_initial(&init);
  /* color first: currentColor is resolved at the shape, with its own */
  if ((s = P[SVGDOC_COLOR]) != NULL && !keeps(s) &&
      strcmp(s, "currentcolor") != 0) {
    if (initial(s)) p->color_clear = 0;
    else if (svgdoc_color(s, &zero)) p->color_clear = (unsigned char)zero;
  }
  if ((s = P[SVGDOC_FILL]) != NULL && !keeps(s)) {
    if (initial(s)) p->fill = init.fill;
    else if ((v = paint_value(s, cf, cs)) >= 0) p->fill = (unsigned char)v;
  }
  if ((s = P[SVGDOC_STROKE]) != NULL && !keeps(s)) {
    if (initial(s)) p->stroke = init.stroke;
    else if ((v = paint_value(s, cf, cs)) >= 0) p->stroke = (unsigned char)v;
  }
  if ((s = P[SVGDOC_FILL_OPACITY]) != NULL && !keeps(s)) {
    if (initial(s)) p->fill_clear = 0;
    else if (alpha_value(s, &zero)) p->fill_clear = (unsigned char)zero;
  }
  if ((s = P[SVGDOC_STROKE_OPACITY]) != NULL && !keeps(s)) {
    if (initial(s)) p->stroke_clear = 0;
    else if (alpha_value(s, &zero)) p->stroke_clear = (unsigned char)zero;
  }
  if ((s = P[SVGDOC_STROKE_WIDTH]) != NULL && !keeps(s)) {
    if (initial(s)) p->width_zero = 0;
    else if (width_value(s, &zero)) p->width_zero = (unsigned char)zero;
  }
  /* opacity is not inherited, but a group of opacity 0 shows none of its
  ** content (CSS Color 4 section 3.2): the flag only ever turns on */
  if ((s = P[SVGDOC_OPACITY]) != NULL && alpha_value(s, &zero) && zero)
    p->opacity_zero = 1;
}

/* Does paint kind k show, with the opacity flag of its property? */
static int shows(const svgdoc_paint *p, int k, int clear) {
  if (clear || p->opacity_zero) return 0;
  if (k == SVGDOC_PAINT_CURRENT) return !p->color_clear;
  return k == SVGDOC_PAINT_SHOWN;
}

int svgdoc_paint_stroked(const svgdoc_paint *p) {
  return !p->width_zero && shows(p, p->stroke, p->stroke_clear);
}

int svgdoc_paint_filled(const svgdoc_paint *p, const char *tag) {
  return strcmp(tag, "line") != 0 && shows(p, p->fill, p->fill_clear);
}
