// node bench/explorer.js [BUILD_DIR] — the explorer's speed in headless Chromium (Debian's, through
// explorer/test/node_modules/playwright-core), opened from disk as a user would:
//   first load (navigation to the first state drawn), a slider update (classify + trace + redraw;
//   a3 moved, so the ruler's events are kept) for 60 random trains with |p|, q <= 7, the boundary
//   events at one a2 (lib.events, 60 random), the design map (128^2 cells, then the boundary
//   curves) in its worker, the census of a dense curve (n = 133/200, a2 = a3 = pi/2: 26,602 nodes;
//   lib.classify, median of 3), the page's certificate of three trains (report Fig. 3, n = 13/5 at
//   (0.7, 2.5), n = 133/200 at pi/2, pi/2: from the state drawn to the count check's verdict, the
//   certified census in its worker) and the module's size. Prints medians; not a test (timing
//   never is).
'use strict';
const fs = require('fs');
const path = require('path');
const zlib = require('zlib');
const { chromium } = require(path.join(__dirname, '..', 'explorer', 'test', 'node_modules', 'playwright-core'));

const build = path.resolve(process.argv[2] || 'build');
const url = 'file://' + path.join(build, 'web', 'index.html');
const median = (xs) => { const s = xs.slice().sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

// The page's certificate of the train in `hash`: ms from the state drawn to the count check's
// verdict ("certified" or "not-certified"; [data-testid="certified"]'s data-state), and the verdict.
async function certificateTime(page, hash) {
  await page.goto(url + hash);
  await page.waitForSelector('body[data-ready="1"]');
  const t0 = Date.now();
  await page.waitForFunction(() => !['pending', ''].includes(document.querySelector('[data-testid="certified"]').dataset.state),
    null, { timeout: 600000 });
  const state = await page.evaluate(() => document.querySelector('[data-testid="certified"]').dataset.state);
  return { ms: Date.now() - t0, state };
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
  const page = await browser.newPage({ viewport: { width: 1400, height: 1100 } });
  const loads = [];
  for (let i = 0; i < 5; ++i) {
    const t0 = Date.now();
    await page.goto(url + '#a2=pi/3&a3=pi/2&n=2&phase=0');
    await page.waitForSelector('body[data-ready="1"]');
    loads.push(Date.now() - t0);
  }
  const inPage = await page.evaluate(() => {
    const ex = window.sphtrochExplorer, lib = ex.lib;
    let seed = 7;
    const rnd = () => { seed = (seed * 16807) % 2147483647; return seed / 2147483647; };
    const update = [], compute = [], events = [];
    for (let k = 0; k < 60; ++k) {
      const p = 1 + Math.floor(rnd() * 7), q = 1 + Math.floor(rnd() * 7);
      const n = (rnd() < 0.3 ? -p : p) + '/' + q, a2 = (0.1 + rnd() * 2.9).toFixed(4);
      window.location.hash = '#a2=' + a2 + '&a3=1&n=' + n + '&phase=0';
      window.dispatchEvent(new HashChangeEvent('hashchange'));  // loads the state (events computed)
      const field = document.querySelector('[data-testid="a3-text"]');
      field.value = (0.1 + rnd() * 2.9).toFixed(4);
      field.dispatchEvent(new Event('input'));                  // the slider's path: a3 moves
      update.push(ex.timing().total);
      compute.push(ex.timing().compute);
      const t0 = performance.now();
      lib.events((0.1 + rnd() * 2.9).toFixed(5), n, '');
      events.push(performance.now() - t0);
    }
    const dense = [];
    for (let k = 0; k < 3; ++k) {
      const t0 = performance.now();
      lib.classify('pi/2', 'pi/2', '133/200', '0', '');
      dense.push(performance.now() - t0);
    }
    return { update, compute, events, dense };
  });
  await page.goto(url + '#a2=0.7&a3=2.5&n=13/5&phase=0');
  await page.waitForSelector('body[data-ready="1"]');
  await page.waitForFunction(() => /boundary curves/.test(document.querySelector('[data-testid="map-status"]').textContent), null, { timeout: 120000 });
  const status = await page.textContent('[data-testid="map-status"]');
  const certificates = [];
  for (const [name, hash] of [['report Fig. 3', '#a2=pi/2&a3=pi/2&n=1&phase=0'], ['n = 13/5 at (0.7, 2.5)', '#a2=0.7&a3=2.5&n=13/5&phase=0'],
                              ['n = 133/200 at pi/2, pi/2', '#a2=pi/2&a3=pi/2&n=133/200&phase=0']]) {
    const c = await certificateTime(page, hash);
    certificates.push(name + ' ' + c.ms + ' ms (' + c.state + ')');
  }
  await browser.close();
  const js = fs.readFileSync(path.join(build, 'web', 'sphtroch.js'));
  const wasmBytes = Buffer.from(/base64,([A-Za-z0-9+/=]+)/.exec(js.toString())[1], 'base64');
  console.log('explorer, headless Chromium, ' + new Date().toISOString());
  console.log('first load (median of 5):            ' + median(loads) + ' ms (the first, cold: ' + loads[0] + ' ms)');
  console.log('slider update, a3 (median of 60):    ' + median(inPage.update).toFixed(1) + ' ms (library ' + median(inPage.compute).toFixed(1) + ' ms; max ' + Math.max(...inPage.update).toFixed(1) + ')');
  console.log('boundary events at one a2 (median):  ' + median(inPage.events).toFixed(1) + ' ms (max ' + Math.max(...inPage.events).toFixed(1) + ')');
  console.log('dense census, 133/200 (median of 3):  ' + median(inPage.dense).toFixed(0) + ' ms');
  console.log('design map, n = 13/5:                ' + status);
  console.log('the page\'s certificate:              ' + certificates.join('; '));
  console.log('wasm: ' + wasmBytes.length + ' bytes, gzip ' + zlib.gzipSync(wasmBytes).length + ' bytes; sphtroch.js ' + js.length + ' bytes');
})();
