/*
** gzip.h -- gzip-compressed documents (Inkscape's .svgz, RFC 1952)
** inflated as a stream over zlib: the output comes in pieces of the
** caller's size, so that a small file that inflates to gigabytes (a
** "gzip bomb") costs time, never memory.  zlib is optional: without it
** (ARCLEN_HAVE_ZLIB undefined) svgdoc_gunzip_new returns NULL.
*/
#ifndef ARCLEN_SVGDOC_GZIP_H
#define ARCLEN_SVGDOC_GZIP_H

#include <stddef.h>

typedef struct svgdoc_gunzip svgdoc_gunzip;

/* Was the reader built with zlib? */
int svgdoc_gunzip_available(void);

/* A new inflater (NULL without memory or without zlib). */
svgdoc_gunzip *svgdoc_gunzip_new(void);
void svgdoc_gunzip_free(svgdoc_gunzip *g);

/* The next n compressed bytes, copied (the previous ones must have been
** used up: svgdoc_gunzip_read returned 0).  0, or -1 without memory. */
int svgdoc_gunzip_feed(svgdoc_gunzip *g, const char *s, size_t n);

/* Up to room inflated bytes into out: how many (0 when the input given is
** used up), or -1 with the reason in svgdoc_gunzip_error.  Members one
** after another (RFC 1952 section 2.2) inflate as one stream; zero bytes
** after the last are padding, anything else an error. */
long svgdoc_gunzip_read(svgdoc_gunzip *g, char *out, size_t room);

/* At the end of the input: 0 when the last member was complete, else -1
** (a truncated file). */
int svgdoc_gunzip_finish(svgdoc_gunzip *g);

const char *svgdoc_gunzip_error(const svgdoc_gunzip *g);

#endif
