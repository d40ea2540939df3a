/*
** quad_bound.c -- the quadratic time's table answers with their bounds
** (src/segment/quad_time.c, direct_bound), for tools/check_quad_bound.py,
** which measures each answer's true miss with mpmath and its ratio to the
** bound (at most 1 where the bound holds).  Quadratics of five families
** from the bench's random cubics' points in [0, 10]^2: as they are, nearly
** collinear legs, hairpins (P2 near P0), the middle point near the chord's
** middle (nearly straight), and far from the origin (times 1e5, plus 3e7);
** 19 distances j L/20 each, at the tol given.  Prints the points, the
** distance, t and the bound (user units) of every answer the table gave
** without a length.  Run: sh tools/check-quad-bound.sh (CI runs it).
**
**   quad_bound N RTOL
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "arclen.h"
#include "bench_util.h"
#include "segment/segment.h"

int main(int argc, char **argv) {
  int n = argc > 1 ? atoi(argv[1]) : 1000, i, j;
  double rtol = argc > 2 ? atof(argv[2]) : 1e-12, *pts;
  if (n < 1 || !(rtol > 0)) {
    fprintf(stderr, "usage: quad_bound N RTOL\n");
    return 2;
  }
  pts = malloc(sizeof(double) * 8 * (size_t)n);
  if (pts == NULL) return 1;
  bench_random_curves(pts, n, 20261205);
  for (i = 0; i < n; i++) {
    double *p = pts + 8 * i, L, f;
    arclen_opts o;
    arclen_quad_form F;
    /* P0 P1 P2 of the cubic, then the family's change */
    switch (i % 5) {
    case 1:                              /* P1 near the line P0 P2 */
      f = p[6] / 10;
      for (j = 0; j < 2; j++)
        p[2 + j] = p[j] + (p[4 + j] - p[j]) * f + 1e-3 * (p[7 - j] / 10 - 0.5);
      break;
    case 2:                              /* P2 near P0: a hairpin */
      for (j = 0; j < 2; j++) p[4 + j] = p[j] + 1e-2 * (p[6 + j] / 10 - 0.5);
      break;
    case 3:                              /* P1 near the chord's middle */
      for (j = 0; j < 2; j++)
        p[2 + j] = (p[j] + p[4 + j]) / 2 + 0.3 * (p[6 + j] / 10 - 0.5);
      break;
    case 4:                              /* far from the origin */
      for (j = 0; j < 6; j++) p[j] = p[j] * 1e5 + 3e7;
      break;
    }
    arclen_opts_init(&o);
    if (arclen_segment_length(ARCLEN_SEG_QUAD, 2, p, NULL, &o, &L, NULL))
      continue;
    arclen_quad_setup(p, 2, &F);
    for (j = 1; j < 20; j++) {
      double total = NAN, from[3] = {0, 0, 0}, t, s = L * j / 20;
      long evals;
      if (arclen_quad_time(&F, &total, s, rtol, from, &t, &evals) == ARCLEN_OK
          && evals == 0 && from[2] < HUGE_VAL)
        printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p[0],
               p[1], p[2], p[3], p[4], p[5], s, t, from[2]);
    }
  }
  free(pts);
  return 0;
}
