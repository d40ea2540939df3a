#!/usr/bin/python3
"""bench/svg/svgelements_peer.py -- svgelements' side of `make bench-svg`:
each document parsed (SVG.parse: transforms, viewBox, use) and every
drawn shape's length() at its default accuracy (error 1e-12, as
svgelements documents it), timed per file (best of BENCH_REPS).
Prints "svgelements<TAB>file<TAB>total<TAB>seconds" per file."""
import os
import sys
import time

import svgelements as se

REPS = int(os.environ.get("BENCH_REPS", "1"))


def measure(path):
    total = 0.0
    for e in se.SVG.parse(path).elements():
        if isinstance(e, se.Shape) and e.values.get("display") != "none":
            total += e.length()
    return total


for f in sys.argv[1:]:
    best, total = float("inf"), None
    for _ in range(REPS):
        t0 = time.process_time()
        try:
            total = measure(f)
        except Exception as ex:  # noqa: BLE001 -- a peer that fails is reported
            print("svgelements\t%s\tfailed: %s\t0" % (f, ex))
            break
        best = min(best, time.process_time() - t0)
    else:
        print("svgelements\t%s\t%.17g\t%.6f" % (f, total, best))
    sys.stdout.flush()
