// earcut on the outlines with holes bench/holes.lua exports: `node bench/earcut-holes.js DIR` prints
// for each DIR/*.json ({"vertices": flat array, "holes": earcut's hole start indices}) one line:
// name, vertices, warm milliseconds per call (the best round of 0.2 s once three in a row bring
// it down by less than 2%, after a warm-up of 0.5 s), triangles. `node bench/earcut-holes.js
// DIR NAME` prints the first call's milliseconds in this process (what a level load pays), then
// exits. EARCUT names earcut's module file (default: the one npm installs in /tmp/earcut).
const fs = require("fs");
const path = require("path");
const file = process.env.EARCUT || "/tmp/earcut/node_modules/earcut/src/earcut.js";

import(file).then((module) => {
  const earcut = module.default;
  const dir = process.argv[2], only = process.argv[3];
  const read = (name) => JSON.parse(fs.readFileSync(path.join(dir, name + ".json")));
  if (only) {
    const c = read(only);
    const start = process.hrtime.bigint();
    const tris = earcut(c.vertices, c.holes);
    const ms = Number(process.hrtime.bigint() - start) / 1e6;
    console.log(only, c.vertices.length / 2, ms, tris.length / 3);
    return;
  }
  for (const name of fs.readdirSync(dir).filter((f) => f.endsWith(".json")).sort()) {
    const c = read(name.replace(/\.json$/, ""));
    // as bench/holes.lua: rounds until three in a row do not bring the best down by 2%
    let best = Infinity, pieces = 0, tris = [], calm = 0;
    const began = process.hrtime.bigint();
    for (let round = 0; calm < 3 && Number(process.hrtime.bigint() - began) / 1e9 < 10; round++) {
      let runs = 0, elapsed = 0;
      const start = process.hrtime.bigint();
      do {
        tris = earcut(c.vertices, c.holes);
        pieces += tris.length;
        runs++;
        elapsed = Number(process.hrtime.bigint() - start) / 1e9;
      } while (runs < 2 || elapsed < (round === 0 ? 0.5 : 0.2));
      if (round > 0) {
        const ms = (elapsed / runs) * 1e3;
        calm = ms < 0.98 * best ? 0 : calm + 1;
        best = Math.min(best, ms);
      }
    }
    if (pieces < 0) console.log("unreachable");   // pieces: the checksum that keeps the runs
    console.log(name.replace(/\.json$/, ""), c.vertices.length / 2, best, tris.length / 3);
  }
});
