#!/usr/bin/python3
"""tools/ref_decimal.py -- decimal numbers and their nearest doubles
(spec/data/decimal_hard.tsv, spec/data/decimal_random.tsv), the reference
for src/svg/decimal.c and decimal_exact.c (spec/decimal_spec.lua).

Every value is found twice, independently, and the two must agree:
  - exactly: the text as a fractions.Fraction, rounded to 53 bits (or to
    the subnormal grid 2^-1074) by integer arithmetic here, ties to even
    (IEEE 754 section 4.3.1), beyond the largest double -> inf;
  - by CPython's float(), which is correctly rounded (David Gay's dtoa).

decimal_hard.tsv: the hard cases -- halfway points between neighbouring
doubles written out exactly (normal and subnormal, up to 767 significant
digits), one digit past them (just above and just below, also beyond the
800 digits the parser keeps; integer ones plus and minus 1), long mantissas (hundreds of digits), the
smallest subnormal, the largest subnormal, the smallest normal, the largest
double and the points just past them (overflow -> inf, underflow -> 0),
powers of ten across the range, and the grammar's forms (.5e+2, 5., +1).
decimal_random.tsv: random doubles written with 17 significant digits, the
shortest digits that read back, 20-25 digits, and random digit strings with
random exponents.

Columns: kind, text (an SVG number), sign (+ or -), m, e: the double is
sign * m * 2^e with m an odd integer below 2^53 (m = 0 for zero, e = 0),
or m = inf when the number is beyond the doubles; hex: float.hex of it.

Usage: /usr/bin/python3 tools/ref_decimal.py   (from the repository root)
"""
import math
import random
import sys
from fractions import Fraction

OUT = "spec/data/"
TWO_1024 = 2 ** 1024


def nearest(x, sign):
    """(sign, m, e) of the double nearest to the Fraction x of that sign
    (zero has one too), m odd or 0, m = None beyond the doubles."""
    a = abs(x)
    if a == 0:
        return sign, 0, 0
    n, d = a.numerator, a.denominator
    lead = n.bit_length() - d.bit_length()      # a in [2^(lead-1), 2^(lead+1))
    if Fraction(2) ** lead > a:
        lead -= 1                                # now a in [2^lead, 2^(lead+1))
    low = max(lead - 52, -1074)
    scaled = a / Fraction(2) ** low
    m = scaled.numerator // scaled.denominator
    rest = scaled - m
    if rest > Fraction(1, 2) or (rest == Fraction(1, 2) and m % 2 == 1):
        m += 1
    if m * Fraction(2) ** low >= TWO_1024:
        return sign, None, 0
    if m == 0:
        return sign, 0, 0
    while m % 2 == 0:
        m //= 2
        low += 1
    return sign, m, low


def row(kind, text):
    sign, m, e = nearest(Fraction(text), "-" if text.startswith("-") else "+")
    f = float(text)
    if m is None:
        assert math.isinf(f), (text[:60], f)
        return [kind, text, sign, "inf", "0", "inf" if sign == "+" else "-inf"]
    g = math.ldexp(m, e)
    if sign == "-":
        g = -g
    assert f == g and math.copysign(1, f) == math.copysign(1, g), (kind, text[:80], f, g)
    return [kind, text, sign, str(m), str(e), f.hex()]


def exact_decimal(x):
    """The finite decimal expansion of a dyadic Fraction x > 0, as
    digits 'e' exponent (no rounding)."""
    k = 0
    while x.denominator != 1:
        x *= 10
        k += 1
    return "%de-%d" % (x.numerator, k) if k else str(x.numerator)


def with_point(digits, exp10):
    """digits (no sign) times 10^exp10 written with a decimal point."""
    digits = digits.lstrip("0") or "0"
    n = len(digits) + exp10          # digits before the point
    if n <= 0:
        return "0." + "0" * (-n) + digits
    if n >= len(digits):
        return digits + "0" * (n - len(digits))
    return digits[:n] + "." + digits[n:]


def split_exact(x):
    """(digits, exp10) with x = digits * 10^exp10 exactly, x > 0 dyadic."""
    k = 0
    while x.denominator != 1:
        x *= 10
        k += 1
    return str(x.numerator), -k


def halfway_cases(rng, out):
    """Halfway points between neighbours, and one unit past them."""
    picks = [5e-324, 1e-323, 2.2250738585072009e-308, 2.2250738585072014e-308,
             1.7976931348623157e308, 1.0, 0.1, 9007199254740992.0, 1e23, 8.98846567431158e307]
    for _ in range(60):
        picks.append(math.ldexp(rng.randrange(2 ** 52, 2 ** 53), rng.randrange(-1126, 971)))
    for _ in range(20):
        picks.append(math.ldexp(rng.randrange(1, 2 ** 52), -1074))   # subnormals
    for d in picks:
        up = math.nextafter(d, math.inf)
        lo, hi = Fraction(d), Fraction(TWO_1024) if math.isinf(up) else Fraction(up)
        h = (lo + hi) / 2
        digits, ex = split_exact(h)
        out.append(row("halfway", exact_decimal(h)))
        out.append(row("halfway", with_point(digits, ex)))
        # one unit past the last digit, and one unit short of it
        out.append(row("halfway+", digits + "1e" + str(ex - 1)))
        short = str(int(digits) - 1) + "9"
        out.append(row("halfway-", short + "e" + str(ex - 1)))
        # an integer halfway point (doubles from 2^54 up) plus or minus 1:
        # the difference sits in the lowest bits of a long integer
        if h.denominator == 1:
            out.append(row("halfway+1", str(h.numerator + 1)))
            out.append(row("halfway-1", str(h.numerator - 1)))
            out.append(row("halfway+1", str(h.numerator * 10 + 1) + "e-1"))
        # past it beyond the 800 digits the parser keeps
        pad = 820 - len(digits)
        if pad > 0:
            out.append(row("halfway+far", digits + "0" * pad + "1e" + str(ex - pad - 1)))
            out.append(row("halfway-far", short + "9" * pad + "e" + str(ex - pad - 1)))


def edge_cases(out):
    tiny = Fraction(2) ** -1074
    big = (2 ** 53 - 1) * Fraction(2) ** 971
    for text in ["4.9406564584124654e-324", "5e-324", "2.4703282292062327e-324",
                 "2.4703282292062328e-324", "2.470328229206232720882e-324",
                 "1e-324", "3e-324", "7.4e-324", "2.2250738585072009e-308",
                 "2.2250738585072011e-308", "2.2250738585072014e-308",
                 "1.7976931348623157e308", "1.7976931348623158e308",
                 "1.7976931348623159e308", "1.797693134862315807e308",
                 "1.797693134862315708e308", "1e308", "1e309", "2e308",
                 "1e-400", "-1e-400", "0", "-0", "0.0", "-0.0e-5", "000.000e+999",
                 "1e-99999", "1e99999", "0.000000000000000000000000000000001e330",
                 "100000000000000000000000000000000000000e-347"]:
        out.append(row("edge", text))
    for text in [exact_decimal(tiny / 2), exact_decimal(tiny * 3 / 2),
                 exact_decimal(big), exact_decimal(big + Fraction(2) ** 969),
                 exact_decimal(Fraction(2) ** -1022), exact_decimal(Fraction(2) ** -1022 - tiny)]:
        out.append(row("edge-exact", text))
        digits, ex = split_exact(Fraction(text))
        out.append(row("edge-exact+", digits + "000001e" + str(ex - 6)))
    for k in range(-330, 311, 7):
        out.append(row("pow10", "1e%d" % k))
    for text in [".5e+2", "5.", "+1", "-1", "1E5", "1e+0", "0001234.5600", ".000123e-2",
                 "1.5e30", "0.12345678901234567890", "1e-5", "123456789012345678901234567890",
                 "9007199254740993", "9007199254740992.5", "4503599627370496.5",
                 "89255.0e-22", "8.98846567431158e307", "4.9e-324", "2.2e-308"]:
        out.append(row("form", text))


def long_cases(rng, out):
    for _ in range(80):
        n = rng.randrange(100, 1000)
        digits = str(rng.randrange(1, 10)) + "".join(rng.choice("0123456789") for _ in range(n - 1))
        ex = rng.randrange(-330 - n, 300 - n)
        out.append(row("long", digits + "e" + str(ex)))
        out.append(row("long", with_point(digits, ex)))
    for _ in range(20):      # long runs of zeros and nines
        n = rng.randrange(100, 900)
        d = str(rng.randrange(1, 10)) + rng.choice("09") * n + str(rng.randrange(1, 10))
        out.append(row("long-run", d + "e" + str(rng.randrange(-330 - n, 300 - n))))


def random_cases(rng, out):
    for _ in range(800):
        if rng.random() < 0.1:
            d = math.ldexp(rng.randrange(1, 2 ** 52), -1074)
        else:
            d = math.ldexp(rng.randrange(2 ** 52, 2 ** 53), rng.randrange(-1074, 971))
        if rng.random() < 0.5:
            d = -d
        out.append(row("g17", "%.17g" % d))
        out.append(row("repr", repr(d)))
        out.append(row("e20", "%.*e" % (rng.randrange(19, 25), d)))
    for _ in range(600):
        n = rng.randrange(1, 40)
        digits = "".join(rng.choice("0123456789") for _ in range(n))
        out.append(row("digits", with_point(digits, rng.randrange(-340, 300))))


def write(name, rows):
    with open(OUT + name, "w") as f:
        f.write("# generated by tools/ref_decimal.py: exact rounding of the text as a\n")
        f.write("# fraction, checked against Python's float(); double = sign * m * 2^e\n")
        f.write("kind\ttext\tsign\tm\te\thex\n")
        for r in rows:
            f.write("\t".join(r) + "\n")
    print("%s: %d rows" % (name, len(rows)), file=sys.stderr)


def main():
    rng = random.Random(20261203)
    hard = []
    halfway_cases(rng, hard)
    edge_cases(hard)
    long_cases(rng, hard)
    write("decimal_hard.tsv", hard)
    rand = []
    random_cases(rng, rand)
    write("decimal_random.tsv", rand)


if __name__ == "__main__":
    main()
