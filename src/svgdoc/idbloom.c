/*
** idbloom.c -- the ids of a whole document, from svgdoc_scan, as a Bloom
** filter of fixed size: "no element has this id" is then known before
** the reading reaches the end, so that a <use> of a missing id (SVG 2
** section 5.6: not rendered) is passed over where it stands, instead of
** holding everything after it until the end.  A false positive (about 2%
** at 10^5 ids) only makes such a use wait, as without the scan.
** The paint servers' ids go into the same filter under a salt, so that
** a fill or stroke of url(#id) that names no paint server is known too.
*/
#include <stdlib.h>

#include "svgdoc/internal.h"

#define BLOOM_BITS (1u << 20)            /* 128 KiB */
#define BLOOM_K 3                        /* probes per id */

/* Two independent hashes of s[0 .. n-1] (djb2 and FNV-1a), combined as
** h1 + k h2 for the k-th probe (Kirsch and Mitzenmacher 2006). */
static void hashes(const char *s, size_t n, int salt, unsigned long *h1,
                   unsigned long *h2) {
  unsigned long a = 5381 + (unsigned long)salt, b = 2166136261u ^ (unsigned long)salt;
  size_t k;
  for (k = 0; k < n; k++) {
    unsigned char c = (unsigned char)s[k];
    a = a * 33 + c;
    b = (b ^ c) * 16777619u;
  }
  *h1 = a, *h2 = b | 1;
}

int svgdoc_bloom_add(svgdoc *D, const char *s, size_t n, int server) {
  unsigned long h1, h2;
  int k;
  if (D->id_bloom == NULL) {
    D->id_bloom = calloc(BLOOM_BITS / 8, 1);
    if (D->id_bloom == NULL) return -1;
  }
  hashes(s, n, server ? 0x5a : 0, &h1, &h2);
  for (k = 0; k < BLOOM_K; k++) {
    unsigned long bit = (h1 + (unsigned long)k * h2) & (BLOOM_BITS - 1);
    D->id_bloom[bit >> 3] |= (unsigned char)(1u << (bit & 7));
  }
  return 0;
}

int svgdoc_bloom_absent(const svgdoc *D, const char *s, size_t n, int server) {
  unsigned long h1, h2;
  int k;
  if (!D->ids_known) return 0;
  if (D->id_bloom == NULL) return 1;       /* the document has no id */
  hashes(s, n, server ? 0x5a : 0, &h1, &h2);
  for (k = 0; k < BLOOM_K; k++) {
    unsigned long bit = (h1 + (unsigned long)k * h2) & (BLOOM_BITS - 1);
    if (!(D->id_bloom[bit >> 3] & (1u << (bit & 7)))) return 1;
  }
  return 0;
}
