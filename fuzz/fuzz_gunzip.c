/*
** fuzz_gunzip.c -- the gzip inflater of the document reader
** (src/svgdoc/gzip.c over zlib) on fuzzed input.  The first byte picks the
** output room per read (1 byte to 64 KiB), the second where the input is
** cut in two; the rest is the compressed data.  It is inflated twice: fed
** whole and read in pieces of that room, and fed in two pieces and read
** 64 KiB at a time.  Invariants: a read never gives more than its room,
** returns 0 only when the input fed is used up, and an error has a
** message; both inflations agree: the same verdict (complete, truncated
** or failed) and, when neither failed, the same bytes (count and FNV-1a
** hash).  At most 16 MiB is inflated per run (a bomb costs time only).
*/
#include <string.h>

#include "svgdoc/gzip.h"
#include "fuzz_input.h"

#define CAP (16u << 20)

typedef struct outcome {
  int verdict;                 /* 0 complete, 1 truncated, 2 failed, 3 capped */
  size_t count;
  unsigned long long h;
} outcome;

static char out[65536];

/* Inflate s[0 .. n-1] fed in pieces cut at the given places. */
static outcome inflate_all(const char *s, size_t n, size_t cut, size_t room) {
  outcome o = {0, 0, 14695981039346656037ULL};
  svgdoc_gunzip *g = svgdoc_gunzip_new();
  size_t starts[3] = {0, cut, n}, k;
  int piece;
  if (g == NULL) fz_fail("gunzip", NULL, 2, "no memory for an inflater", 0, 0);
  for (piece = 0; piece < 2 && o.verdict == 0; piece++) {
    if (svgdoc_gunzip_feed(g, s + starts[piece], starts[piece + 1] - starts[piece]) != 0)
      fz_fail("gunzip", NULL, 2, "no memory to feed", 0, 0);
    for (;;) {
      long m = svgdoc_gunzip_read(g, out, room);
      if (m < 0) {
        if (svgdoc_gunzip_error(g)[0] == '\0')
          fz_fail("gunzip", NULL, 2, "failed without a message", 0, 0);
        o.verdict = 2;
        break;
      }
      if ((size_t)m > room) fz_fail("gunzip", NULL, 2, "%g bytes for a room of %g", (double)m, (double)room);
      if (m == 0) break;
      for (k = 0; k < (size_t)m; k++) o.h = (o.h ^ (unsigned char)out[k]) * 1099511628211ULL;
      o.count += (size_t)m;
      if (o.count > CAP) { o.verdict = 3; break; }
    }
  }
  if (o.verdict == 0 && svgdoc_gunzip_finish(g) != 0) o.verdict = 1;
  svgdoc_gunzip_free(g);
  return o;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const size_t ROOMS[8] = {1, 2, 7, 64, 1000, 4096, 32768, 65536};
  const char *s = (const char *)data + 2;
  size_t n, cut;
  outcome a, b;
  if (size < 2) return 0;
  if (!svgdoc_gunzip_available()) fz_fail("gunzip", NULL, 2, "built without zlib", 0, 0);
  n = size - 2;
  cut = n ? data[1] * n / 256 : 0;
  a = inflate_all(s, n, n, ROOMS[data[0] & 7]);
  b = inflate_all(s, n, cut, 65536);
  if (a.verdict == 3 || b.verdict == 3) return 0;      /* capped: not compared */
  if (a.verdict != b.verdict)
    fz_fail("gunzip", NULL, 2, "verdicts %g and %g", a.verdict, b.verdict);
  if (a.verdict != 2 && (a.count != b.count || a.h != b.h))
    fz_fail("gunzip", NULL, 2, "%g and %g bytes, or they differ", (double)a.count, (double)b.count);
  return 0;
}
