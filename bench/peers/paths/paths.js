// paths.js -- points at k distances along one path by svg-path-properties
// (getPointAtLength) and paper.js (Path.getPointAt), for bench_paths.lua.
// Input (argv[2]/path.txt): SVG path data, the length (arclen's), k.  The
// distances are L i / (k - 1), as bench_paths.lua's.  Writes
// <name>.pts (x y per line) and "name ns-per-point" lines to results.txt.
"use strict";
const fs = require("fs");
const path = require("path");
const dir = process.argv[2];
const [d, Ls, ks] = fs.readFileSync(path.join(dir, "path.txt"), "utf8").split("\n");
const L = Number(Ls), k = Number(ks);
const results = [];

function run(name, setup, at) {
  let obj;
  try {
    obj = setup();
  } catch (e) {
    results.push(`# ${name}: skipped (${e.message})`);
    return;
  }
  const pts = new Float64Array(2 * k);
  const once = () => {
    for (let i = 0; i < k; i++) {
      const p = at(obj, L * i / (k - 1));
      pts[2 * i] = p.x;
      pts[2 * i + 1] = p.y;
    }
  };
  once();                              // warm up (JIT, caches)
  let best = Infinity;
  for (let r = 0; r < 5; r++) {
    const t0 = process.hrtime.bigint();
    once();
    const t = Number(process.hrtime.bigint() - t0) / k;
    if (t < best) best = t;
  }
  const lines = [];
  for (let i = 0; i < k; i++) lines.push(`${pts[2 * i]} ${pts[2 * i + 1]}`);
  fs.writeFileSync(path.join(dir, name + ".pts"), lines.join("\n") + "\n");
  results.push(`${name} ${best.toFixed(1)}`);
}

try {
  const {svgPathProperties} = require("svg-path-properties");
  const ver = require("svg-path-properties/package.json").version;
  run(`svg-path-properties-${ver}`, () => new svgPathProperties(d),
      (o, s) => o.getPointAtLength(s));
} catch (e) {
  results.push(`# svg-path-properties: skipped (${e.message})`);
}
try {
  const paper = require("paper");
  paper.setup(new paper.Size(1, 1));
  // the path's own length, as a user would scale by it; clamp at the end
  run(`paper.js-${paper.version}`, () => {
    const p = new paper.Path(d);
    return {p, scale: p.length / L, end: p.length};
  }, (o, s) => o.p.getPointAt(Math.min(s * o.scale, o.end)));
} catch (e) {
  results.push(`# paper.js: skipped (${e.message})`);
}
fs.writeFileSync(path.join(dir, "results.txt"), results.join("\n") + "\n");
