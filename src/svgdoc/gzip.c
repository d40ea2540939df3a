/*
** gzip.c -- gzip input inflated in bounded pieces (gzip.h).  zlib's
** inflate with a gzip wrapper (windowBits 16 + 15) does the work; this
** file holds one chunk of input and hands out what it inflates to, at
** most the caller's room at a time.
*/
#include "svgdoc/gzip.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(ARCLEN_HAVE_ZLIB)
#include <zlib.h>

#define GZIP_WINDOW (16 + MAX_WBITS)     /* zlib.h: a gzip header, not zlib's */
#define MAX_STEP 0x40000000u             /* bytes per inflate call (uInt) */
#define MAX_CALLS 64                     /* inflate calls per read */

struct svgdoc_gunzip {
  z_stream z;
  int live;                  /* inflateInit2 succeeded */
  int ended;                 /* the last member's trailer was read */
  int more;                  /* the last inflate filled its room: it may
                             ** hold output for input it has taken already */
  int failed;
  char *in;
  size_t in_len, in_at, in_room;
  size_t consumed;           /* compressed bytes used (for messages) */
  char msg[256];
};

int svgdoc_gunzip_available(void) { return 1; }

svgdoc_gunzip *svgdoc_gunzip_new(void) {
  svgdoc_gunzip *g = calloc(1, sizeof *g);
  if (g == NULL) return NULL;
  if (inflateInit2(&g->z, GZIP_WINDOW) != Z_OK) {
    free(g);
    return NULL;
  }
  g->live = 1;
  return g;
}

void svgdoc_gunzip_free(svgdoc_gunzip *g) {
  if (g == NULL) return;
  if (g->live) inflateEnd(&g->z);
  free(g->in);
  free(g);
}

int svgdoc_gunzip_feed(svgdoc_gunzip *g, const char *s, size_t n) {
  if (g->in_room < n) {
    char *p = realloc(g->in, n);
    if (p == NULL) return -1;
    g->in = p, g->in_room = n;
  }
  if (n) memcpy(g->in, s, n);
  g->in_len = n, g->in_at = 0;
  return 0;
}

static long fail(svgdoc_gunzip *g, const char *what, const char *why) {
  g->failed = 1;
  /* the place as a byte offset of the compressed file, from 0 */
  snprintf(g->msg, sizeof g->msg, "%s (byte %lu of the compressed data%s%.80s)",
           what, (unsigned long)g->consumed, why ? ": " : "", why ? why : "");
  return -1;
}

long svgdoc_gunzip_read(svgdoc_gunzip *g, char *out, size_t room) {
  size_t made = 0;
  int calls;
  if (g->failed) return -1;
  if (room > MAX_STEP) room = MAX_STEP;
  for (calls = 0; calls < MAX_CALLS && made < room &&
                  (g->in_at < g->in_len || g->more);
       calls++) {
    size_t avail, used;
    int rc;
    if (g->ended) {
      /* RFC 1952 section 2.2: another member may follow; zeros pad */
      g->more = 0;
      while (g->in_at < g->in_len && g->in[g->in_at] == 0)
        g->in_at++, g->consumed++;
      if (g->in_at == g->in_len) break;
      if ((unsigned char)g->in[g->in_at] != 0x1f)
        return fail(g, "data after the end of the gzip stream", NULL);
      if (inflateReset(&g->z) != Z_OK)
        return fail(g, "corrupt gzip data", g->z.msg);
      g->ended = 0;
    }
    avail = g->in_len - g->in_at;
    if (avail > MAX_STEP) avail = MAX_STEP;
    g->z.next_in = (unsigned char *)g->in + g->in_at;
    g->z.avail_in = (uInt)avail;
    g->z.next_out = (unsigned char *)out + made;
    g->z.avail_out = (uInt)(room - made);
    rc = inflate(&g->z, Z_NO_FLUSH);
    used = avail - g->z.avail_in;
    g->in_at += used, g->consumed += used;
    /* a full room: inflate may hold more output for the bits it took */
    g->more = g->z.avail_out == 0 && rc == Z_OK;
    made = room - g->z.avail_out;
    if (rc == Z_STREAM_END) {
      g->ended = 1;
    } else if (rc == Z_MEM_ERROR) {
      return fail(g, "not enough memory to inflate", NULL);
    } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
      return fail(g, "corrupt gzip data", g->z.msg);
    }
  }
  /* 0 must mean that the input is used up (the caller gives more) */
  if (made == 0 && g->in_at < g->in_len)
    return fail(g, "corrupt gzip data", "inflate makes no progress");
  return (long)made;
}

int svgdoc_gunzip_finish(svgdoc_gunzip *g) {
  if (g->failed) return -1;
  if (!g->ended) {
    fail(g, "truncated gzip data: the file ends inside the compressed stream",
         NULL);
    return -1;
  }
  return 0;
}

const char *svgdoc_gunzip_error(const svgdoc_gunzip *g) { return g->msg; }

#else  /* without zlib: nothing inflates */

int svgdoc_gunzip_available(void) { return 0; }
svgdoc_gunzip *svgdoc_gunzip_new(void) { return NULL; }
void svgdoc_gunzip_free(svgdoc_gunzip *g) { (void)g; }
int svgdoc_gunzip_feed(svgdoc_gunzip *g, const char *s, size_t n) {
  (void)g, (void)s, (void)n;
  return -1;
}
long svgdoc_gunzip_read(svgdoc_gunzip *g, char *out, size_t room) {
  (void)g, (void)out, (void)room;
  return -1;
}
int svgdoc_gunzip_finish(svgdoc_gunzip *g) {
  (void)g;
  return -1;
}
const char *svgdoc_gunzip_error(const svgdoc_gunzip *g) {
  (void)g;
  return "built without zlib";
}

#endif
