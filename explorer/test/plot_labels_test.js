// node plot_labels_test.js SPHTROCH_EXE OUT_DIR — `sphtroch plot` pictures laid out by Chromium,
// measured on the glyphs as drawn (getBBox), not on the estimates the renderer uses:
// - `--labels auto` (the default) for dense curves (n = 13/5 with 169 nodes in three views, and
//   others): every two node or cusp labels at least 12 px apart; --labels numbers (every label)
//   does overlap there, so the check can fail;
// - every picture: each text at least 9.5 px, inside the picture, and the notes and caption under
//   the sphere (the group "caption") clear of the sphere's disc, also for n = 133/200 (26,602
//   nodes) and a long caption.
'use strict';
const fs = require('fs');
const path = require('path');
const { spawnSync } = require('child_process');
const { chromium } = require('playwright-core');

const [exe, outDir] = process.argv.slice(2);
const failures = [];

async function measure(page, file) {
  await page.goto('file://' + path.resolve(file));
  return page.evaluate(() => {
    const root = document.querySelector('svg');
    const width = parseFloat(root.getAttribute('width')), height = parseFloat(root.getAttribute('height'));
    const disc = document.querySelector('circle');
    const cx = parseFloat(disc.getAttribute('cx')), cy = parseFloat(disc.getAttribute('cy')), r = parseFloat(disc.getAttribute('r'));
    const gap = (a, c) => Math.hypot(Math.max(0, c.x - (a.x + a.width), a.x - (c.x + c.width)),
                                     Math.max(0, c.y - (a.y + a.height), a.y - (c.y + c.height)));
    const texts = Array.from(document.querySelectorAll('text'));
    const labels = texts
      .filter((t) => /^[NC]\d+$/.test(t.textContent) && !/stroke:#ffffff/.test(t.getAttribute('style')))
      .map((t) => ({ name: t.textContent, b: t.getBBox() }));
    let closest = Infinity, pair = '';
    for (let i = 0; i < labels.length; ++i)
      for (let j = i + 1; j < labels.length; ++j) {
        const g = gap(labels[i].b, labels[j].b);
        if (g < closest) { closest = g; pair = labels[i].name + '/' + labels[j].name; }
      }
    const problems = [];
    for (const t of texts) {
      const size = parseFloat(getComputedStyle(t).fontSize), b = t.getBBox();
      if (size < 9.5) problems.push('"' + t.textContent + '" is ' + size + ' px');
      if (b.x < -0.5 || b.y < -0.5 || b.x + b.width > width + 0.5 || b.y + b.height > height + 0.5)
        problems.push('"' + t.textContent + '" leaves the picture');
      if (t.closest('#caption')) {
        const nx = Math.min(Math.max(cx, b.x), b.x + b.width), ny = Math.min(Math.max(cy, b.y), b.y + b.height);
        if (Math.hypot(nx - cx, ny - cy) <= r) problems.push('"' + t.textContent + '" lies on the sphere\'s disc');
      }
    }
    return { labels: labels.length, closest, pair, problems };
  });
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
  const page = await browser.newPage();
  const train = '--a2 0.7 --a3 2.5 --n 13/5';
  const cases = [[train, 'auto'], [train + ' --view top', 'auto'], [train + ' --view 30deg,10deg', 'auto'],
                 ['--a2 1.2 --a3 2.2 --n 9/4', 'auto'], ['--a2 pi/2 --a3 pi/2 --n 11/7', 'auto'], [train, 'numbers'],
                 ['--a2 pi/2 --a3 pi/2 --n 133/200', 'auto'], ['--a2 0.7 --a3 2.5 --n 133/200 --style density', 'auto'],
                 ['--a2 pi/3 --a3 pi/2 --teeth 120:60', 'auto']];
  for (const [k, [args, labels]] of cases.entries()) {
    const file = path.join(outDir, 'labels_' + k + '.svg');
    const argv = ['plot', ...args.split(' '), '--labels', labels, '-o', file];
    const run = spawnSync(exe, argv, { encoding: 'utf8' });
    if (run.status !== 0) { failures.push('plot ' + argv.join(' ') + ': exit ' + run.status + ' ' + run.stderr); continue; }
    const r = await measure(page, file);
    const what = 'plot ' + args + ' --labels ' + labels + ': ' + r.labels + ' labels, the closest two ' +
                 (r.labels > 1 ? r.closest.toFixed(1) + ' px apart (' + r.pair + ')' : '(none)');
    console.log(what);
    for (const p of r.problems) failures.push('plot ' + args + ': ' + p);
    const dense = !args.includes('133/200') && !args.includes('teeth');
    if (labels === 'auto' && dense && (r.closest < 12 || r.labels < 20)) failures.push(what);
    if (labels === 'numbers' && (r.closest > 0 || r.labels !== 169)) failures.push(what + ' (expected 169 labels, some overlapping)');
  }
  await browser.close();
  for (const f of failures) console.log('FAIL ' + f);
  process.exit(failures.length === 0 ? 0 : 1);
})().catch((e) => { console.log('FAIL ' + (e && e.stack ? e.stack : e)); process.exit(1); });
