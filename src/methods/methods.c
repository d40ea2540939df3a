/*
** methods.c -- the table of length and time methods by name, so that the
** binding and C users can pick one at run time ("gauss", "elliptic", ...).
*/
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
