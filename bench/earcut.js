// earcut on the outlines bench/concave.lua exports: `node bench/earcut.js DIR`. For each
// DIR/*.json (a flat array), prints one line: name, vertices, microseconds per vertex,
// triangles, and the relative error of the triangles' total area (doubles; -1 when earcut
// throws). EARCUT names earcut's module file (default: the one npm installs in /tmp/earcut).
const fs = require("fs");
const path = require("path");
const file = process.env.EARCUT || "/tmp/earcut/node_modules/earcut/src/earcut.js";

function area(p, i, j, k) {
  return Math.abs((p[j] - p[i]) * (p[k + 1] - p[i + 1]) - (p[j + 1] - p[i + 1]) * (p[k] - p[i])) / 2;
}

function polygonArea(p) {
  let s = 0;
  for (let i = 0; i < p.length; i += 2) {
    const j = (i + 2) % p.length;
    s += (p[i] - p[0]) * (p[j + 1] - p[1]) - (p[j] - p[0]) * (p[i + 1] - p[1]);
  }
  return Math.abs(s) / 2;
}

import(file).then((module) => {
  const earcut = module.default;
  const dir = process.argv[2];
  for (const name of fs.readdirSync(dir).filter((f) => f.endsWith(".json")).sort()) {
    const points = JSON.parse(fs.readFileSync(path.join(dir, name)));
    const n = points.length / 2;
    // a warm-up of 0.5 s, then the best of three rounds of 0.2 s, as bench/concave.lua does
    let best = Infinity, pieces = 0, tris = [];
    try {
      for (let round = 0; round <= 3; round++) {
        let runs = 0, elapsed = 0;
        const start = process.hrtime.bigint();
        do {
          tris = earcut(points);
          pieces += tris.length;
          runs++;
          elapsed = Number(process.hrtime.bigint() - start) / 1e9;
        } while (runs < 2 || elapsed < (round === 0 ? 0.5 : 0.2));
        if (round > 0) best = Math.min(best, (elapsed / runs / n) * 1e6);
      }
    } catch (e) {
      console.log(name.replace(/\.json$/, ""), n, -1, 0, -1);
      continue;
    }
    let sum = 0;
    for (let t = 0; t < tris.length; t += 3) sum += area(points, 2 * tris[t], 2 * tris[t + 1], 2 * tris[t + 2]);
    const a = polygonArea(points);
    if (pieces < 0) console.log("unreachable");   // pieces: the checksum that keeps the runs
    console.log(name.replace(/\.json$/, ""), n, best, tris.length / 3, Math.abs(sum - a) / a);
  }
});
