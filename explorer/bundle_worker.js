// node bundle_worker.js OUT SOURCE... — writes OUT as one classic script that defines
// SPHTROCH_WORKER_SOURCE: the SOURCE files joined, as a string the page turns into a Blob worker
// (a page opened from disk may not start a worker from a file).
'use strict';
const fs = require('fs');
const [out, ...sources] = process.argv.slice(2);
const text = sources.map((f) => fs.readFileSync(f, 'utf8')).join('\n;\n');
fs.writeFileSync(out, 'var SPHTROCH_WORKER_SOURCE = ' + JSON.stringify(text) + ';\n');
