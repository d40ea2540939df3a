/*
** measure.h -- a drawn element's length in C, as the stream reads it
** (measure.c).  Not part of the public API.
*/
#ifndef ARCLEN_SVGDOC_MEASURE_H
#define ARCLEN_SVGDOC_MEASURE_H

#include "arclen.h"
#include "svg/pathdata.h"

/* The length of pd's segments (2D records) by method m with options o,
** summed in their order from 0: for the default method (gauss), the very
** double arclen.path's p:length() gives for them (one arclen.lengths call,
** its kinds; runs of cubics through arclen_lengths, the other kinds
** through arclen_segment_length; a path of another method makes its
** conics cubics first, so arclen.svg leaves those to the path).
** Returns ARCLEN_OK, or an error code (a coordinate that is not finite,
** a length that fails or overflows; *len is then NaN) for the caller to
** measure the element its own way and report it. */
int svgdoc_measure(const arclen_pathdata *pd, const arclen_method *m,
                   const arclen_opts *o, double *len);

#endif
