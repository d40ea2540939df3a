/*
** measure.c -- a drawn element's length in C, as the stream reads it: the
** command line's `length` of a drawing of 10^5 circles spent more on
** making each element an arclen.path and measuring it from Lua than on
** the measuring itself (doc/benchmarks.md, "Circles").  The sum is the
** one arclen.path forms (lua/arclen/path.lua, cumulative): each segment's
** length in order, added from 0, so that e.length and e.path:length()
** are the same double.
*/
#include <math.h>

#include "svgdoc/measure.h"

#define RUN 256                  /* cubics measured per arclen_lengths call */

int svgdoc_measure(const arclen_pathdata *pd, const arclen_method *m,
                   const arclen_opts *o, double *len) {
  double out[RUN], total = 0;
  size_t i = 0, j, k, n = pd->ncubics;
  *len = NAN;
  while (i < n) {                         /* capped: i grows each time */
    const double *rec = pd->cubics + ARCLEN_PD_STRIDE * i;
    int kind = arclen_segment_kind_of_letter(pd->kinds[i]), rc;
    if (kind == ARCLEN_SEG_CUBIC) {
      long failed;
      double z = 0;
      for (j = i + 1; j < n && j - i < RUN && pd->kinds[j] == ARCLEN_PD_CUBIC; j++) {}
      /* arclen_lengths takes its cubics as checked (batch.c checks them):
      ** x - x is 0 for a finite x, one test for the run */
      for (k = 0; k < ARCLEN_PD_STRIDE * (j - i); k++) z += rec[k] - rec[k];
      if (z != 0) return ARCLEN_EINVAL;
      rc = arclen_lengths(rec, (long)(j - i), 2, m, o, out, &failed);
      if (rc != ARCLEN_OK) return rc;
      for (k = i; k < j; k++) total += out[k - i];
      i = j;
    } else {
      double L;
      /* checked there (finite numbers, a conic's weight > 0) */
      rc = arclen_segment_length(kind, 2, rec, m, o, &L, NULL);
      if (rc != ARCLEN_OK) return rc;
      total += L;
      i++;
    }
  }
  if (!isfinite(total)) return ARCLEN_EOVERFLOW;
  *len = total;
  return ARCLEN_OK;
}
