"""The speed of a rational quadratic (conic) and its complex singularities,
shared by tools/ref_conic.py (half_length) and tools/ref_conic_thin.py.

For the conic (p0, p1, p2; w) with legs a = p1 - p0, c = p2 - p1 the speed
is |P(t)| / D(t)^2 with
  P(t)/2 = w (1-t)^2 a + w t^2 c + t (1-t) (a + c) = A t^2 + B t + C,
  D(t)   = 1 + 2 (w - 1) t (1 - t);
it is analytic but for the complex roots of |P|^2 (a quartic) and of D.
Quadrature on panels clustered geometrically about those roots is smooth
on each panel's own scale however close to [0, 1] they come.  The legs
are formed exactly from the doubles, whatever their exponents.

Not a script: the two references import it (from tools/, as they import
each other).
"""
import mpmath as mp


class ConicSpeed:
    """A, B, C and w at `dps` digits, and the singularities of the speed
    (roots found at 3 dps digits)."""

    def __init__(self, p, w, dps):
        self.dps = dps
        # 2300 bits hold the difference of any two doubles exactly
        with mp.workprec(2300):
            P = [[mp.mpf(x) for x in q] for q in p]
            a = [P[1][k] - P[0][k] for k in range(2)]
            c = [P[2][k] - P[1][k] for k in range(2)]
        with mp.workdps(dps):
            a = [+x for x in a]
            c = [+x for x in c]
            w = mp.mpf(w)
            self.w = w
            self.C = [w * a[k] for k in range(2)]
            self.B = [a[k] + c[k] - 2 * w * a[k] for k in range(2)]
            self.A = [(w - 1) * (a[k] + c[k]) for k in range(2)]
            A, B, C = self.A, self.B, self.C
            # |P(t)/2|^2, highest power first (polyroots' order)
            quart = [sum(A[k] ** 2 for k in range(2)),
                     sum(2 * A[k] * B[k] for k in range(2)),
                     sum(B[k] ** 2 + 2 * A[k] * C[k] for k in range(2)),
                     sum(2 * B[k] * C[k] for k in range(2)),
                     sum(C[k] ** 2 for k in range(2))]
            sing = []
            with mp.workdps(3 * dps):
                while quart and quart[0] == 0:
                    quart = quart[1:]
                if len(quart) > 1:
                    sing += mp.polyroots(quart, maxsteps=4000, extraprec=4000)
                if w != 1:
                    sing += mp.polyroots([-2 * (w - 1), 2 * (w - 1), 1],
                                         maxsteps=4000, extraprec=4000)
            self.sing = sing

    def speed(self, t):
        """|P(t)| / D(t)^2 at the caller's precision."""
        w, A, B, C = self.w, self.A, self.B, self.C
        D = 1 + 2 * (w - 1) * t * (1 - t)
        return 2 * mp.hypot(A[0] * t * t + B[0] * t + C[0],
                            A[1] * t * t + B[1] * t + C[1]) / (D * D)

    def panels(self, t0, t1, ratio):
        """Sorted break points of [t0, t1] (mpf, t0 < t1): about each
        singularity's real part, steps from its distance to the real line
        growing by `ratio`; at the caller's precision."""
        pts = {t0, t1}
        for z in self.sing:
            re = min(max(mp.re(z), t0), t1)
            step = abs(z - re)
            pts.add(re)
            if step == 0:
                step = mp.mpf(2) ** -4000
            while step < t1 - t0:           # ends: step grows by ratio > 1
                for x in (re - step, re + step):
                    if t0 < x < t1:
                        pts.add(x)
                step *= ratio
        return sorted(pts)
