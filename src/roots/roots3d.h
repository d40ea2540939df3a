/*
** roots3d.h -- the branch points of a space cubic's speed (roots3d.c).
** Not part of the public API.
*/
#ifndef ARCLEN_ROOTS3D_H
#define ARCLEN_ROOTS3D_H

/* The roots s1, s2 of |a2 t^2 + a1 t + a0|^2 (3D, a2 != 0) in the upper
** half plane, with |a2|^2 |t - s1|^2 |t - s2|^2 = that quartic; close
** roots are set in a frame about their cluster.  Used by the elliptic
** method (elliptic/elliptic3d.c) and the default method's branch points
** (gauss/branch.c). */
int arclen_roots3d(const double a2[3], const double a1[3],
                   const double a0[3], double re[2], double im[2]);

#endif
