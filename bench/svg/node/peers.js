// bench/svg/node/peers.js -- the JavaScript side of `make bench-svg`:
// svg-path-properties (getTotalLength) and paper.js (Path.length) on each
// drawn element's own path data from build/bench-svg/elements.tsv, times
// the scale of its transform.  They read no XML and apply no transform
// themselves (arclen.svg did both), so their times are measuring only; a
// file with a transform that is not a similarity is skipped for them.
// Prints "NAME<TAB>file<TAB>total<TAB>seconds" per file (best of BENCH_REPS).
"use strict";
const fs = require("fs");
const path = require("path");
const dir = process.argv[2];
module.paths.unshift(path.join(dir, "node", "node_modules"));
const REPS = Number(process.env.BENCH_REPS || 5);
const rows = fs.readFileSync(path.join(dir, "elements.tsv"), "utf8").split("\n").filter(Boolean);
const files = new Map();
for (const r of rows) {
  const [f, s, d] = r.split("\t");
  if (!files.has(f)) files.set(f, []);
  files.get(f).push([s === "-" ? null : Number(s), d]);
}

function run(name, lengthOf) {
  for (const [f, els] of files) {
    if (els.some(e => e[0] === null)) {
      console.log(`${name}\t${f}\tskipped: a transform that is not a similarity\t0`);
      continue;
    }
    let best = Infinity, total = 0;
    try {
      for (let k = 0; k < REPS; k++) {
        const t0 = process.cpuUsage();
        total = 0;
        for (const [s, d] of els) total += s * lengthOf(d);
        const t = process.cpuUsage(t0);
        best = Math.min(best, (t.user + t.system) / 1e6);
      }
    } catch (e) {
      console.log(`${name}\t${f}\tfailed: ${String(e.message).slice(0, 80)}\t0`);
      continue;
    }
    console.log(`${name}\t${f}\t${total.toPrecision(17)}\t${best.toFixed(6)}`);
  }
}

try {
  const m = require("svg-path-properties");
  const P = m.svgPathProperties || m.SVGPathProperties;
  const version = require("svg-path-properties/package.json").version;
  run(`svg-path-properties ${version}`, d => new P(d).getTotalLength());
} catch (e) {
  console.error("svg-path-properties: skipped (" + e.message + ")");
}
try {
  const paper = require("paper");
  paper.setup(new paper.Size(1, 1));
  run(`paper.js ${paper.version}`, d => new paper.CompoundPath(d).children.reduce((a, p) => a + p.length, 0));
} catch (e) {
  console.error("paper.js: skipped (" + e.message + ")");
}
