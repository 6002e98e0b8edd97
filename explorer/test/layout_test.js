// node layout_test.js WEB_DIR OUT_DIR [FIGURE] — the explorer page's layout in headless Chromium
// (Debian's, driven by playwright-core), opened from disk (file://), at the viewport widths
// 1024 x 768, 1366 x 768 and 1920 x 1080 px, in every state that shows a different set of controls:
//  - design:    n = 13/5 at (0.7, 2.5), the design map and its boundary curves drawn, the count
//               certified, the tolerance verdict shown;
//  - node list: the same with the "Nodes and cusps" box (a <details>) open;
//  - fit:       the same with an inverse design's candidates listed (their "use" buttons);
//  - dense:     n = 133/200 at (pi/2, pi/2): the markers note beside the markers select;
//  - panels:    the clinostat panel (a machine computed) and the chain panel (a three-stage chain:
//               its census, command and picture) open; then the chain made a two-stage one (its
//               gear train and "show it above" button instead);
//  - errors:    a2, the clinostat's outer rpm and the chain's twists refused: the three error lines.
// The markers select's open list is drawn by the browser outside the page's layout, so it has no
// state of its own: the closed select is a control of every state.
//
// The controls: what a user reads or operates — every visible input, select, button, textarea,
// label, summary, canvas, svg, th, li and element with a data-testid; their boxes include their
// text's and an outside list marker's, clipped where an ancestor clips (layout_probe.js, which runs
// in the page, says exactly how). Fails (exit 1, each failure printed with the width and state) when
//  - two controls' boxes intersect with an area > 0 (each side over 1/128 px), unless one contains
//    the other or is its label;
//  - a visible element's box reaches left of 0 or right of the viewport's width (its clientWidth,
//    the viewport less a vertical scrollbar), or document.documentElement.scrollWidth exceeds it
//    (the page scrolls sideways).
// The screenshot: the design state laid out at 1366 x 768 (the sphere's animation stopped at carrier
// angle 0), written at 0.75 device pixels per CSS pixel as OUT_DIR/explorer_1366.png (fails at
// 300 KB or more). With FIGURE (the docs' committed copy,
// data/figures/explorer.png) it is compared with it: fails when the sizes differ or when the mean
// absolute difference of the two images' 8 x 8 px block means (over the blocks and the R, G, B
// channels, 0..255) exceeds SCREENSHOT_TOLERANCE; the fix is to copy OUT_DIR/explorer_1366.png
// over FIGURE.
'use strict';
const fs = require('fs');
const path = require('path');
const { chromium } = require('playwright-core');

const [webDir, outDir, figure] = process.argv.slice(2);
if (!webDir || !outDir) {
  process.stderr.write('usage: node layout_test.js WEB_DIR OUT_DIR [FIGURE]\n');
  process.exit(2);
}
const pageUrl = 'file://' + path.resolve(webDir, 'index.html');
const VIEWPORTS = [{ width: 1024, height: 768 }, { width: 1366, height: 768 }, { width: 1920, height: 1080 }];
const SCREENSHOT_WIDTH = 1366, SCREENSHOT_SCALE = 0.75, SCREENSHOT_BYTES = 300000;
// Mean absolute difference of 8 x 8 block means, 0..255. Measured: two runs of the test (they
// differ in the map's timing text, "128² cells, 0.6 s") 0.002; one letter of the title changed
// 0.014; the page moved right by 8 px (a wider margin on the body) 7.3.
const SCREENSHOT_TOLERANCE = 0.5;
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

const DESIGN = '#a2=0.7&a3=2.5&n=13/5&phase=0';
const DENSE = '#a2=pi/2&a3=pi/2&n=133/200&phase=0';
const CLINOSTAT = '&clinostat=on&outer=1.33&inner=2&tilt=90&frame-angle=90&window=600&epsilon=0.01';
const PANELS = '#a2=pi/3&a3=pi/2&n=2&phase=0' + CLINOSTAT + '&twists=pi/2,1.2,0.4&rates=1,-2/3,5/3&phases=0,0.3,-1';
const ERRORS = '#a2=7&a3=pi/2&n=2&phase=0' + CLINOSTAT.replace('outer=1.33', 'outer=abc') + '&twists=4,1&rates=1,2';

async function open(page, hash) {
  await page.goto('about:blank');
  await page.goto(pageUrl + hash);
  await page.waitForSelector('body[data-ready="1"]');
}

const textOf = (page, id) => page.textContent('[data-testid="' + id + '"]');
const waitState = (page, id, states) => page.waitForFunction(([i, s]) =>
  s.includes(document.querySelector('[data-testid="' + i + '"]').dataset.state), [id, states], { timeout: 60000 });

async function checkState(page, viewport, state) {
  const where = viewport.width + ' px, ' + state;
  await page.addScriptTag({ path: path.join(__dirname, 'layout_probe.js') });
  const m = await page.evaluate(() => window.layoutProbe.measure());
  check(m.controls >= 20, where + ': only ' + m.controls + ' controls found');
  const SHOWN = 20;  // failures listed per state and kind, then counted
  for (const [list, what] of [[m.overlaps, 'overlaps'], [m.outside, 'elements outside the viewport']]) {
    for (const o of list.slice(0, SHOWN)) check(false, where + ': ' + o);
    check(list.length <= SHOWN, where + ': and ' + (list.length - SHOWN) + ' more ' + what);
  }
  check(m.scrollWidth <= m.viewWidth, where + ': the page scrolls sideways (scrollWidth ' + m.scrollWidth + ' > ' + m.viewWidth + ')');
  return m.controls;
}

// The design state, drawn completely and still: the map with its boundary curves, the count
// check and the tolerance verdict done, the sphere at carrier angle 0 without animation.
async function openDesign(page) {
  await open(page, DESIGN);
  await page.waitForFunction(() => /boundary curves/.test(document.querySelector('[data-testid="map-status"]').textContent), null, { timeout: 60000 });
  await waitState(page, 'certified', ['certified', 'not-certified', 'error']);
  await page.waitForFunction(() => document.querySelector('[data-testid="tolerance"]').dataset.verdict, null, { timeout: 60000 });
  await page.evaluate(() => {
    document.getElementById('animate').checked = false;
    window.Explorer.view.theta = 0;
    window.Explorer.drawSphere();
  });
}

// A small circle on the sphere (24 points, 0.5 rad about +Z) as the inverse design's path.
function circlePath() {
  const lines = ['x,y,z'];
  for (let k = 0; k < 24; ++k) {
    const t = 2 * Math.PI * k / 24;
    lines.push([Math.sin(0.5) * Math.cos(t), Math.sin(0.5) * Math.sin(t), Math.cos(0.5)].map((v) => v.toFixed(9)).join(','));
  }
  return lines.join('\n');
}

async function checkViewport(browser, viewport) {
  const page = await browser.newPage({ viewport });
  const counts = [];
  await openDesign(page);
  counts.push(await checkState(page, viewport, 'design'));
  await page.evaluate(() => { document.getElementById('node-list-box').open = true; });
  counts.push(await checkState(page, viewport, 'node list'));
  await page.fill('[data-testid="path-input"]', circlePath());
  await page.click('[data-testid="fit"]');
  await page.waitForSelector('[data-testid="candidate"]', { timeout: 60000 });
  counts.push(await checkState(page, viewport, 'fit'));
  await open(page, DENSE);
  check((await textOf(page, 'marks-note')).trim() !== '', viewport.width + ' px, dense: no markers note');
  counts.push(await checkState(page, viewport, 'dense'));
  await open(page, PANELS);
  await waitState(page, 'clinostat-status', ['done']);
  await waitState(page, 'chain-status', ['done']);
  counts.push(await checkState(page, viewport, 'panels'));
  for (const [field, text] of [['twists', '1.2,0.9'], ['rates', '1,2'], ['phases', '0,0.4']]) await page.fill('[data-testid="chain-' + field + '"]', text);
  await page.waitForFunction(() => !document.getElementById('chain-use-train').hidden &&
    document.querySelector('[data-testid="chain-status"]').dataset.state === 'done', null, { timeout: 60000 });
  counts.push(await checkState(page, viewport, 'panels, two-stage chain'));
  await open(page, ERRORS);
  await waitState(page, 'clinostat-status', ['error']);
  await waitState(page, 'chain-status', ['error']);
  check((await textOf(page, 'error')).trim() !== '', viewport.width + ' px, errors: no error line for a2');
  counts.push(await checkState(page, viewport, 'errors'));
  await page.close();
  console.log(viewport.width + ' x ' + viewport.height + ': controls per state ' + counts.join(', '));
}

// Decodes both PNGs in the page and compares them: sizes, then the mean absolute difference of
// their 8 x 8 block means.
async function compareScreenshot(browser, made, committed) {
  const page = await browser.newPage();
  const uri = (file) => 'data:image/png;base64,' + fs.readFileSync(file).toString('base64');
  const r = await page.evaluate(async ([a, b]) => {
    const pixels = async (src) => {
      const img = new Image();
      img.src = src;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.naturalWidth; c.height = img.naturalHeight;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      return { width: c.width, height: c.height, data: ctx.getImageData(0, 0, c.width, c.height).data };
    };
    const p = await pixels(a), q = await pixels(b);
    if (p.width !== q.width || p.height !== q.height) return { sizes: [p.width, p.height, q.width, q.height] };
    const B = 8, bw = Math.floor(p.width / B), bh = Math.floor(p.height / B);
    let sum = 0;
    for (let by = 0; by < bh; ++by) {
      for (let bx = 0; bx < bw; ++bx) {
        for (let ch = 0; ch < 3; ++ch) {
          let d = 0;
          for (let y = by * B; y < by * B + B; ++y) {
            for (let x = bx * B; x < bx * B + B; ++x) { const i = (y * p.width + x) * 4 + ch; d += p.data[i] - q.data[i]; }
          }
          sum += Math.abs(d) / (B * B);
        }
      }
    }
    return { difference: sum / (bw * bh * 3) };
  }, [uri(made), uri(committed)]);
  await page.close();
  const fix = ' (the page changed: cp ' + made + ' ' + committed + ')';
  if (r.sizes) {
    check(false, 'screenshot: ' + made + ' is ' + r.sizes[0] + ' x ' + r.sizes[1] + ' px, ' + committed + ' ' + r.sizes[2] + ' x ' + r.sizes[3] + fix);
  } else {
    console.log('screenshot: mean block difference to ' + committed + ': ' + r.difference.toFixed(3) + ' (at most ' + SCREENSHOT_TOLERANCE + ')');
    check(r.difference <= SCREENSHOT_TOLERANCE, 'screenshot: ' + made + ' differs from ' + committed + ' by ' + r.difference.toFixed(3) +
      ' (mean of 8 x 8 block means, 0..255; at most ' + SCREENSHOT_TOLERANCE + ')' + fix);
  }
}

// The docs' screenshot: the design state laid out at 1366 x 768 CSS px, written at 0.75 device
// pixels per CSS pixel (1025 x 576 px: at 1 the PNG takes 400 KB, the sphere's antialiased curve
// and the map's cells being most of it).
async function writeScreenshot(browser, file) {
  const page = await browser.newPage({ viewport: { width: SCREENSHOT_WIDTH, height: 768 }, deviceScaleFactor: SCREENSHOT_SCALE });
  await openDesign(page);
  await page.screenshot({ path: file });
  await page.close();
  const bytes = fs.statSync(file).size;
  console.log('screenshot: ' + file + ', ' + bytes + ' bytes');
  check(bytes < SCREENSHOT_BYTES, 'screenshot: ' + file + ' takes ' + bytes + ' bytes, over ' + SCREENSHOT_BYTES);
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
  try {
    for (const viewport of VIEWPORTS) await checkViewport(browser, viewport);
    const made = path.join(outDir, 'explorer_1366.png');
    await writeScreenshot(browser, made);
    if (figure) await compareScreenshot(browser, made, figure);
  } finally {
    await browser.close();
  }
  for (const f of failures) console.error('FAIL ' + f);
  console.log(failures.length === 0 ? 'layout: every check holds' : 'layout: ' + failures.length + ' failures');
  process.exit(failures.length === 0 ? 0 : 1);
})().catch((e) => { console.error(e); process.exit(1); });
