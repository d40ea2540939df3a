/*
** methods.c -- the table of length and time methods by name, so that the
** binding and C users can pick one at run time ("gauss", "elliptic", ...).
*/
#include <math.h>
#include <string.h>

#include "arclen.h"

static const arclen_method methods[] = {
  /* name, length, time */
  {"gauss", arclen_length_gauss, arclen_time_gauss},
  {"gravesen", arclen_length_gravesen, NULL},
  {"gravesen-richardson", arclen_length_gravesen_richardson, NULL},
  {"metapost", arclen_length_metapost, arclen_time_metapost},
  {"polyline", arclen_length_polyline, NULL},
  {"trapezoid", arclen_length_trapezoid, NULL},
  {"trapezoid-factored", arclen_length_trapezoid_factored, NULL},
  {"elliptic", arclen_length_elliptic, NULL},
  /* new methods: one row each, above this line */
  {NULL, NULL, NULL}
};

const arclen_method *arclen_find_method(const char *name) {
  const arclen_method *m;
  for (m = methods; m->name != NULL; m++)
    if (strcmp(m->name, name) == 0) return m;
  return NULL;
}

const arclen_method *arclen_method_list(void) {
  return methods;
}

void arclen_opts_init(arclen_opts *o) {
  o->rtol = 1e-12;
  o->t0 = 0;
  o->t1 = 1;
  o->steps = 0;
}

void arclen_info_init(arclen_info *info) {
  memset(info, 0, sizeof *info);
}

const char *arclen_strerror(int code) {
  switch (code) {
    case ARCLEN_OK: return "no error";
    case ARCLEN_EINVAL: return "coordinates and arguments must be finite numbers";
    case ARCLEN_ETOL: return "tolerance must be in [1e-15, 0.1]";
    case ARCLEN_ERANGE: return "parameter must be in [0, 1]";
    case ARCLEN_EDIM: return "method does not support this dimension";
    case ARCLEN_EDOMAIN: return "argument outside the function's domain";
    case ARCLEN_EOVERFLOW: return "arithmetic overflow";
    case ARCLEN_ENOCONV: return "iteration limit reached before the tolerance";
    default: return "unknown error";
  }
}
