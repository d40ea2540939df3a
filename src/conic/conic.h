/*
** conic.h -- what conic.c shares with conic_length.c.  Not part of the
** public API.
*/
#ifndef ARCLEN_CONIC_H
#define ARCLEN_CONIC_H

/* Legs p1 - p0, p2 - p1 and chord p2 - p0 (v = ax ay cx cy kx ky), each one
** rounding; returns 1 when they had to be halved to stay finite, else 0. */
int arclen_conic_legs(const double p[6], double v[6]);

#endif
