#!/usr/bin/python3
"""Reference lengths of the cubics where fuzz/fuzz_length found "gravesen"
or "gravesen-richardson" outside their tolerance (pre-asymptotic pieces
accepted: a turn at 1e-3 of a piece's width, a stop beside a collinear
reversal, coordinates from 1e-323 to 1e236), for spec/gravesen_spec.lua.

Columns: id dim rtol t0 t1 c L, c the 8 or 12 coordinates (repr, space
separated), rtol the tolerance the fuzzer ran (gravesen's error must stay
below it), L = s(t1) - s(t0) by both integrators of tools/ref_lengths.py,
which must agree to 1e-30 relative.

Run: nice /usr/bin/python3 tools/ref_gravesen_fuzz.py   (seconds)
"""
import os
import sys

from mpmath import mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_lengths as R  # noqa: E402

# (rtol, t0, t1, coordinates) as printed by the harness (t0, t1 rounded by
# %g: the spec uses these values as they are)
CASES = [
    (2.38419e-07, 0, 1, [4.3137195287272334, 4.3137254891917109, 4.3137254891917109, 4.3137254891917109, 4.3137254891917109, 4.3137254891917109, 4.3137254891917109, 9.475517335709069e-316]),
    (1e-09, 0, 1, [0, 3.9525251667299724e-323, 113, 5.3963479237403982e+228, 1.015625, -39.984375, -42.984375, -83.984375, -51.984375, 0, 80, 9.6658534546537069e+236]),
    (1.86265e-09, 0.151354, 0.775204, [28.461159012746059, 3.4612394118600349e+54, 7.4229183555923097e+54, 7.4229183555923097e+54, 4.5974866225976666e+54, 8.8118493599788609e+55, 8.8118493599788696e+55, 28.461159012746059, 28.461159012746059, 28.461159012746059, 5.7170964583623418e+54, 5.7170964583623363e+54]),
    (4.76837e-07, 0, 1, [0, -2.4099198651028841e-181, -1.0107936529880487e-174, 0, 0, 0, 0, 9.8806714469218249e-180, 0, 0, 0, 0]),
    (1e-09, 0, 1, [1.7572071906123623e+159, 1.7572071906123639e+159, 1.7572071906123639e+159, 113, 0.0009765625, -84.33203125, -4.7174530310269267e+167, 4.4837353166733009e-120]),
    (1e-09, 0.248768, 0.473625, [56, -1, -1, -1, -18, -35, -52, 15]),
    (1e-09, 0, 1, [81, 1.2366520073655227e+173, 0.37109375, 81, 9.2137754512244662e+164, 0, 0, 0]),
    (2.38419e-07, 0, 1, [-4.3454739820398612e+147, 0, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, -3.5463063531589672e+147, 0, 2.5492916022947289e+153]),
    (1e-09, 0, 1, [-3, -3.1130179493515054e+20, 3, 1.1236417176167604e-305, 8796093022208, 1.2049599325514421e-181, 111, -4.9406564584124654e-324]),
    (1e-09, 0, 1, [7.1763243610203283e+128, -1.065377373964683e-176, -1.1640876916392971e-176, -7.4418325434377062e-178, -8.4829179251621521e-178, -3.0034929701816087e+121, -3.0034929701816087e+121, 0]),
    (1e-09, 0, 1, [9.5503209915549101e-181, -4.4794894843556084e+102, -4.4794894843556044e+102, 2.7473086462172879e-179, 2.7818571067834113e-179, 2.5304158583580283e-179, 1.6824126995381736e+94, 1.6824126995381736e+94, 0, 0, 0, 0]),
    # from the spec run of the three-level rule: R3 1e-12 off at tol 1e-12
    # on a piece whose R1 was 7.6e-8 off (ratio |R2 - R1|/|R3 - R2| 1.5e5)
    (1e-12, 0, 1, [1.5612340931373, 5.9275099467286, 6.7985202050851, 9.0105783027876, 4.8972544026614, 3.3079069221825, 7.9872321040414, 6.351274467378]),
]


def main():
    out = ["\t".join(["id", "dim", "rtol", "t0", "t1", "c", "L"])]
    for i, (rtol, t0, t1, c) in enumerate(CASES):
        dim = len(c) // 4
        L = R.range_length([float(x) for x in c], dim, t0, t1)
        out.append("\t".join(["fuzz-%d" % (i + 1), str(dim), repr(rtol),
                              repr(float(t0)), repr(float(t1)),
                              " ".join(repr(float(x)) for x in c),
                              mp.nstr(L, 30)]))
    path = os.path.join(os.path.dirname(__file__), "..", "spec", "data",
                        "gravesen_fuzz.tsv")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
