// earcut on the inputs bench/cycled.lua exports: `node bench/earcut-cycled.js FILE` (a JSON array
// of inputs, each {"vertices": flat array, "holes": earcut's hole start indices}) prints one
// line: the file, then ns a vertex with the first input again and again, and with every input
// in turn, each the best of four rounds of 0.2 s at least, the two ways alternating, after laps
// of 0.5 s (as bench/cycled.lua times polygonTriangulate). EARCUT names earcut's module file.
const fs = require("fs");
const file = process.env.EARCUT || "/tmp/earcut/node_modules/earcut/src/earcut.js";

import(file).then((module) => {
  const earcut = module.default;
  const inputs = JSON.parse(fs.readFileSync(process.argv[2]));
  const counts = inputs.map((c) => c.vertices.length / 2);
  let pieces = 0;   // the checksum that keeps the calls
  const lap = (repeated) => {
    let vertices = 0;
    for (let i = 0; i < inputs.length; i++) {
      const k = repeated ? 0 : i;
      pieces += earcut(inputs[k].vertices, inputs[k].holes).length;
      vertices += counts[k];
    }
    return vertices;
  };
  const seconds = (since) => Number(process.hrtime.bigint() - since) / 1e9;
  const warm = process.hrtime.bigint();
  do lap(false); while (seconds(warm) < 0.5);
  const best = { true: Infinity, false: Infinity };
  for (let round = 0; round < 4; round++) {
    for (const repeated of [true, false]) {
      let vertices = 0;
      const began = process.hrtime.bigint();
      do vertices += lap(repeated); while (seconds(began) < 0.2);
      best[repeated] = Math.min(best[repeated], (seconds(began) / vertices) * 1e9);
    }
  }
  if (pieces < 0) console.log("unreachable");
  console.log(process.argv[2], best[true], best[false]);
});
