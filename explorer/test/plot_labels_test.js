// node plot_labels_test.js SPHTROCH_EXE OUT_DIR — `sphtroch plot --labels auto` (the default) for a
// dense curve (n = 13/5, 169 nodes) in three views, each SVG laid out by Chromium: no two node or
// cusp labels overlap, measured on the glyphs as drawn (getBBox), not on the estimate the
// renderer uses; --labels numbers (every label) does overlap there, so the check can fail.
'use strict';
const fs = require('fs');
const path = require('path');
const { spawnSync } = require('child_process');
const { chromium } = require('playwright-core');

const [exe, outDir] = process.argv.slice(2);
const failures = [];

async function overlaps(page, file) {
  await page.goto('file://' + path.resolve(file));
  return page.evaluate(() => {
    const boxes = Array.from(document.querySelectorAll('text'))
      .filter((t) => /^[NC]\d+$/.test(t.textContent) && !/stroke:#ffffff/.test(t.getAttribute('style')))
      .map((t) => ({ name: t.textContent, b: t.getBBox() }));
    const hits = [];
    for (let i = 0; i < boxes.length; ++i)
      for (let j = i + 1; j < boxes.length; ++j) {
        const a = boxes[i].b, c = boxes[j].b;
        if (a.x < c.x + c.width && c.x < a.x + a.width && a.y < c.y + c.height && c.y < a.y + a.height)
          hits.push(boxes[i].name + '/' + boxes[j].name);
      }
    return { labels: boxes.length, hits };
  });
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
  const page = await browser.newPage();
  const cases = [['', 'auto'], ['--view top', 'auto'], ['--view 30deg,10deg', 'auto'], ['', 'numbers']];
  for (const [k, [view, labels]] of cases.entries()) {
    const file = path.join(outDir, 'labels_' + k + '.svg');
    const args = ['plot', '--a2', '0.7', '--a3', '2.5', '--n', '13/5', '--labels', labels, '-o', file, ...view.split(' ').filter((w) => w)];
    const run = spawnSync(exe, args, { encoding: 'utf8' });
    if (run.status !== 0) { failures.push('plot ' + args.join(' ') + ': exit ' + run.status + ' ' + run.stderr); continue; }
    const r = await overlaps(page, file);
    const what = 'plot ' + (view || '(default view)') + ' --labels ' + labels + ': ' + r.labels + ' labels, ' + r.hits.length + ' overlapping pairs';
    console.log(what);
    if (labels === 'auto' && (r.hits.length > 0 || r.labels < 40)) failures.push(what + ' ' + r.hits.slice(0, 5).join(' '));
    if (labels === 'numbers' && (r.hits.length === 0 || r.labels !== 169)) failures.push(what + ' (expected 169 labels, some overlapping)');
  }
  await browser.close();
  for (const f of failures) console.log('FAIL ' + f);
  process.exit(failures.length === 0 ? 0 : 1);
})().catch((e) => { console.log('FAIL ' + (e && e.stack ? e.stack : e)); process.exit(1); });
