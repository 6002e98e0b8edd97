// node page_test.js WEB_DIR SPHTROCH_EXE OUT_DIR — the explorer page in headless Chromium (Debian's,
// driven by playwright-core), opened from disk (file://), against the native tool:
//  - 20 random states from the URL hash: counts and class equal `sphtroch classify --json`, the
//    ruler's events equal `sphtroch boundaries --json` (a3 within 1e-9, kinds), node points
//    within 1e-9 of `sphtroch nodes`, the hash round-trips;
//  - bad input: the CLI's one-line message and no number left from before;
//  - a drag on the a2 slider and a click on the design map move the state as they should;
//  - the exported scene JSON runs with `sphtroch scene` and gives the page's counts; the exported
//    trace CSV and sphere SVG (written by the module) are the bytes of `sphtroch trace` and `plot`;
//  - the certified margin and the tolerance box: the verdict of `sphtroch tolerance`, overlapping
//    margin brackets, a box beyond the margin never holds, one inside it holds, the square drawn;
//  - no console error; a screenshot where the sphere and the map are drawn (not blank); the pitch
//    cones drawn (turning them off and on changes the sphere's pixels, in the cones' colours);
//  - the count check: certified exactly when `sphtroch classify` is (every state above), report
//    Fig. 3 (on the a3 = a2 pole boundary) certified with 1 node;
//  - the legend's colours: CIEDE2000 (ciede2000.js, checked on pairs of Sharma et al. 2005)
//    >= 10 between counts next to each other in the legend, n = 13/5 and 19/7;
//  - the design map's axes in degrees, and its hover readout: a cell's a2, a3 and count (the
//    count: `sphtroch classify` at the cell's centre), the design not moved;
//  - markers: n = 133/200 (26,602 nodes) opens with them hidden and said so, cones off, the path
//    drawn; "all" draws them (and goes into the hash); Fig. 3 draws its node.
//  - the clinostat panel: on six machines its report is the object `sphtroch clinostat ... --json`
//    prints (deep equality, the same doubles) and its readouts show it, its gravity path equals
//    `--trace`, the URL state round-trips, bad texts show the CLI's line and no number, "show its
//    train above" makes it the design;
//  - the chain panel: its picture is the bytes of `sphtroch chain plot`, its census the object of
//    `sphtroch chain classify --json` (node and cusp numbers within 1e-12), a two-stage chain is
//    offered as the design, bad texts show the CLI's line.
// Exit status 0 when every check holds; each failure is printed.
'use strict';
const path = require('path');
const { execFileSync, spawnSync } = require('child_process');
const { chromium } = require('playwright-core');
const { deltaE00, labOfRgb, SELF_CHECK } = require('./ciede2000.js');

const [webDir, exe, outDir] = process.argv.slice(2);
const pageUrl = 'file://' + path.resolve(webDir, 'index.html');
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); };

// A small seeded generator (mulberry32), so a failing state can be reproduced.
function rng(seed) {
  return () => {
    seed |= 0; seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function randomStates(count) {
  const r = rng(20261125), states = [];
  const gcd = (a, b) => (b === 0 ? a : gcd(b, a % b));
  while (states.length < count) {
    let p = 1 + Math.floor(r() * 7), q = 1 + Math.floor(r() * 7);
    const g = gcd(p, q); p /= g; q /= g;
    const sign = r() < 0.3 ? -1 : 1;
    const angle = () => (0.05 + r() * (Math.PI - 0.1)).toFixed(5);
    states.push({ a2: angle(), a3: angle(), n: (sign * p) + (q === 1 ? '' : '/' + q), phase: (r() * 6).toFixed(4) });
  }
  states.push({ a2: 'pi/3', a3: 'ap', n: '2', phase: '0' });  // cusps, given relative to the pitch cone
  states.push({ a2: '60deg', a3: 'pi/2', n: '', teeth: '39:15', phase: '0' });
  return states;
}

function hashOf(s) {
  const enc = (v) => encodeURIComponent(v).replace(/%2F/g, '/').replace(/%3A/g, ':');
  const ratio = s.teeth ? 'teeth=' + enc(s.teeth) : 'n=' + enc(s.n);
  return '#a2=' + enc(s.a2) + '&a3=' + enc(s.a3) + '&' + ratio + '&phase=' + enc(s.phase);
}

function cli(args) {
  const r = spawnSync(exe, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr.trim() };
}

const ratioArgs = (s) => (s.teeth ? ['--teeth', s.teeth] : ['--n', s.n]);
const trainArgs = (s) => ['--a2', s.a2, '--a3', s.a3, ...ratioArgs(s), '--phase', s.phase];

async function readPage(page) {
  return page.evaluate(() => {
    const text = (id) => document.querySelector('[data-testid="' + id + '"]').textContent;
    const events = Array.from(document.querySelectorAll('[data-testid="event"]')).map((e) => ({
      a3: e.getAttribute('data-a3'), kind: e.getAttribute('data-kind') }));
    const out = { error: text('error'), events, hash: window.location.hash };
    for (const id of ['nodes', 'crossings', 'tangencies', 'cusps', 'class']) out[id] = text(id);
    out.certificate = document.querySelector('[data-testid="certified"]').dataset.state;
    out.nodePoints = window.sphtrochExplorer.nodePositions();
    out.cuspPoints = window.sphtrochExplorer.cuspPositions();
    return out;
  });
}

async function open(page, hash) {
  await page.goto(pageUrl + hash);
  await page.waitForSelector('body[data-ready="1"]');
}

// Waits until the count check is decided (certify() runs in a worker after the state is drawn).
const certificateDecided = (page) => page.waitForFunction(
  () => !['pending', ''].includes(document.querySelector('[data-testid="certified"]').dataset.state), null, { timeout: 60000 });

async function checkState(page, s) {
  const hash = hashOf(s);
  await open(page, hash);
  const refused = await page.evaluate(() => document.querySelector('[data-testid="error"]').textContent !== '');
  if (!refused) await certificateDecided(page);
  const got = await readPage(page);
  const where = JSON.stringify(s);
  check(decodeURIComponent(got.hash) === decodeURIComponent(hash), where + ': hash ' + got.hash + ' != ' + hash);
  const classify = cli(['classify', ...trainArgs(s), '--json']);
  if (classify.status === 2) {
    check(got.error === classify.stderr, where + ': page error "' + got.error + '" != CLI "' + classify.stderr + '"');
    check(got.nodes === '' && got.events.length === 0, where + ': numbers shown with an error');
    return;
  }
  const c = JSON.parse(classify.stdout);
  check(got.error === '', where + ': unexpected error ' + got.error);
  check(got.certificate === (c.certified ? 'certified' : 'not-certified'),
    where + ': the count check is ' + got.certificate + ', the CLI certified: ' + c.certified);
  if (c.certified) {
    for (const k of ['nodes', 'crossings', 'tangencies', 'cusps'])
      check(Number(got[k]) === c.counts[k], where + ': ' + k + ' ' + got[k] + ' != CLI ' + c.counts[k]);
    check(got.class === c.class, where + ': class ' + got.class + ' != CLI ' + c.class);
  }
  const bounds = JSON.parse(cli(['boundaries', '--a2', s.a2, ...ratioArgs(s), '--json']).stdout);
  check(bounds.events.length === got.events.length, where + ': ' + got.events.length + ' events != CLI ' + bounds.events.length);
  bounds.events.forEach((e, i) => {
    const g = got.events[i];
    if (!g) return;
    check(Math.abs(Number(g.a3) - e.a3) <= 1e-9, where + ': event ' + i + ' a3 ' + g.a3 + ' != CLI ' + e.a3);
    check(g.kind === e.kind, where + ': event ' + i + ' kind ' + g.kind + ' != CLI ' + e.kind);
  });
  // `sphtroch nodes` lists node points and cusps (kind column): each must be on the page.
  const rows = cli(['nodes', ...trainArgs(s)]).stdout.trim().split('\n').slice(1).filter((l) => l);
  for (const [kind, points] of [['node', got.nodePoints], ['cusp', got.cuspPoints]]) {
    const mine = rows.filter((r) => (r.startsWith('cusp,') ? 'cusp' : 'node') === kind);
    check(mine.length === points.length / 3, where + ': ' + points.length / 3 + ' ' + kind + ' points != CLI ' + mine.length);
    for (const row of mine) {
      const [, x, y, z] = row.split(',').map(Number);
      let best = Infinity;
      for (let i = 0; i < points.length; i += 3)
        best = Math.min(best, Math.hypot(points[i] - x, points[i + 1] - y, points[i + 2] - z));
      check(best <= 1e-9, where + ': CLI ' + kind + ' ' + row + ' is ' + best + ' from every page ' + kind);
    }
  }
}

async function checkBadInput(page) {
  await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }));
  for (const [field, value, args] of [['a2', '7', ['--a2', '7', '--a3', 'pi/2', '--n', '2', '--phase', '0']],
    ['n', 'abc', ['--a2', 'pi/3', '--a3', 'pi/2', '--n', 'abc', '--phase', '0']]]) {
    await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }));
    await page.fill('[data-testid="' + field + '-text"]', value);
    const got = await readPage(page);
    const want = cli(['classify', ...args]);
    check(want.status === 2 && got.error === want.stderr, 'bad ' + field + ': page "' + got.error + '" != CLI "' + want.stderr + '"');
    const listed = await page.textContent('[data-testid="node-list-count"]');
    const rows = await page.locator('[data-testid="node-list"] tbody tr').count();
    check(got.nodes === '' && got.class === '' && got.events.length === 0 && got.nodePoints.length === 0 &&
      listed === '0' && rows === 0, 'bad ' + field + ': a number from before is still shown');
  }
  // A malformed escape in the hash ("50%"): the page still loads and names the text.
  await open(page, '#a2=pi/3&a3=50%&n=2&phase=0');
  const odd = await readPage(page);
  const want = cli(['classify', '--a2', 'pi/3', '--a3', '50%', '--n', '2', '--phase', '0']);
  check(odd.error === want.stderr && odd.nodes === '', 'hash "a3=50%": page "' + odd.error + '" != CLI "' + want.stderr + '"');
}

async function checkSliderAndMap(page) {
  await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }));
  const slider = await page.locator('[data-testid="a2-slider"]').boundingBox();
  // Drag the a2 thumb (at pi/3, a third of the track) left by 8% of the slider's width: a2 drops
  // by 8% of the range or a little more (the thumb's own width shortens the track).
  await page.mouse.move(slider.x + slider.width * 0.33, slider.y + slider.height / 2);
  await page.mouse.down();
  await page.mouse.move(slider.x + slider.width * 0.25, slider.y + slider.height / 2, { steps: 5 });
  await page.mouse.up();
  let got = await readPage(page);
  const a2 = Number(await page.inputValue('[data-testid="a2-text"]'));
  check(a2 < Math.PI / 3 - 0.08 * 3.14 && a2 > Math.PI / 3 - 0.12 * 3.14, 'slider drag: a2 = ' + a2 + ', expected 0.08..0.12 pi below pi/3');
  check(Number(await page.inputValue('[data-testid="a2-slider"]')) === a2, 'slider drag: the text field does not show the slider value');
  check(got.hash.includes('a2=' + a2), 'slider drag: the hash ' + got.hash + ' does not carry a2 = ' + a2);
  let want = JSON.parse(cli(['classify', '--a2', String(a2), '--a3', 'pi/2', '--n', '2', '--json']).stdout);
  check(Number(got.nodes) === want.counts.nodes, 'slider drag: nodes ' + got.nodes + ' != CLI ' + want.counts.nodes);
  // Click on the map at 30% across, 20% down: a2 = 0.3 pi, a3 = 0.8 pi.
  const map = await page.locator('[data-testid="map"]').boundingBox();
  await page.mouse.click(map.x + map.width * 0.3, map.y + map.height * 0.2);
  got = await readPage(page);
  const a2m = Number(await page.inputValue('[data-testid="a2-text"]'));
  const a3m = Number(await page.inputValue('[data-testid="a3-text"]'));
  check(Math.abs(a2m - 0.3 * Math.PI) < 0.02 && Math.abs(a3m - 0.8 * Math.PI) < 0.02,
    'map click: (a2, a3) = (' + a2m + ', ' + a3m + '), expected about (0.3 pi, 0.8 pi)');
  want = JSON.parse(cli(['classify', '--a2', String(a2m), '--a3', String(a3m), '--n', '2', '--json']).stdout);
  check(Number(got.nodes) === want.counts.nodes, 'map click: nodes ' + got.nodes + ' != CLI ' + want.counts.nodes);
}

// The exported scene runs with the tool, and its classification has the page's counts.
async function checkSceneExport(page) {
  const fs = require('fs');
  await open(page, hashOf({ a2: '60deg', a3: 'pi/2', n: '', teeth: '39:15', phase: '0.25' }));
  const got = await readPage(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid="export-scene"]')]);
  const dir = fs.mkdtempSync(path.join(outDir, 'scene-'));
  const file = path.join(dir, 'scene.json');
  await download.saveAs(file);
  const run = cli(['scene', file, '--output-dir', dir]);
  check(run.status === 0, 'scene export: sphtroch scene exited ' + run.status + ': ' + run.stderr);
  if (run.status !== 0) return;
  const c = JSON.parse(fs.readFileSync(path.join(dir, 'explorer.json'), 'utf8'));
  check(c.counts.nodes === Number(got.nodes) && c.counts.cusps === Number(got.cusps),
    'scene export: the scene counts ' + JSON.stringify(c.counts) + ' differ from the page (' + got.nodes + ' nodes)');
  const listed = await page.textContent('[data-testid="node-list-count"]');
  check(Number(listed) === Number(got.nodes) + Number(got.cusps), 'node list: ' + listed + ' rows for ' + got.nodes + ' nodes');
}

// The trace CSV and the sphere SVG are the library's (the module's traceCsv and plotSvg): the
// bytes `sphtroch trace --samples N` (N: the page's samples, the CSV's rows) and `sphtroch plot`
// write for the same texts (the sines under the curve and the grid are core/portable_trig.hpp's,
// the same bits in the module and natively).
async function checkTraceAndPlotExports(page) {
  const fs = require('fs');
  const saved = async (button, name) => {
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
    const file = path.join(outDir, name);
    await download.saveAs(file);
    return fs.readFileSync(file, 'utf8');
  };
  for (const s of [{ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }, { a2: '60deg', a3: 'pi/2', n: '', teeth: '39:15', phase: '0.25' }]) {
    await open(page, hashOf(s));
    const where = JSON.stringify(s);
    const csv = await saved('#export-csv', 'export_trace.csv');
    const samples = csv.split('\n').length - 2;  // the header and the final newline
    const traceFile = path.join(outDir, 'cli_trace.csv');
    const trace = cli(['trace', ...trainArgs(s), '--samples', String(samples), '-o', traceFile]);
    check(samples >= 2000 && trace.status === 0 && csv === fs.readFileSync(traceFile, 'utf8'),
      where + ': the trace CSV export (' + samples + ' rows) differs from sphtroch trace: ' + trace.stderr);
    const svg = await saved('#export-svg', 'export_sphere.svg');
    const plotFile = path.join(outDir, 'cli_sphere.svg');
    const plot = cli(['plot', ...trainArgs(s), '-o', plotFile]);
    check(plot.status === 0 && svg === fs.readFileSync(plotFile, 'utf8'),
      where + ': the sphere SVG export differs from sphtroch plot: ' + plot.stderr);
  }
}

// Inverse design: the CSV of `sphtroch trace` pasted as the path gives back its train first (a2,
// a3 to 1e-6), each candidate's census equals `sphtroch classify` of the printed train, "use" makes
// it the design; bad points and a bad node count show the CLI's line and no candidate; a
// shift-click on the sphere adds a unit vector.
async function checkInverseDesign(page) {
  const hidden = { a2: '1.1', a3: '0.9', n: '2', phase: '0.4' };
  const csv = cli(['trace', ...trainArgs(hidden), '--samples', '48']).stdout;
  await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }));
  await page.fill('[data-testid="path-input"]', csv);
  await page.click('[data-testid="fit"]');
  await page.waitForSelector('[data-testid="candidate"]', { timeout: 60000 });
  const rows = await page.$$eval('[data-testid="candidate"]', (els) => els.map((e) => Object.assign({}, e.dataset)));
  check(rows.length >= 1 && Math.abs(Number(rows[0].a2) - 1.1) < 1e-6 && Math.abs(Number(rows[0].a3) - 0.9) < 1e-6,
    'inverse design: the traced train is not first: ' + JSON.stringify(rows[0]));
  for (const r of rows) {
    const c = cli(['classify', '--a2', r.a2, '--a3', r.a3, '--n', r.n, '--phase', r.phase, '--json']);
    const j = c.status === 0 ? JSON.parse(c.stdout) : null;
    check(j && j.certified && Number(r.nodes) === j.counts.nodes && Number(r.cusps) === j.counts.cusps,
      'inverse design: a candidate\'s census differs from sphtroch classify: ' + JSON.stringify(r) + ' ' + c.stdout.slice(0, 200));
  }
  await page.click('[data-testid="use-candidate"]');
  const usedState = await page.evaluate(() => window.sphtrochExplorer.state());
  const used = await readPage(page);
  check(usedState.a2 === rows[0].a2 && usedState.a3 === rows[0].a3 && used.nodes === rows[0].nodes,
    'inverse design: "use" did not make the candidate the design: ' + JSON.stringify(usedState) + ' nodes ' + used.nodes);
  const tooMany = 'x,y,z\n' + '0,0,1\n'.repeat(60000);  // over the page's bound for n = 2 (58823 points)
  const setPath = (text) => page.evaluate((t) => {
    const area = document.querySelector('[data-testid="path-input"]');
    area.value = t;
    area.dispatchEvent(new Event('input'));
  }, text);
  for (const [text, nodes, field] of [['x,y,z\n1,2\n', '', '--points'], [csv, 'x', '--nodes'], [csv, '1000000000', '--nodes'],
    [tooMany, '', '--points = 60000 points']]) {
    await setPath(csv);  // a good fit first: its candidates must go
    await page.fill('[data-testid="fit-nodes"]', '');
    await page.click('[data-testid="fit"]');
    const before = await page.$$eval('[data-testid="candidate"]', (els) => els.length);
    await setPath(text);
    await page.fill('[data-testid="fit-nodes"]', nodes);
    await page.click('[data-testid="fit"]');
    const error = await page.textContent('[data-testid="fit-error"]');
    const count = await page.$$eval('[data-testid="candidate"]', (els) => els.length);
    check(before > 0 && error.startsWith('sphtroch: ' + field) && count === 0,
      'inverse design: bad ' + field + ' gave "' + error + '" and ' + count + ' candidates (' + before + ' before)');
  }
  await setPath('');
  await page.fill('[data-testid="fit-nodes"]', '');
  // A shift-click adds the point under the pointer, on the front of the sphere. The pointer goes
  // to a whole pixel of the viewport (where a click lands), `at` is it from the canvas's corner.
  await page.locator('[data-testid="sphere"]').scrollIntoViewIfNeeded();
  const box = await page.locator('[data-testid="sphere"]').boundingBox();
  const pointer = { x: Math.round(box.x + box.width * 0.45), y: Math.round(box.y + box.height * 0.4) };
  const at = { x: pointer.x - box.x, y: pointer.y - box.y };
  await page.keyboard.down('Shift');
  await page.mouse.click(pointer.x, pointer.y);
  await page.keyboard.up('Shift');
  const added = (await page.inputValue('[data-testid="path-input"]')).trim().split('\n');
  const p = added.length === 2 ? added[1].split(',').map(Number) : [];
  const seen = p.length === 3 ? await page.evaluate((q) => {
    const c = document.querySelector('[data-testid="sphere"]');
    const s = window.sphtrochExplorer.project(q);
    return [s[0] * c.getBoundingClientRect().width / c.width, s[1] * c.getBoundingClientRect().height / c.height, s[2]];
  }, p) : null;
  check(added[0] === 'x,y,z' && p.length === 3 && Math.abs(Math.hypot(...p) - 1) < 1e-12 && seen &&
    Math.abs(seen[0] - at.x) < 0.6 && Math.abs(seen[1] - at.y) < 0.6 && seen[2] === true,
    'inverse design: a shift-click did not add the point under the pointer: ' + JSON.stringify({ added, seen, at }));
}

// Three points of a trace: every train through them equals `sphtroch synth points --json`'s
// (the same count, a2, a3 and phase modulo 2 pi / q within 1e-9, the same certified census
// counts, the isolated flag), certified in both, the traced train among them; two points, and
// a ratio over the page's work bound, are refused with one line and no rows.
async function checkThroughPoints(page) {
  const fs = require('fs');
  const setPath = (text) => page.evaluate((t) => {
    const area = document.querySelector('[data-testid="path-input"]');
    area.value = t;
    area.dispatchEvent(new Event('input'));
  }, text);
  const rowsOf = () => page.$$eval('[data-testid="candidate"]', (els) => els.map((e) => Object.assign({}, e.dataset)));
  for (const hidden of [{ a2: '1', a3: '2', n: '1/2', phase: '0.3' }, { a2: '2.2', a3: '0.7', n: '-3/2', phase: '1.1' },
    { a2: '0.4', a3: '1.3', n: '5/3', phase: '5' }]) {
    const lines = cli(['trace', ...trainArgs(hidden), '--samples', '40']).stdout.trim().split('\n');
    const csv = [lines[0], lines[3], lines[12], lines[30]].join('\n') + '\n';
    const file = path.join(outDir, 'three_points.csv');
    fs.writeFileSync(file, csv);
    const run = cli(['synth', 'points', '--input', file, '--n', hidden.n, '--json']);
    const want = JSON.parse(run.stdout);
    await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n: hidden.n, phase: '0' }));
    await setPath(csv);
    await page.click('[data-testid="through-points"]');
    await page.waitForFunction(() => /train\(s\) through/.test(document.querySelector('[data-testid="fit-status"]').textContent), null, { timeout: 60000 });
    const status = await page.textContent('[data-testid="fit-status"]');
    const rows = await rowsOf();
    const q = Number(hidden.n.split('/')[1] || 1), turn = 2 * Math.PI / q;
    const same = (r, w) => Math.abs(Number(r.a2) - w.a2) < 1e-9 && Math.abs(Number(r.a3) - w.a3) < 1e-9 &&
      Math.abs(((Number(r.phase) - w.phase) % turn + 1.5 * turn) % turn - 0.5 * turn) < 1e-9;
    check(run.status === 0 && want.complete && /all of them \(certified\)/.test(status) && rows.length === want.solutions.length,
      'through 3 points: ' + rows.length + ' rows, "' + status + '"; the CLI: ' + run.stdout.slice(0, 200));
    for (const w of want.solutions) {
      const r = rows.find((x) => same(x, w));
      check(r && Number(r.nodes) === w.counts.nodes && Number(r.cusps) === w.counts.cusps && r.certified === '1' &&
        r.isolated === (w.isolated ? '1' : '0'),
        'through 3 points: the CLI\'s train ' + JSON.stringify(w).slice(0, 160) + ' is not in the page as ' + JSON.stringify(r));
    }
    check(rows.some((r) => Math.abs(Number(r.a2) - Number(hidden.a2)) < 1e-9 && Math.abs(Number(r.a3) - Number(hidden.a3)) < 1e-9),
      'through 3 points: the traced train ' + JSON.stringify(hidden) + ' is missing');
  }
  for (const [text, n, field] of [['x,y,z\n1,0,0\n0,1,0\n', '5/3', '--points'],
    ['x,y,z\n1,0,0\n0,1,0\n0,0,1\n', '1/20', '--n = 1/20: too much work']]) {  // (|p| + q)^2 = 441 > 400
    await open(page, hashOf({ a2: 'pi/3', a3: 'pi/2', n, phase: '0' }));
    await setPath(text);
    await page.click('[data-testid="through-points"]');
    const error = await page.textContent('[data-testid="fit-error"]');
    check(error.startsWith('sphtroch: ' + field) && (await rowsOf()).length === 0,
      'through 3 points: ' + field + ' gave "' + error + '"');
  }
  await setPath('');
}

// The certified margin and the tolerance box against `sphtroch tolerance --json` (the native
// build; the module rounds to nearest with outward steps, so the brackets may differ in the last
// digits but must overlap), and a box wider than the margin's upper bound never holds (the margin
// is the largest half-width free of boundaries); the margin's square is drawn about the cross.
async function checkTolerance(page) {
  const states = [{ a2: '1', a3: '2', n: '5/2', phase: '0' }, { a2: '1.1', a3: '0.9', n: '2', phase: '0.4' },
    { a2: '0.3', a3: '1.2', n: '-1', phase: '0' }, { a2: '0.7', a3: '2.5', n: '13/5', phase: '0' },
    { a2: 'pi/2', a3: 'pi/2', n: '1', phase: '0' }, { a2: '1.5', a3: '1.5', n: '1', phase: '0' },  // the report's Fig. 3; n = +-1
    { a2: 'pi/2', a3: 'pi/2', n: '-1/2', phase: '0' }];
  const readTolerance = () => page.evaluate(() => {
    const m = document.querySelector('[data-testid="margin"]'), t = document.querySelector('[data-testid="tolerance"]');
    return { lower: m.dataset.lower, upper: m.dataset.upper, verdict: t.dataset.verdict, text: t.textContent };
  });
  const setBox = async (a2, a3) => {
    await page.evaluate(() => { document.querySelector('[data-testid="tolerance"]').dataset.verdict = ''; });
    await page.fill('[data-testid="tol-a2"]', a2);
    await page.fill('[data-testid="tol-a3"]', a3);
    await page.waitForFunction(() => document.querySelector('[data-testid="tolerance"]').dataset.verdict, null, { timeout: 30000 });
    return readTolerance();
  };
  for (const s of states) {
    const where = 'tolerance ' + JSON.stringify(s);
    await open(page, hashOf(s));
    const got = await setBox('0.1deg', '0.1deg');
    const want = JSON.parse(cli(['tolerance', ...trainArgs(s), '--tol-a2', '0.1deg', '--tol-a3', '0.1deg', '--json']).stdout);
    check(got.verdict === want.topology, where + ': page ' + got.verdict + ' != CLI ' + want.topology + ' (' + got.text + ')');
    const lower = Number(got.lower), upper = Number(got.upper);
    check(want.margin.converged, where + ': the CLI margin did not converge');
    check(lower > 0 && Math.max(lower, want.margin.lower) <= Math.min(upper, want.margin.upper) * (1 + 1e-12),
      where + ': page margin [' + got.lower + ', ' + got.upper + '] and CLI [' + want.margin.lower + ', ' + want.margin.upper + '] do not overlap');
    const wide = String(1.01 * upper);
    const radians = (t) => (t === 'pi/2' ? Math.PI / 2 : Number(t));
    const [a2, a3] = [radians(s.a2), radians(s.a3)];
    if (a2 - 1.01 * upper > 1e-6 && a2 + 1.01 * upper < Math.PI - 1e-6 && a3 - 1.01 * upper > 1e-6 && a3 + 1.01 * upper < Math.PI - 1e-6) {
      const beyond = await setBox(wide, wide);
      check(beyond.verdict === 'changes' || beyond.verdict === 'undecided', where + ': a box of half-width 1.01 x upper ' + beyond.verdict);
    }
    const inside = await setBox(String(0.99 * lower), String(0.99 * lower));
    check(inside.verdict === 'holds', where + ': a box of half-width 0.99 x lower ' + inside.verdict + ' (' + inside.text + ')');
    const magenta = await page.evaluate(() => {
      const c = document.querySelector('[data-testid="map"]'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let k = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] > 180 && d[i + 1] < 90 && d[i + 2] > 180) ++k;  // magenta
      return k;
    });
    check(magenta >= 8, where + ': the margin square is not drawn on the map (' + magenta + ' magenta pixels)');
  }
  await open(page, hashOf(states[0]));
  const bad = await setBox('-1', '0.1deg');
  const want = cli(['tolerance', ...trainArgs(states[0]), '--tol-a2', '-1', '--tol-a3', '0.1deg']);
  check(bad.verdict === 'error' && want.status === 2 && bad.text === want.stderr, 'tolerance -1: page "' + bad.text + '" != CLI "' + want.stderr + '"');
}

async function checkDrawn(page) {
  await open(page, hashOf({ a2: '0.7', a3: '2.5', n: '13/5', phase: '0' }));
  await page.waitForFunction(() => /boundary curves/.test(document.querySelector('[data-testid="map-status"]').textContent), null, { timeout: 60000 });
  await page.screenshot({ path: path.join(outDir, 'explorer.png'), fullPage: true });
  const inked = await page.evaluate(() => {
    const count = (id) => {
      const c = document.querySelector('[data-testid="' + id + '"]');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const colours = new Set();
      let dark = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (d[i] + d[i + 1] + d[i + 2] < 300 && d[i + 3] > 0) ++dark;
        if (colours.size < 50) colours.add(d[i] + ',' + d[i + 1] + ',' + d[i + 2]);
      }
      return { dark, colours: colours.size };
    };
    return { sphere: count('sphere'), map: count('map') };
  });
  check(inked.sphere.dark > 2000, 'the sphere view is blank: ' + JSON.stringify(inked.sphere));
  check(inked.map.colours >= 5, 'the design map is blank: ' + JSON.stringify(inked.map));
  // The legend by area (n = 13/5, 128^2 cells): the shown counts and the rest cover every cell,
  // no hidden count covers more than a shown one, and every count is a multiple of |p| = 13.
  const legend = await page.evaluate(() => {
    const r = document.querySelector('[data-testid="legend-rest"]');
    return {
      entries: Array.from(document.querySelectorAll('[data-testid="legend-entry"]')).map((e) => [Number(e.dataset.count), Number(e.dataset.cells)]),
      rest: r ? { cells: Number(r.dataset.cells), largest: Number(r.dataset.largest), values: r.dataset.values.split(' ').map(Number) }
        : { cells: 0, largest: 0, values: [] },
    };
  });
  const shownCells = legend.entries.reduce((sum, e) => sum + e[1], 0);
  check(legend.entries.length >= 1 && legend.entries.length <= 8, 'legend entries: ' + JSON.stringify(legend));
  check(shownCells + legend.rest.cells === 128 * 128, 'the legend does not cover the map: ' + JSON.stringify(legend));
  check(Math.min(...legend.entries.map((e) => e[1])) >= legend.rest.largest, 'a hidden count covers more than a shown one: ' + JSON.stringify(legend));
  check(legend.entries.map((e) => e[0]).concat(legend.rest.values).every((v) => v < 0 || v % 13 === 0),
    'a count not in sets of 13: ' + JSON.stringify(legend));
  // The pitch cones: with the animation stopped, turning them off and on again changes thousands
  // of pixels of the sphere, the changed ones tinted blue or green (the cones' colours).
  await page.uncheck('#animate');
  const pixels = () => page.evaluate(() => {
    const c = document.querySelector('[data-testid="sphere"]');
    return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
  });
  await page.uncheck('[data-testid="cones"]');
  const off = await pixels();
  await page.check('[data-testid="cones"]');
  const on = await pixels();
  let changed = 0, tinted = 0;
  for (let i = 0; i < on.length; i += 4) {
    if (on[i] === off[i] && on[i + 1] === off[i + 1] && on[i + 2] === off[i + 2]) continue;
    ++changed;
    if (on[i + 2] > on[i] || on[i + 1] > on[i]) ++tinted;
  }
  check(changed > 2000 && tinted > 0.9 * changed, 'the pitch cones are not drawn: ' + changed + ' pixels changed, ' + tinted + ' tinted');
}

// Report Fig. 3 (n = 1, a2 = a3 = pi/2: on the a3 = a2 pole boundary) is certified in the page as
// by `sphtroch classify`, with its one node; the map's count is labelled as not certified.
async function checkFigure3(page) {
  const fig3 = { a2: 'pi/2', a3: 'pi/2', n: '1', phase: '0' };
  const want = JSON.parse(cli(['classify', ...trainArgs(fig3), '--json']).stdout);
  await open(page, hashOf(fig3));
  await certificateDecided(page);
  const got = await readPage(page);
  const text = await page.textContent('[data-testid="certified"]');
  check(want.certified && want.counts.nodes === 1 && got.certificate === 'certified' && got.nodes === '1' &&
    /^certified: two independent censuses agree/.test(text), 'Fig. 3: the page says "' + text + '" with ' + got.nodes +
    ' node(s); the CLI: certified ' + want.certified + ', ' + want.counts.nodes + ' node(s)');
  check(/not certified/.test(await page.textContent('[data-testid="map-caption"]')), 'the map\'s counts are not labelled as not certified');
}

// The sphere opens looking from where `sphtroch plot` looks by default (the view it states, whole
// degrees): that direction projects within 1 degree's arc of the canvas centre, on the front half,
// with +Z up the screen when the view is not along Z. The README's n = 13/5 example lies below the
// equator (seen from below); Fig. 3 from the side.
async function checkViewFromCurve(page) {
  for (const s of [{ a2: '0.7', a3: '2.5', n: '13/5', phase: '0' }, { a2: 'pi/2', a3: 'pi/2', n: '1', phase: '0' }]) {
    const where = 'view of ' + JSON.stringify(s);
    await open(page, hashOf(s));
    await page.reload();
    await page.waitForSelector('body[data-ready="1"]');
    const file = path.join(outDir, 'view.svg');
    check(cli(['plot', ...trainArgs(s), '-o', file]).status === 0, where + ': sphtroch plot failed');
    const m = /view from az (-?\d+) deg, el (-?\d+) deg/.exec(require('fs').readFileSync(file, 'utf8'));
    check(m !== null, where + ': the CLI picture states no view');
    if (!m) continue;
    const az = Number(m[1]) * Math.PI / 180, el = Number(m[2]) * Math.PI / 180;
    const d = [Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)];
    const got = await page.evaluate((d) => {
      const c = document.getElementById('sphere');
      return { at: window.Explorer.project(d), z: window.Explorer.project([0, 0, 1]), w: c.width, h: c.height };
    }, d);
    const radius = 0.46 * got.w, off = Math.hypot(got.at[0] - got.w / 2, got.at[1] - got.h / 2);
    check(off <= radius * Math.PI / 180 && got.at[2] === true,  // project()'s third value: on the front half
      where + ': the CLI\'s view direction projects ' + off.toFixed(1) + ' px from the centre (front: ' + got.at[2] + ')');
    if (Math.abs(Number(m[2])) < 80) check(got.z[1] < got.h / 2, where + ': +Z does not point up the screen');
    if (s.n === '13/5') check(Number(m[2]) < 0, where + ': not seen from below (el ' + m[2] + ')');
  }
}

// Waits for the map's finest grid (128^2 cells).
const mapDone = (page) => page.waitForFunction(() => /^128² cells/.test(document.querySelector('[data-testid="map-status"]').textContent),
  null, { timeout: 60000 });

// The legend's swatches, as rendered: CIEDE2000 of counts next to each other (sorted by count) at
// least 10, for a ratio with 10 counts on the map (13/5) and one with 18 (19/7).
async function checkPalette(page) {
  for (const [lab1, lab2, want] of SELF_CHECK)
    check(Math.abs(deltaE00(lab1, lab2) - want) < 5e-5, 'ciede2000.js: ' + deltaE00(lab1, lab2) + ' != ' + want + ' (Sharma et al.)');
  for (const n of ['13/5', '19/7']) {
    await open(page, hashOf({ a2: '0.7', a3: '2.5', n, phase: '0' }));
    await mapDone(page);
    const entries = await page.$$eval('[data-testid="legend-entry"]', (els) => els.map((e) => {
      const rgb = getComputedStyle(e.querySelector('i')).backgroundColor.match(/\d+/g).map(Number);
      return { count: Number(e.dataset.count), rgb };
    }));
    const steps = await page.$$eval('[data-testid="count-scale"] .bar i', (els) => els.map((e) => Number(e.dataset.count)));
    const rest = await page.$eval('[data-testid="legend-rest"]', (e) => Number(e.dataset.counts)).catch(() => 0);
    check(entries.length >= 8 && steps.length === entries.length + rest && steps.every((c, k) => k === 0 || c > steps[k - 1]),
      'n = ' + n + ': the count scale ' + JSON.stringify(steps) + ' is not every count present, ascending (' + entries.length + ' + ' + rest + ')');
    entries.sort((a, b) => a.count - b.count);
    for (let k = 1; k < entries.length; ++k) {
      const d = deltaE00(labOfRgb(entries[k - 1].rgb), labOfRgb(entries[k].rgb));
      check(d >= 10, 'n = ' + n + ': CIEDE2000 ' + d.toFixed(2) + ' between the legend\'s ' + entries[k - 1].count + ' and ' +
        entries[k].count + ' nodes (' + entries[k - 1].rgb + ' / ' + entries[k].rgb + ')');
    }
  }
}

// The map's axes: ticks 0°..180° every 30°, 90° at the middle of the cells; the hover readout of
// a cell: its centre's a2 and a3 (degrees, radians) and its count, which `sphtroch classify` gives
// at that centre; the design does not move.
async function checkMapHover(page) {
  const s = { a2: 'pi/3', a3: 'pi/2', n: '5/2', phase: '0' };
  await open(page, hashOf(s));
  await mapDone(page);
  const box = await page.evaluate(() => {
    const c = document.querySelector('[data-testid="map"]'), r = c.getBoundingClientRect();
    return { x: r.left + c.clientLeft, y: r.top + c.clientTop, w: c.clientWidth, h: c.clientHeight };
  });
  for (const axis of ['a2', 'a3']) {
    const ticks = await page.$$eval('[data-testid="map-axis-' + axis + '"] span', (els) => els.map((e) => {
      const r = e.getBoundingClientRect();
      return { text: e.textContent, x: r.left + r.width / 2, y: r.top + r.height / 2 };
    }));
    const middle = ticks.find((t) => t.text === '90°');
    const off = middle ? (axis === 'a2' ? middle.x - (box.x + box.w / 2) : middle.y - (box.y + box.h / 2)) : NaN;
    check(ticks.map((t) => t.text).join(' ') === '0° 30° 60° 90° 120° 150° 180°' && Math.abs(off) <= 2,
      'map axis ' + axis + ': ticks ' + JSON.stringify(ticks) + ', 90° is ' + off + ' px off the middle');
  }
  const [i, j] = [38, 100];  // the cell 38 across, 100 up of 128
  const centre = { a2: (i + 0.5) * Math.PI / 128, a3: (j + 0.5) * Math.PI / 128 };
  await page.mouse.move(box.x + (i + 0.5) / 128 * box.w, box.y + (1 - (j + 0.5) / 128) * box.h);
  const text = await page.textContent('[data-testid="map-hover"]');
  const m = text.match(/a2 = ([\d.]+)° \(([\d.]+) rad\), a3 = ([\d.]+)° \(([\d.]+) rad\): (\d+) nodes/);
  const want = JSON.parse(cli(['classify', '--a2', String(centre.a2), '--a3', String(centre.a3), '--n', s.n, '--json']).stdout);
  const deg = (v) => v * 180 / Math.PI;
  check(m && Math.abs(Number(m[1]) - deg(centre.a2)) <= 0.006 && Math.abs(Number(m[2]) - centre.a2) <= 6e-5 &&
    Math.abs(Number(m[3]) - deg(centre.a3)) <= 0.006 && Math.abs(Number(m[4]) - centre.a3) <= 6e-5 &&
    want.certified && Number(m[5]) === want.counts.nodes,
    'map hover: "' + text + '"; the cell centre (' + centre.a2 + ', ' + centre.a3 + '), the CLI there: ' + want.counts.nodes + ' nodes');
  const state = await page.evaluate(() => window.sphtrochExplorer.state());
  check(state.a2 === s.a2 && state.a3 === s.a3, 'map hover moved the design: ' + JSON.stringify(state));
}

// Pixels of the sphere in the markers' red or orange (front, or faded on the back half: 30% red
// over the sphere's grey-white is still 45 levels redder than green and blue); no other colour of
// the view (curve, pitch circles, cones, tracer) is.
const redPixels = (page) => page.evaluate(() => {
  const c = document.querySelector('[data-testid="sphere"]'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let k = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i] > d[i + 1] + 30 && d[i] > d[i + 2] + 30) ++k;
  return k;
});

// Markers by the library's rule (mark_density.hpp): n = 133/200, a2 = a3 = pi/2 (26,602 nodes by
// `sphtroch classify`, over the automatic limit of 200) opens with no marker, the note saying how
// many are hidden, the cones off and the path drawn; "all" draws them and goes into the hash;
// Fig. 3's one node is drawn, its cones on.
async function checkMarkers(page) {
  const dense = { a2: 'pi/2', a3: 'pi/2', n: '133/200', phase: '0' };
  const want = JSON.parse(cli(['classify', ...trainArgs(dense), '--json']).stdout);
  const marks = want.counts.nodes + want.counts.cusps;
  await open(page, hashOf(dense));
  await page.uncheck('#animate');
  const state = () => page.evaluate(() => ({
    note: document.querySelector('[data-testid="marks-note"]').textContent,
    cones: document.querySelector('[data-testid="cones"]').checked,
    dark: (() => {
      const c = document.querySelector('[data-testid="sphere"]'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let k = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 300 && d[i + 3] > 0) ++k;
      return k;
    })() }));
  const hidden = await state();
  check(marks > 200 && hidden.note === marks + ' node and cusp markers hidden (more than 200)' && !hidden.cones &&
    hidden.dark > 20000 && (await redPixels(page)) === 0,
    'dense curve: ' + JSON.stringify(hidden) + ', ' + (await redPixels(page)) + ' red pixels; the CLI: ' + marks + ' marks');
  await page.selectOption('[data-testid="markers"]', 'all');
  const all = await state();
  const hash = await page.evaluate(() => window.location.hash);
  check(all.note === '' && (await redPixels(page)) > 1000 && /markers=all/.test(hash),
    'markers all: ' + JSON.stringify(all) + ', hash ' + hash);
  await open(page, hashOf({ a2: 'pi/2', a3: 'pi/2', n: '1', phase: '0' }));
  await page.uncheck('#animate');
  const fig3 = await state();
  check(fig3.note === '' && fig3.cones && (await redPixels(page)) > 10, 'Fig. 3: its node is not drawn: ' + JSON.stringify(fig3));
}

// Where the object `got` differs from `want` (JSON values: the same members, arrays of the same
// length, the same strings, booleans and nulls, numbers the same double (Object.is: -0 is not 0),
// or within tolerance(path) of each other where that is not 0): "path: got != want" lines.
function differences(got, want, tolerance, where = '', out = []) {
  const kind = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v);
  if (kind(got) !== kind(want)) out.push(where + ': ' + JSON.stringify(got) + ' != ' + JSON.stringify(want));
  else if (kind(got) === 'number') {
    if (!Object.is(got, want) && !(Math.abs(got - want) <= tolerance(where))) out.push(where + ': ' + got + ' != ' + want);
  } else if (kind(got) === 'object' || kind(got) === 'array') {
    for (const k of new Set([...Object.keys(got), ...Object.keys(want)]))
      differences(got[k], want[k], tolerance, where + '.' + k, out);
  } else if (got !== want) out.push(where + ': ' + JSON.stringify(got) + ' != ' + JSON.stringify(want));
  return out;
}

// The clinostat panel (clinostat.js) for the state `s` (the CLI's option texts): waits until the
// worker is done and reads its report (the object the page shows), its readouts' data attributes,
// error line and hash.
async function readClinostat(page) {
  await page.waitForFunction(() => ['done', 'error'].includes(document.querySelector('[data-testid="clinostat-status"]').dataset.state),
    null, { timeout: 30000 });
  return page.evaluate(() => {
    const cell = (id) => document.querySelector('[data-testid="clinostat-' + id + '"]');
    const out = { error: cell('error').textContent, hash: window.location.hash, path: window.sphtrochExplorer.clinostatPath(),
      report: window.sphtrochExplorer.clinostatReport() };
    for (const id of ['train', 'period', 'mean', 'worst', 'time']) out[id] = Object.assign({ text: cell(id).textContent }, cell(id).dataset);
    out.command = cell('command').textContent;
    out.coverage = cell('coverage').textContent;
    return out;
  });
}

const CLINOSTAT_DEFAULTS = { outer: '1.33', inner: '2', tilt: '90', 'frame-angle': '90', window: '600', epsilon: '0.01' };
// Machines whose report the page must give as `sphtroch clinostat ... --json` does, member for
// member: a fraction and a negative speed, a tilt, a frame angle, the CLI's defaults (empty tilt),
// a single-axis machine, a mean above epsilon (no time to epsilon), epsilon without a window.
const CLINOSTAT_MACHINES = [
  { outer: '4/3', inner: '-2.5', tilt: '60', 'frame-angle': '75', window: '90', epsilon: '0.1' },
  { outer: '3', inner: '0', tilt: '80', 'frame-angle': '90', window: '60', epsilon: '0.5' },
  { outer: '-1', inner: '2.5', tilt: '', 'frame-angle': '60', window: '120', epsilon: '0.05' },
  { outer: '5/7', inner: '1', tilt: '30', 'frame-angle': '90', window: '300', epsilon: '0.2' },
  { outer: '2', inner: '-3/4', tilt: '45', 'frame-angle': '', window: '', epsilon: '0.3' }];
const clinostatHash = (s) => hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }) + '&clinostat=on' +
  Object.keys(CLINOSTAT_DEFAULTS).map((k) => '&' + k + '=' + encodeURIComponent(s[k]).replace(/%2F/g, '/')).join('');
// `sphtroch clinostat` with the options given (an empty text is left out: the CLI's default).
const clinostatArgs = (s) => ['clinostat', ...Object.keys(CLINOSTAT_DEFAULTS).filter((k) => s[k] !== '').flatMap((k) => ['--' + k, s[k]])];

// The panel against `sphtroch clinostat --json` of the same texts: the report the page shows is
// the CLI's object, every number the same double (deep equality); the readouts show its members
// (their data attributes, shortest round-trip texts, read back to the same doubles); the gravity
// path is within 1e-14 of --trace at the same times.
function compareClinostat(got, s, where) {
  const run = cli([...clinostatArgs(s), '--json']);
  check(run.status === 0 && got.error === '', where + ': the CLI exited ' + run.status + ' (' + run.stderr + '), the page says "' + got.error + '"');
  if (run.status !== 0) return;
  const want = JSON.parse(run.stdout);
  const diff = got.report ? differences(got.report, want, () => 0, 'report') : ['no report shown'];
  check(diff.length === 0, where + ': the page\'s report is not the CLI\'s: ' + diff.slice(0, 6).join('; '));
  if (got.report) checkClinostatReadouts(got, got.report, s, where);
  const samples = got.path.length / 3;
  const rows = want.period_s === null ? [] : cli([...clinostatArgs(Object.assign({}, s, { window: '', epsilon: '' })), '--trace',
    '--duration', String(want.period_s), '--samples', String(samples + 1)]).stdout.trim().split('\n').slice(1);
  let worst = rows.length === samples + 1 ? 0 : Infinity;
  for (let k = 0; k < samples && worst < Infinity; ++k) {
    const g = rows[k].split(',').map(Number);
    worst = Math.max(worst, Math.hypot(g[1] - got.path[3 * k], g[2] - got.path[3 * k + 1], g[3] - got.path[3 * k + 2]));
  }
  check(samples >= 360 && worst <= 1e-14, where + ': the gravity path (' + samples + ' points) is ' + worst + ' from sphtroch clinostat --trace');
}

// The readouts show the report `r` (their data attributes: shortest round-trip texts of its
// members, read back to the same doubles; "no window given" and "no epsilon given" without them).
function checkClinostatReadouts(got, r, s, where) {
  const w = r.worst_window_mean, e = r.time_to_epsilon, t = r.train;
  const exact = (a, b) => (b === null || b === undefined ? a === '' || a === undefined : a !== '' && Number(a) === b);
  const shown = [['train', t ? ['n', 'a2', 'a3', 'phase'].every((k) => (k === 'n' ? got.train.n === t.n : exact(got.train[k], t[k])))
    : got.train.text === r.train_note], ['period', exact(got.period.value, r.period_s)],
  ['mean', ['x', 'y', 'z'].every((k, i) => exact(got.mean[k], r.mean_over_period[i]))],
  ['M(W)', w ? exact(got.worst.lower, w.lower) && exact(got.worst.upper, w.upper) && exact(got.worst.start, w.start_s) &&
    got.worst.certified === (w.certified ? '1' : '0') : s.window === '' && got.worst.text === 'no window given'],
  ['time to epsilon', e ? exact(got.time.first, e.first_s) && exact(got.time.stays, e.stays_below_from_s) &&
    got.time.certified === (e.certified ? '1' : '0') : s.epsilon === '' && got.time.text === 'no epsilon given']];
  const { path, ...readouts } = got;
  for (const [what, ok] of shown) check(ok, where + ': the readout ' + what + ' does not show the report: ' + JSON.stringify(readouts).slice(0, 600));
}

// The clinostat panel: `sphtroch clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01
// --json`'s object from the URL, the path drawn; the machines of CLINOSTAT_MACHINES, the first
// typed (its texts go into the hash, and a new load of that hash gives them back), the others
// opened from the URL, each the CLI's object; bad texts show the CLI's line and no number; "show
// its train above" makes the train the design; closing the panel takes it out of the hash.
async function checkClinostat(page) {
  await open(page, clinostatHash(CLINOSTAT_DEFAULTS));
  compareClinostat(await readClinostat(page), CLINOSTAT_DEFAULTS, 'clinostat 1.33/2');
  const dark = await page.evaluate(() => {
    const c = document.querySelector('[data-testid="clinostat-sphere"]'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let k = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] + d[i + 1] + d[i + 2] < 300 && d[i + 3] > 0) ++k;
    return k;
  });
  check(dark > 2000, 'clinostat: the gravity path is not drawn (' + dark + ' dark pixels)');
  const typed = CLINOSTAT_MACHINES[0];
  for (const k of Object.keys(CLINOSTAT_DEFAULTS)) await page.fill('[data-testid="clinostat-' + k + '"]', typed[k]);
  const shownTyped = await readClinostat(page);
  check(decodeURIComponent(shownTyped.hash) === decodeURIComponent(clinostatHash(typed)),
    'clinostat: the hash ' + shownTyped.hash + ' != ' + clinostatHash(typed));
  compareClinostat(shownTyped, typed, 'clinostat typed ' + JSON.stringify(typed));
  await page.goto('about:blank');  // a new page load from the hash, not a change of the hash
  await open(page, shownTyped.hash);
  const reopened = await readClinostat(page);
  const fields = await page.evaluate(() => window.sphtrochExplorer.state());
  check(Object.keys(typed).every((k) => fields[k] === typed[k]) && fields.clinostat === 'on',
    'clinostat: the hash did not give back the texts: ' + JSON.stringify(fields));
  compareClinostat(reopened, typed, 'clinostat reopened ' + JSON.stringify(typed));
  for (const s of CLINOSTAT_MACHINES.slice(1)) {
    await open(page, clinostatHash(s));
    compareClinostat(await readClinostat(page), s, 'clinostat ' + JSON.stringify(s));
  }
  await checkClinostatRefusals(page);
  await open(page, clinostatHash(CLINOSTAT_DEFAULTS));
  const shown = await readClinostat(page);
  await page.click('#clinostat-use-train');
  const design = await page.evaluate(() => window.sphtrochExplorer.state());
  check(design.n === shown.train.n && design.a2 === shown.train.a2 && design.a3 === shown.train.a3 && design.phase === shown.train.phase,
    'clinostat: "show its train above" gave ' + JSON.stringify(design) + ' for ' + JSON.stringify(shown.train));
  await page.uncheck('[data-testid="clinostat-on"]');
  check(!/clinostat|outer=/.test(await page.evaluate(() => window.location.hash)), 'clinostat: off, the hash still carries the panel');
}

// Bad texts: the CLI's one line (its stderr, exit 2) and no number of the panel left.
async function checkClinostatRefusals(page) {
  for (const [field, value] of [['outer', 'abc'], ['outer', '5000'], ['tilt', '200'], ['window', '-1'], ['epsilon', 'x'],
    ['epsilon', '1e-9']]) {
    const s = Object.assign({}, CLINOSTAT_DEFAULTS, { [field]: value });
    await open(page, clinostatHash(CLINOSTAT_DEFAULTS));
    await readClinostat(page);
    await page.fill('[data-testid="clinostat-' + field + '"]', value);
    const got = await readClinostat(page);
    const want = cli(clinostatArgs(s));
    check(want.status === 2 && got.error === want.stderr, 'clinostat ' + field + ' = ' + value + ': page "' + got.error + '" != CLI "' + want.stderr + '"');
    check(['train', 'period', 'mean', 'worst', 'time'].every((id) => got[id].text === '') && got.command === '' && got.report === null,
      'clinostat ' + field + ' = ' + value + ': a number is still shown: ' + JSON.stringify(got).slice(0, 300));
  }
}

// The chain panel: a chain given in the URL is drawn with its census, the SVG the bytes of `sphtroch
// chain plot`, the census object `chain classify --json`'s: the same members, counts, class,
// certificate and strings; the node and cusp numbers within 1e-12 (the certified engine's boxes
// are rounded outward by an ulp to nearest in the module, in directed rounding natively, so a node
// refined to the same box width may land a few ulp apart: measured 1.8e-14), every other number
// the same double; a two-stage chain is offered as the page's gear
// train (gear_train_of: a2 = A1, a3 = A2, n = N2 / N1) and "show it above" makes it the design, with
// chain classify's node count; bad texts show the CLI's line and no picture.
async function readChain(page) {
  await page.waitForFunction(() => ['done', 'error'].includes(document.querySelector('[data-testid="chain-status"]').dataset.state),
    null, { timeout: 60000 });
  return page.evaluate(() => {
    const cell = (id) => document.querySelector('[data-testid="chain-' + id + '"]');
    return { svg: window.sphtrochExplorer.chainSvg(), error: cell('error').textContent, census: Object.assign({}, cell('census').dataset),
      object: window.sphtrochExplorer.chainCensus(), command: cell('command').textContent, train: Object.assign({}, cell('train').dataset),
      hash: window.location.hash };
  });
}

const chainHash = (c) => hashOf({ a2: 'pi/3', a3: 'pi/2', n: '2', phase: '0' }) + '&twists=' + encodeURIComponent(c.twists) +
  '&rates=' + encodeURIComponent(c.rates).replace(/%2F/g, '/') + (c.phases ? '&phases=' + encodeURIComponent(c.phases) : '');
const chainArgs = (c) => ['--twists', c.twists, '--rates', c.rates, ...(c.phases ? ['--phases', c.phases] : [])];
const chainTolerance = (where) => (/^census\.(nodes|cusps)\./.test(where) ? 1e-12 : 0);

async function checkChain(page) {
  const fs = require('fs');
  for (const c of [{ twists: 'pi/2,1.2,0.4', rates: '1,-2/3,5/3', phases: '0,0.3,-1' }, { twists: '1.2,0.9,0.7', rates: '1,2,-3', phases: '' },
    { twists: '1,2,0.5,1.1', rates: '1,2/3,-1,3', phases: '0.1,0,0,2' }]) {
    await open(page, chainHash(c));
    const got = await readChain(page);
    const file = path.join(outDir, 'cli_chain.svg');
    const plot = cli(['chain', 'plot', ...chainArgs(c), '-o', file]);
    const want = JSON.parse(cli(['chain', 'classify', ...chainArgs(c), '--json']).stdout), counts = want.counts;
    const where = JSON.stringify(c);
    check(plot.status === 0 && got.svg === fs.readFileSync(file, 'utf8'), where + ': the chain picture differs from sphtroch chain plot: ' + plot.stderr);
    const diff = got.object ? differences(got.object, want, chainTolerance, 'census') : ['no census shown'];
    check(diff.length === 0, where + ': the page\'s census is not chain classify --json\'s: ' + diff.slice(0, 6).join('; '));
    check(Number(got.census.nodes) === counts.nodes && Number(got.census.cusps) === counts.cusps && got.census.certified === '1',
      where + ': the chain census ' + JSON.stringify(got.census) + ' != chain classify ' + JSON.stringify(counts));
    check(got.error === '' && got.command.startsWith('sphtroch chain plot --twists'), where + ': ' + JSON.stringify(got).slice(0, 300));
  }
  // Two stages: the gear train, made the design by the button; its count is chain classify's.
  const two = { twists: '1,2', rates: '2,-6', phases: '0.3,0.5' };
  await open(page, chainHash(two));
  const got = await readChain(page);
  check(got.svg === '' && got.train.a2 === '1' && got.train.a3 === '2' && got.train.n === '-3', 'two stages: ' + JSON.stringify(got.train));
  await page.click('#chain-use-train');
  await page.waitForFunction(() => window.sphtrochExplorer.state().n === '-3');
  const shown = await readPage(page);
  const counts = JSON.parse(cli(['chain', 'classify', ...chainArgs(two), '--json']).stdout).counts;
  check(Number(shown.nodes) === counts.nodes, 'two stages: the design shows ' + shown.nodes + ' nodes, chain classify ' + counts.nodes);
  // Bad texts: the CLI's line, no picture.
  for (const bad of [{ twists: '1,2', rates: '1,2,3', phases: '' }, { twists: '1,4,1', rates: '1,2,3', phases: '' },
    { twists: '1,2,1', rates: '1,x,3', phases: '' }, { twists: '1,2,1', rates: '1,2,3', phases: '0,nan,0' }]) {
    await open(page, chainHash(bad));
    const r = await readChain(page);
    const want = cli(['chain', 'classify', ...chainArgs(bad)]);
    check(want.status === 2 && r.error === want.stderr && r.svg === '' && r.census.nodes === '' && r.object === null,
      'chain ' + JSON.stringify(bad) + ': page "' + r.error + '" != CLI "' + want.stderr + '"');
  }
}

(async () => {
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox'] });
  const page = await browser.newPage({ viewport: { width: 1400, height: 1100 } });
  const consoleErrors = [];
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
  page.on('pageerror', (e) => consoleErrors.push(e.message));
  try {
    for (const s of randomStates(20)) await checkState(page, s);
    await checkBadInput(page);
    await checkSliderAndMap(page);
    await checkSceneExport(page);
    await checkTraceAndPlotExports(page);
    await checkInverseDesign(page);
    await checkThroughPoints(page);
    await checkTolerance(page);
    await checkDrawn(page);
    await checkFigure3(page);
    await checkPalette(page);
    await checkMapHover(page);
    await checkMarkers(page);
    await checkViewFromCurve(page);
    await checkClinostat(page);
    await checkChain(page);
  } finally {
    await browser.close();
  }
  check(consoleErrors.length === 0, 'console errors: ' + consoleErrors.join(' | '));
  for (const f of failures) console.log('FAIL ' + f);
  console.log(failures.length === 0 ? 'PASS: 22 states, bad input, slider, map click, scene export, trace and plot exports, inverse design, through 3 points, tolerance, drawn, legend, cones, Fig. 3 certified, palette, map hover, markers, clinostat, chain' : failures.length + ' failures');
  process.exit(failures.length === 0 ? 0 : 1);
})().catch((e) => { console.log('FAIL ' + (e && e.stack ? e.stack : e)); process.exit(1); });
