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

/* arclen_quartic_factor without its double-double refinement of the
** factors (roots.c): for callers that polish the roots themselves. */
int arclen_quartic_factor_plain(double a4, double a3, double a2, double a1,
                                double a0, double q[4]);
/* arclen_quartic without its double-double step (roots.c). */
int arclen_quartic_plain(double a4, double a3, double a2, double a1,
                         double a0, double re[4], double im[4]);

#endif
