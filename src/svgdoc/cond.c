/*
** cond.c -- conditional processing (SVG 2 section 5.8.2 and 5.8.5).  An
** element whose test attributes fail is not rendered, in a <switch> or
** not; a <switch> renders its first child element that passes (reader.c).
**   requiredExtensions: no extension is supported, so any value fails,
**     the empty one too (SVG 2: "a null string or empty string value ...
**     evaluates to false").
**   requiredFeatures: SVG 2 removed it; like browsers, it is ignored
**     (passes).  (librsvg still fails feature strings it does not know.)
**   systemLanguage: a comma-separated list of BCP 47 tags; passes when a
**     user language equals one of them, or is a prefix of one followed by
**     '-' ("en" passes "en-US"; "en-US" does not pass "en"), compared
**     without case; an empty list fails.
*/
#include <string.h>

#include "svgdoc/cond.h"
#include "svgdoc/internal.h"

static unsigned char lower(unsigned char c) {
  return c >= 'A' && c <= 'Z' ? (unsigned char)(c - 'A' + 'a') : c;
}

/* The next item of the comma-separated list at *s, trimmed, into *item
** and *n; 0 at the end. */
static int next_item(const char **s, const char **item, size_t *n) {
  const char *p = *s, *e;
  if (*p == '\0') return 0;
  e = strchr(p, ',');
  if (e == NULL) e = p + strlen(p);
  *s = *e ? e + 1 : e;
  while (p < e && svgdoc_space((unsigned char)*p)) p++;
  while (e > p && svgdoc_space((unsigned char)e[-1])) e--;
  *item = p, *n = (size_t)(e - p);
  return 1;
}

/* Does the user's tag u[0 .. un-1] match the document's d[0 .. dn-1]? */
static int tag_matches(const char *u, size_t un, const char *d, size_t dn) {
  size_t k;
  /* "en-" is no tag: a prefix needs a subtag after its '-' */
  if (un == 0 || un > dn || (un < dn && (d[un] != '-' || un + 1 == dn)))
    return 0;
  for (k = 0; k < un; k++)
    if (lower((unsigned char)u[k]) != lower((unsigned char)d[k])) return 0;
  return 1;
}

static int language_passes(const char *value, const char *lang) {
  const char *d, *u, *ds = value;
  size_t dn, un;
  while (next_item(&ds, &d, &dn)) {         /* each ends at the string's end */
    const char *us = lang;
    while (next_item(&us, &u, &un))
      if (tag_matches(u, un, d, dn)) return 1;
  }
  return 0;
}

int svgdoc_cond_pass(const char **atts, const char *lang) {
  const char *v;
  if (svgdoc_attr(atts, "requiredExtensions") != NULL) return 0;
  v = svgdoc_attr(atts, "systemLanguage");
  return v == NULL || language_passes(v, lang);
}

int svgdoc_cond_lang_ok(const char *lang) {
  size_t n = strlen(lang), k, letters = 0;
  if (n == 0 || n >= SVGDOC_MAX_LANG) return 0;
  for (k = 0; k < n; k++) {
    unsigned char c = (unsigned char)lang[k];
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
        (c >= '0' && c <= '9'))
      letters++;
    else if (c != '-' && c != ',' && c != ' ')
      return 0;
  }
  return letters > 0;
}
