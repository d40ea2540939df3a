/*
** options.c -- what every method shares: the default options, an empty
** report and the error codes' messages.  Below every method, so that the
** methods' registry (methods/methods.c) is the only file that knows them
** all and no method depends on another through it.
*/
#include <string.h>

#include "arclen.h"

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
