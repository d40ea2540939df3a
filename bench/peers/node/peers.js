// peers.js -- bezier-js and paper.js on the curves of bench/peers/run.sh
// (one a line: kind "r"/"a", 8 coordinates, reference length), under node.
// Prints per library: name, median ns per random curve, max relative error
// on the random and on the adversarial curves ("inf" for NaN).  Neither
// library takes a tolerance: bezier-js uses a fixed 24-point Gauss rule,
// paper.js a fixed 16-point one (their sources).
"use strict";
const fs = require("fs");
const REPS = 8;

function load(path) {
  const curves = [];
  for (const line of fs.readFileSync(path, "utf8").split("\n")) {
    const f = line.trim().split(/\s+/);
    if (f.length < 10) continue;
    curves.push({random: f[0] === "r", c: f.slice(1, 9).map(Number), ref: Number(f[9])});
  }
  return curves;
}

function measure(name, curves, length) {
  const times = [];
  let sink = 0;
  for (const k of curves) {
    if (!k.random) continue;
    const t0 = process.hrtime.bigint();
    for (let r = 0; r < REPS; r++) sink += length(k.c);
    times.push(Number(process.hrtime.bigint() - t0) / REPS);
  }
  times.sort((a, b) => a - b);
  const n = times.length;
  const median = n % 2 ? times[(n - 1) / 2] : (times[n / 2 - 1] + times[n / 2]) / 2;
  let er = 0, ea = 0;
  for (const k of curves) {
    const L = length(k.c);
    let e = k.ref === 0 ? Math.abs(L) : Math.abs(L - k.ref) / k.ref;
    if (Number.isNaN(e)) e = Infinity;
    if (k.random) er = Math.max(er, e); else ea = Math.max(ea, e);
  }
  if (sink === 0.12345) console.error(sink);
  console.log([name, median.toFixed(1), er.toPrecision(3), ea.toPrecision(3)].join("\t"));
}

const curves = load(process.argv[2]);

try {
  const {Bezier} = require("bezier-js");
  const pkg = JSON.parse(fs.readFileSync(require("path").join(__dirname,
      "node_modules", "bezier-js", "package.json"), "utf8"));
  measure(`bezier-js ${pkg.version} length() (node)`, curves,
          c => new Bezier(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]).length());
} catch (e) {
  console.error("bezier-js: skipped (" + e.message + ")");
}

try {
  const paper = require("paper");
  paper.setup(new paper.Size(1, 1));
  measure(`paper.js ${paper.version} Curve.getLength (node)`, curves,
          c => paper.Curve.getLength(c));
} catch (e) {
  console.error("paper.js: skipped (" + e.message + ")");
}
