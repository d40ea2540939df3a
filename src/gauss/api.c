/*
** api.c -- the plain API of arclen.h over the default method: one length
** or one time, NaN on bad input.
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

double arclen_length(const double c[8], double rtol) {
  return arclen_integ_length_of(c, 2, 0, 1, rtol);
}
double arclen_length_range(const double c[8], double t0, double t1,
                           double rtol) {
  return arclen_integ_length_of(c, 2, t0, t1, rtol);
}
double arclen_time(const double c[8], double s, double rtol) {
  return time_of(c, 2, s, rtol);
}
double arclen_length3(const double c[12], double rtol) {
  return arclen_integ_length_of(c, 3, 0, 1, rtol);
}
double arclen_length3_range(const double c[12], double t0, double t1,
                            double rtol) {
  return arclen_integ_length_of(c, 3, t0, t1, rtol);
}
double arclen_time3(const double c[12], double s, double rtol) {
  return time_of(c, 3, s, rtol);
}
