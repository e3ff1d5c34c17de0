// SPDX-License-Identifier: Apache-2.0
// Times the cncjs `gcode-parser` npm package parsing a G-code file (the side-by-side reference
// of bench/run_parse_bench.sh). Usage: node gcode_parser_time.js FILE [parseFile|parseLine]
//   parseFile: the package's streaming file API (documented usage), results dropped as they come
//   parseLine: parseLine() on every line of the file read into memory (the parser alone)
'use strict';
const fs = require('fs');
const parser = require('gcode-parser');

const file = process.argv[2];
const mode = process.argv[3] || 'parseFile';
const bytes = fs.statSync(file).size;

function report(seconds, blocks) {
  console.log(`gcode-parser ${mode}: ${seconds.toFixed(3)} s  ${(bytes / 1e6 / seconds).toFixed(1)} MB/s  ` +
              `${Math.round(blocks / seconds)} blocks/s  (${blocks} blocks)`);
}

const start = process.hrtime.bigint();
const seconds = () => Number(process.hrtime.bigint() - start) / 1e9;
if (mode === 'parseLine') {
  const lines = fs.readFileSync(file, 'utf8').split('\n');
  let words = 0;
  for (const line of lines) words += parser.parseLine(line).words.length;
  if (words === 0) console.log('no words?');
  report(seconds(), lines.length);
} else {
  let blocks = 0;
  const stream = fs.createReadStream(file, { encoding: 'utf8', highWaterMark: 1 << 16 });
  parser.parseStream(stream, (err) => {
    if (err) { console.error(err); process.exit(2); }
    report(seconds(), blocks);
  }).on('data', (data) => { blocks += Array.isArray(data) ? data.length : 1; });
}
