// node layout_test.js WEB_DIR OUT_DIR [FIGURE] — the explorer page's layout in headless Chromium
// (Debian's, driven by playwright-core), opened from disk (file://), at the viewport widths
// 1024 x 768, 1366 x 768 and 1920 x 1080 px, in every state that shows a different set of controls:
//  - design:    n = 13/5 at (0.7, 2.5), the design map and its boundary curves drawn, the count
//               certified, the tolerance verdict shown;
//  - node list: the same with the "Nodes and cusps" box (a <details>) open;
//  - fit:       the same with an inverse design's candidates listed (their "use" buttons);
//  - dense:     n = 133/200 at (pi/2, pi/2): the markers note beside the markers select;
//  - panels:    the clinostat panel (a machine computed) and the chain panel (a two-stage chain:
//               its picture, census and "show it above" button) open;
//  - errors:    a2, the clinostat's outer rpm and the chain's twists refused: the three error lines.
// The markers select's open list is drawn by the browser outside the page's layout, so it has no
// state of its own: the closed select is a control of every state.
//
// The controls: what a user reads or operates. Every visible input (not type=hidden), select,
// button, textarea, label, summary, canvas, outermost svg, table header cell (th: a readout's name)
// and every element with a data-testid (the readouts, status and error lines of the test contract,
// docs/explorer.md); elements inside an svg are its drawing, not controls. A control's boxes are its
// border boxes (getClientRects: one per line of an inline element) and the boxes of the text inside
// it (so a label whose text runs out of its box counts where the text is), each clipped to every
// ancestor that clips its overflow (a scrolled box shows only what lies inside it).
// Fails (exit 1, each failure printed with the width and state) when
//  - two controls' boxes intersect with an area > 0 (each side longer than 1/128 px, below
//    Chromium's layout unit of 1/64 px: float noise is not an overlap), unless one contains the
//    other in the document (a control and its descendants) or one is the other's label
//    (label.control);
//  - a visible element's clipped box reaches left of 0 or right of the viewport's width
//    (document.documentElement.clientWidth, the viewport less a vertical scrollbar, 1/128 px
//    allowed), or document.documentElement.scrollWidth > clientWidth (the page scrolls sideways).
// The screenshot: at 1366 x 768, the design state (the sphere's animation stopped at carrier angle
// 0) is written as OUT_DIR/explorer_1366.png. With FIGURE (the docs' committed copy,
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
// Mean absolute difference of 8 x 8 block means, 0..255. Two runs of the test differ by the map's
// timing text ("128² cells, 0.6 s") and a few antialiased pixels: measured 0.02; the layout moved
// by 8 px (a wider margin on the body) measures 3.9.
const SCREENSHOT_TOLERANCE = 0.5;
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

const DESIGN = '#a2=0.7&a3=2.5&n=13/5&phase=0';
const DENSE = '#a2=pi/2&a3=pi/2&n=133/200&phase=0';
const CLINOSTAT = '&clinostat=on&outer=1.33&inner=2&tilt=90&frame-angle=90&window=600&epsilon=0.01';
const PANELS = '#a2=pi/3&a3=pi/2&n=2&phase=0' + CLINOSTAT + '&twists=1.2,0.9&rates=1,2&phases=0,0.4';
const ERRORS = '#a2=7&a3=pi/2&n=2&phase=0' + CLINOSTAT.replace('outer=1.33', 'outer=abc') + '&twists=4,1&rates=1,2';

// Runs in the page: the controls' clipped boxes, the overlapping pairs and the elements outside
// the viewport horizontally (see the file's comment for the rules).
function measureLayout() {
  const EPS = 1 / 128;
  const SELECTOR = 'input:not([type=hidden]), select, button, textarea, label, summary, canvas, svg, th, [data-testid]';
  const viewWidth = document.documentElement.clientWidth;
  const inSvg = (el) => el.parentElement && el.parentElement.closest('svg') !== null;
  const name = (el) => {
    let s = el.tagName.toLowerCase();
    if (el.id) s += '#' + el.id;
    if (el.dataset.testid) s += '[data-testid=' + el.dataset.testid + ']';
    const text = (el.textContent || el.value || '').trim().replace(/\s+/g, ' ').slice(0, 24);
    return text ? s + ' "' + text + '"' : s;
  };
  // The rectangle r cut to every ancestor of el that clips its overflow (its padding box).
  const clip = (el, r) => {
    let { left, top, right, bottom } = r;
    for (let a = el.parentElement; a && a !== document.documentElement; a = a.parentElement) {
      const cs = getComputedStyle(a);
      if (cs.overflowX === 'visible' && cs.overflowY === 'visible') continue;
      const b = a.getBoundingClientRect();
      left = Math.max(left, b.left + a.clientLeft); right = Math.min(right, b.left + a.clientLeft + a.clientWidth);
      top = Math.max(top, b.top + a.clientTop); bottom = Math.min(bottom, b.top + a.clientTop + a.clientHeight);
    }
    return right - left > EPS && bottom - top > EPS ? { left, top, right, bottom } : null;
  };
  const visible = (el) => el.checkVisibility({ checkOpacity: false, checkVisibilityCSS: true });
  const boxesOf = (el) => {
    const rects = Array.from(el.getClientRects());
    const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
    const range = document.createRange();
    for (let t = walker.nextNode(); t; t = walker.nextNode()) {
      if (t.textContent.trim() === '' || !visible(t.parentElement)) continue;
      range.selectNodeContents(t);
      rects.push(...range.getClientRects());
    }
    return rects.map((r) => clip(el, r)).filter((r) => r !== null);
  };
  const controls = [];
  for (const el of document.body.querySelectorAll(SELECTOR)) {
    if (inSvg(el) || !visible(el)) continue;
    const boxes = boxesOf(el);
    if (boxes.length > 0) controls.push({ el, boxes });
  }
  const related = (a, b) => a.contains(b) || b.contains(a) || (a.control && a.control === b) || (b.control && b.control === a);
  const overlaps = [];
  for (let i = 0; i < controls.length; ++i) {
    for (let j = i + 1; j < controls.length; ++j) {
      const a = controls[i], b = controls[j];
      if (related(a.el, b.el)) continue;
      let worst = null;
      for (const p of a.boxes) {
        for (const q of b.boxes) {
          const w = Math.min(p.right, q.right) - Math.max(p.left, q.left), h = Math.min(p.bottom, q.bottom) - Math.max(p.top, q.top);
          if (w > EPS && h > EPS && (!worst || w * h > worst.w * worst.h)) worst = { w, h, x: Math.max(p.left, q.left), y: Math.max(p.top, q.top) };
        }
      }
      if (worst) {
        overlaps.push(name(a.el) + ' and ' + name(b.el) + ' overlap by ' + worst.w.toFixed(1) + ' x ' + worst.h.toFixed(1) +
          ' px at (' + worst.x.toFixed(0) + ', ' + (worst.y + window.scrollY).toFixed(0) + ')');
      }
    }
  }
  const outside = [];
  for (const el of document.body.querySelectorAll('*')) {
    if (inSvg(el) || !visible(el)) continue;
    for (const r of Array.from(el.getClientRects()).map((x) => clip(el, x)).filter((x) => x !== null)) {
      if (r.left < -EPS || r.right > viewWidth + EPS) {
        outside.push(name(el) + ' spans x = ' + r.left.toFixed(1) + ' .. ' + r.right.toFixed(1) + ', the viewport 0 .. ' + viewWidth);
        break;
      }
    }
  }
  const scrollWidth = document.documentElement.scrollWidth;
  return { controls: controls.length, overlaps, outside, scrollWidth, viewWidth };
}

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
  const m = await page.evaluate(measureLayout);
  check(m.controls >= 20, where + ': only ' + m.controls + ' controls found');
  for (const o of m.overlaps) check(false, where + ': ' + o);
  for (const o of m.outside) check(false, where + ': ' + o);
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
