/*
** cond.h -- conditional processing (SVG 2 section 5.8): does an element's
** requiredExtensions / systemLanguage pass (cond.c)?
*/
#ifndef ARCLEN_SVGDOC_COND_H
#define ARCLEN_SVGDOC_COND_H

/* The language the reader matches systemLanguage against when the
** options give none: fixed, not the host's locale, so that a document
** measures the same everywhere (doc/svg.md). */
#define SVGDOC_DEFAULT_LANG "en"
#define SVGDOC_MAX_LANG 256            /* bytes of the language option */

/* Do the conditional processing attributes among expat's atts pass, for
** the user languages lang (a comma-separated list of BCP 47 tags)? */
int svgdoc_cond_pass(const char **atts, const char *lang);

/* Is lang a usable language option: 1 to SVGDOC_MAX_LANG - 1 bytes of
** tags (letters, digits, '-') separated by commas and spaces? */
int svgdoc_cond_lang_ok(const char *lang);

#endif
