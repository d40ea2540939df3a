#!/usr/bin/python3
"""Henkel's published section 6 (the six tables) as data.

Parses the seed text of H. Henkel, "Calculating the Cubic Bezier Arc Length by
Elliptic Integrals" (2014), whose text is the argument: for each of the six examples the control points of
its `arc = {{x,y},...}` line and every row of its table (Eqn, method, arc
length or failure text, steps), in his order.  Nothing is typed by hand: a
change in the seed changes the data.  Writes spec/data/henkel_published.tsv:

  arc  row  x0 y0 x1 y1 x2 y2 x3 y3  eqn  method  value  steps

value is Henkel's text ("18.355664405651", or "invalid arguments", "$R_D$
hangs"); steps is empty where his table has none.

Usage: /usr/bin/python3 tools/henkel_published.py HENKEL.txt
"""
import os
import re
import sys

NUMBER = re.compile(r"-?\d+(?:\.\d+)?")


def parse(text):
    body = text.split("## 6 Testing", 1)[1].split("#### 6.1 Observations", 1)[0]
    arcs, current = [], None
    for line in body.splitlines():
        s = line.strip()
        if "arc" in s and "=" in s and s.startswith("$"):
            nums = [float(v) for v in NUMBER.findall(s.split("=", 1)[1])]
            if len(nums) != 8:
                raise ValueError("arc line without 8 numbers: " + s)
            current = {"coords": nums, "rows": []}
            arcs.append(current)
        elif s.startswith("|") and current is not None:
            cells = [c.strip() for c in s.strip("|").split("|")]
            if not cells or not cells[0].isdigit():
                continue                       # header or --- separator
            eqn, method, value = cells[0], cells[1], cells[2]
            steps = cells[3] if len(cells) > 3 and cells[3].isdigit() else ""
            current["rows"].append((eqn, method, value, steps))
    if len(arcs) != 6 or any(len(a["rows"]) != 7 for a in arcs):
        raise ValueError("expected 6 tables of 7 rows, got %s"
                         % [len(a["rows"]) for a in arcs])
    return arcs


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: tools/henkel_published.py HENKEL.txt (the paper's text)")
    seed = sys.argv[1]
    with open(seed, encoding="utf-8") as f:
        arcs = parse(f.read())
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "spec", "data", "henkel_published.tsv")
    with open(out, "w") as f:
        f.write("arc\trow\tx0\ty0\tx1\ty1\tx2\ty2\tx3\ty3\teqn\tmethod\tvalue\tsteps\n")
        for i, a in enumerate(arcs, 1):
            for j, (eqn, method, value, steps) in enumerate(a["rows"], 1):
                f.write("\t".join([str(i), str(j)] + [repr(v) for v in a["coords"]]
                                  + [eqn, method, value, steps]) + "\n")
    print("6 arcs, %d rows -> %s" % (sum(len(a["rows"]) for a in arcs), out),
          file=sys.stderr)


if __name__ == "__main__":
    main()
