#!/usr/bin/python3
"""bench/svg/svgelements_peer.py -- svgelements' side of `make bench-svg`:
each document parsed (SVG.parse: transforms, viewBox, use) and every
drawn shape's length() at its default accuracy (error 1e-12, as
svgelements documents it), timed per file (best of BENCH_REPS).
With scipy installed, svgelements integrates cubics and arcs by QUADPACK
(scipy.integrate.quad, epsabs 1e-12); without it, by its own recursive
subdivision: SVGELEMENTS_NO_SCIPY=1 hides scipy to measure that case.
One document is measured once before the timing (imports warm up).
Prints "NAME<TAB>file<TAB>total<TAB>seconds" per file."""
import os
import sys
import time

NAME = "svgelements"
if os.environ.get("SVGELEMENTS_NO_SCIPY"):
    sys.modules["scipy"] = None          # import scipy now raises ImportError
    NAME = "svgelements (no scipy)"
import svgelements as se  # noqa: E402

REPS = int(os.environ.get("BENCH_REPS", "1"))


def measure(path):
    total = 0.0
    for e in se.SVG.parse(path).elements():
        if isinstance(e, se.Shape) and e.values.get("display") != "none":
            total += e.length()
    return total


if sys.argv[1:] and "scipy" not in NAME:
    try:
        measure(sys.argv[1])
    except Exception:  # noqa: BLE001
        pass
for f in sys.argv[1:]:
    best, total = float("inf"), None
    for _ in range(REPS):
        t0 = time.process_time()
        try:
            total = measure(f)
        except Exception as ex:  # noqa: BLE001 -- a peer that fails is reported
            print("%s\t%s\tfailed: %s\t0" % (NAME, f, ex))
            break
        best = min(best, time.process_time() - t0)
    else:
        print("%s\t%s\t%.17g\t%.6f" % (NAME, f, total, best))
    sys.stdout.flush()
