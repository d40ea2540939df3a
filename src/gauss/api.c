/*
** api.c -- the plain API of arclen.h for the inverse: one time, NaN on
** bad input.  (The length's, arclen_length and its forms, is in length.c
** beside the fast path it takes.)
*/
#include <math.h>

#include "arclen.h"
#include "gauss/integrator.h"

static double time_of(const double *c, int dim, double s, double rtol) {
  arclen_opts o;
  double t;
  arclen_opts_init(&o);
  o.rtol = rtol;
  arclen_time_gauss(c, dim, s, &o, &t, NULL);
  return t;
}

double arclen_time(const double c[8], double s, double rtol) {
  return time_of(c, 2, s, rtol);
}
double arclen_time3(const double c[12], double s, double rtol) {
  return time_of(c, 3, s, rtol);
}
