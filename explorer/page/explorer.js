// explorer.js — the explorer page: controls, readouts, the sphere view, the design map (in a
// worker) and the a3 ruler, all computed by the library's WebAssembly module (sphtroch.js).
// Test contract (docs/explorer.md): data-testid nodes, crossings, tangencies, cusps, class, error,
// one data-testid="event" per a3 event (data-a3: shortest round-trip text, data-kind); the state
// lives in the URL hash (#a2=pi/3&a3=pi/2&n=2&phase=0) and is applied on load; body[data-ready]
// is "1" once the first state is drawn.
'use strict';

(function () {
  const FIELDS = ['a2', 'a3', 'n', 'teeth', 'phase'];
  const DEFAULT_STATE = { a2: 'pi/3', a3: 'pi/2', n: '2', teeth: '', phase: '0' };
  const $ = (id) => document.getElementById(id);
  const byTestId = (id) => document.querySelector('[data-testid="' + id + '"]');

  let lib = null;
  let state = Object.assign({}, DEFAULT_STATE);
  let result = null; // classify() of the current state, or null after an error
  let curve = null; // trace() of the current state
  let ruler = null; // events() at the current a2 and n
  const view = { spin: 0.5, tilt: 1.1, zoom: 1, panX: 0, panY: 0, theta: 0 };

  // ---- state and the URL hash -----------------------------------------------------------------
  function readHash() {
    const s = Object.assign({}, DEFAULT_STATE);
    const hash = window.location.hash.replace(/^#/, '');
    if (hash === '') return s;
    // A malformed escape ("50%") is kept as typed: the parser then names it in the error line.
    const decode = (t) => { try { return decodeURIComponent(t); } catch (e) { return t; } };
    for (const part of hash.split('&')) {
      const eq = part.indexOf('=');
      if (eq < 0) continue;
      const key = decode(part.slice(0, eq));
      if (FIELDS.includes(key)) s[key] = decode(part.slice(eq + 1));
    }
    if (s.teeth !== '' && !/[#&]n=/.test('&' + hash)) s.n = ''; // teeth given instead of n
    return s;
  }

  function hashOf(s) {
    const enc = (v) => encodeURIComponent(v).replace(/%2F/g, '/').replace(/%3A/g, ':');
    const parts = ['a2=' + enc(s.a2), 'a3=' + enc(s.a3)];
    if (s.teeth !== '') parts.push('teeth=' + enc(s.teeth));
    if (s.n !== '' || s.teeth === '') parts.push('n=' + enc(s.n));
    parts.push('phase=' + enc(s.phase));
    return '#' + parts.join('&');
  }

  function fillFields() {
    for (const f of FIELDS) $(f + '-text').value = state[f];
  }

  function readFields() {
    const s = {};
    for (const f of FIELDS) s[f] = $(f + '-text').value.trim();
    return s;
  }

  // ---- computing ------------------------------------------------------------------------------
  function samplesFor(r) {
    return Math.min(200000, Math.max(2000, 600 * r.q * Math.min(40, Math.abs(r.p) + r.q)));
  }

  // The ruler's events depend on a2 and n only: kept while a3 or the phase moves.
  let eventsCache = { key: null, value: null };

  function eventsOf(s) {
    const key = s.a2 + '|' + s.n + '|' + s.teeth;
    if (eventsCache.key !== key) eventsCache = { key, value: lib.events(s.a2, s.n, s.teeth) };
    return eventsCache.value;
  }

  function compute() {
    const s = state;
    const c = lib.classify(s.a2, s.a3, s.n, s.phase, s.teeth);
    if (c.error) return { error: c.error };
    const t = lib.trace(s.a2, s.a3, s.n, s.phase, s.teeth, samplesFor(c), false);
    if (t.error) return { error: t.error };
    const e = eventsOf(s);
    if (e.error) return { error: e.error };
    return { c, t, e };
  }

  // Timings of the last update (ms), for bench/explorer.js: compute (the library) and all of it.
  const timing = { compute: 0, total: 0 };

  function update(pushHash) {
    const start = performance.now();
    const out = compute();
    timing.compute = performance.now() - start;
    if (out.error) {
      result = curve = ruler = null;
      byTestId('error').textContent = out.error;
    } else {
      byTestId('error').textContent = '';
      const mapKeyChanged = !result || result.n !== out.c.n;
      result = out.c;
      curve = out.t;
      ruler = out.e;
      if (mapKeyChanged) startMap();
      syncSliders();
    }
    if (pushHash) history.replaceState(null, '', hashOf(state));
    renderReadouts();
    renderRuler();
    drawSphere();
    drawMap();
    timing.total = performance.now() - start;
  }

  function syncSliders() {
    $('a2-slider').value = result.a2;
    $('a3-slider').value = result.a3;
    $('phase-slider').value = result.phase;
  }

  // ---- readouts --------------------------------------------------------------------------------
  const fmt = (v) => (Math.abs(v) < 1e-3 && v !== 0 ? v.toExponential(3) : v.toFixed(6));

  function renderReadouts() {
    const r = result;
    const set = (id, text) => { byTestId(id).textContent = text; };
    for (const id of ['class', 'nodes', 'crossings', 'tangencies', 'cusps', 'certified', 'ratio', 'period',
      'z-range', 'pitch-cone', 'nearest-event', 'command']) set(id, '');
    $('criteria').textContent = '';
    $('node-list').querySelector('tbody').textContent = '';
    byTestId('node-list-count').textContent = '0';
    if (!r) return;
    set('class', r.class);
    set('nodes', String(r.nodes));
    set('crossings', String(r.crossings));
    set('tangencies', String(r.tangencies));
    set('cusps', String(r.cusps));
    set('certified', r.certified ? 'two censuses agree (' + r.boundaryCount + ')'
      : 'not certified here (on a boundary or a tangency: run sphtroch classify)');
    set('ratio', r.n + (state.teeth ? ' (teeth ' + state.teeth + ')' : ''));
    set('period', '2π·' + r.q + ' = ' + fmt(r.period) + ' rad of carrier');
    set('z-range', fmt(r.zMin) + ' … ' + fmt(r.zMax));
    set('pitch-cone', fmt(r.planetCone) + ' rad (' + (r.planetCone * 180 / Math.PI).toFixed(4) + '°)');
    set('nearest-event', nearestEventText());
    set('command', commandLine());
    renderNodeList();
    for (const c of r.criteria) {
      const li = document.createElement('li');
      li.textContent = c.equation + ': ' + c.statement + ' — ' + c.status + ', margins ' + fmt(c.lowerMargin) +
        ' / ' + fmt(c.upperMargin) + (c.prediction ? ' (' + c.prediction + ')' : '');
      $('criteria').appendChild(li);
    }
  }

  // The node points (ids N1.., in the root census's order: by position, not matched to the ids of
  // `sphtroch plot`) and the cusps
  // (C1..); at most NODE_ROWS rows, the count says how many there are.
  const NODE_ROWS = 300;

  function renderNodeList() {
    const body = $('node-list').querySelector('tbody');
    body.textContent = '';
    const rows = [];
    result.nodePoints.forEach((node, i) => rows.push(['N' + (i + 1), node.kind, node.x, node.y, node.z]));
    const cp = result.cuspPositions;
    for (let i = 0; i < cp.length / 3; ++i) rows.push(['C' + (i + 1), 'cusp', cp[3 * i], cp[3 * i + 1], cp[3 * i + 2]]);
    byTestId('node-list-count').textContent = String(rows.length);
    for (const row of rows.slice(0, NODE_ROWS)) {
      const tr = document.createElement('tr');
      for (const v of row) {
        const td = document.createElement('td');
        td.textContent = typeof v === 'number' ? v.toFixed(9) : v;
        tr.appendChild(td);
      }
      body.appendChild(tr);
    }
    if (rows.length > NODE_ROWS) {
      const tr = document.createElement('tr');
      tr.innerHTML = '<td colspan="5">… ' + (rows.length - NODE_ROWS) + ' more: export the scene and run it for all</td>';
      body.appendChild(tr);
    }
  }

  function nearestEventText() {
    if (!ruler || ruler.events.length === 0) return 'none at this a2';
    let best = null;
    for (const e of ruler.events) if (!best || Math.abs(e.a3 - result.a3) < Math.abs(best.a3 - result.a3)) best = e;
    return fmt(Math.abs(best.a3 - result.a3)) + ' rad to ' + best.name + ' at a3 = ' + best.text;
  }

  function shellWord(s) {
    return /^[A-Za-z0-9_.\/:+-]+$/.test(s) ? s : "'" + s.replace(/'/g, "'\\''") + "'";
  }

  function commandLine() {
    const s = state;
    const ratio = s.teeth !== '' ? '--teeth ' + shellWord(s.teeth) : '--n ' + shellWord(s.n);
    return 'sphtroch classify --a2 ' + shellWord(s.a2) + ' --a3 ' + shellWord(s.a3) + ' ' + ratio +
      ' --phase ' + shellWord(s.phase);
  }

  // ---- the a3 ruler ---------------------------------------------------------------------------
  const SVG_NS = 'http://www.w3.org/2000/svg';

  function svgElement(name, attrs, text) {
    const el = document.createElementNS(SVG_NS, name);
    for (const k in attrs) el.setAttribute(k, attrs[k]);
    if (text !== undefined) el.textContent = text;
    return el;
  }

  function renderRuler() {
    const svg = $('ruler');
    const list = $('events');
    svg.textContent = '';
    list.textContent = '';
    if (!ruler || !result) return;
    const width = 960, left = 20, right = 940;
    const x = (a3) => left + (right - left) * a3 / Math.PI;
    svg.appendChild(svgElement('line', { x1: left, y1: 50, x2: right, y2: 50, class: 'axis' }));
    const cuts = [0].concat(ruler.events.map((e) => e.a3), [Math.PI]);
    for (let i = 0; i + 1 < cuts.length && ruler.events.length > 0; ++i) {
      const count = i < ruler.events.length ? ruler.events[i].nodesBelow : ruler.events[i - 1].nodesAbove;
      const mid = (x(cuts[i]) + x(cuts[i + 1])) / 2;
      if (x(cuts[i + 1]) - x(cuts[i]) > 18) svg.appendChild(svgElement('text', { x: mid, y: 42, class: 'count' }, String(count)));
    }
    for (const e of ruler.events) {
      const line = svgElement('line', { x1: x(e.a3), y1: 30, x2: x(e.a3), y2: 70, class: 'event ' + e.kind,
        'data-testid': 'event', 'data-a3': e.text, 'data-kind': e.kind });
      line.appendChild(svgElement('title', {}, e.name + ': a3 = ' + e.text + ', nodes ' + e.nodesBelow + ' → ' + e.nodesAbove));
      svg.appendChild(line);
      const li = document.createElement('li');
      li.textContent = 'a3 = ' + e.text + '  ' + e.kind + '  nodes ' + e.nodesBelow + ' → ' + e.nodesAbove + '  (' + e.name + ')';
      list.appendChild(li);
    }
    svg.appendChild(svgElement('path', { d: 'M' + x(result.a3) + ' 74 l-6 10 h12 z', class: 'current' }));
    svg.appendChild(svgElement('text', { x: left, y: 86, class: 'tick' }, '0'));
    svg.appendChild(svgElement('text', { x: right - 8, y: 86, class: 'tick' }, 'π'));
    svg.appendChild(svgElement('text', { x: left, y: 16, class: 'tick' }, 'a3 → (node count between events)'));
  }

  // ---- the sphere view ------------------------------------------------------------------------
  function project(p) {
    const cs = Math.cos(view.spin), ss = Math.sin(view.spin), ct = Math.cos(view.tilt), st = Math.sin(view.tilt);
    const x1 = cs * p[0] - ss * p[1], y1 = ss * p[0] + cs * p[1], z1 = p[2];
    const y2 = ct * y1 - st * z1, z2 = st * y1 + ct * z1; // tilt about the screen's x axis
    const canvas = $('sphere');
    const radius = 0.46 * canvas.width * view.zoom;
    return [canvas.width / 2 + view.panX + radius * x1, canvas.height / 2 + view.panY - radius * z2, y2 < 0];
  }

  function strokeRuns(ctx, points, count, frontStyle, backStyle, closed) {
    for (const front of [false, true]) {
      ctx.beginPath();
      let open = false;
      for (let k = 0; k <= count - (closed ? 0 : 1); ++k) {
        const i = k % count;
        const s = project([points[3 * i], points[3 * i + 1], points[3 * i + 2]]);
        if (s[2] === front) {
          if (open) ctx.lineTo(s[0], s[1]); else ctx.moveTo(s[0], s[1]);
          open = true;
        } else {
          open = false;
        }
      }
      ctx.strokeStyle = front ? frontStyle : backStyle;
      ctx.lineWidth = front ? 1.4 : 1;
      ctx.stroke();
    }
  }

  function circlePoints(axis, radius) {
    const w = axis;
    const u = Math.abs(w[2]) < 0.9 ? normalize(cross(w, [0, 0, 1])) : normalize(cross(w, [1, 0, 0]));
    const v = cross(w, u);
    const pts = new Float64Array(3 * 180);
    for (let k = 0; k < 180; ++k) {
      const phi = 2 * Math.PI * k / 180;
      for (let d = 0; d < 3; ++d)
        pts[3 * k + d] = Math.cos(radius) * w[d] + Math.sin(radius) * (Math.cos(phi) * u[d] + Math.sin(phi) * v[d]);
    }
    return pts;
  }

  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const normalize = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return [a[0] / l, a[1] / l, a[2] / l]; };

  function drawSphere() {
    const canvas = $('sphere');
    const ctx = canvas.getContext('2d');
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const centre = project([0, 0, 0]);
    ctx.beginPath();
    ctx.arc(centre[0], centre[1], 0.46 * canvas.width * view.zoom, 0, 2 * Math.PI);
    ctx.fillStyle = '#f4f6fa';
    ctx.fill();
    ctx.strokeStyle = '#9aa4b2';
    ctx.lineWidth = 1;
    ctx.stroke();
    if (!result || !curve) return;
    const pts = curve.points, count = pts.length / 3;
    strokeRuns(ctx, pts, count, '#1c2733', 'rgba(28,39,51,0.18)', true);
    // Nodes and cusps.
    const np = result.nodePositions;
    for (let i = 0; i < np.length / 3; ++i) {
      const s = project([np[3 * i], np[3 * i + 1], np[3 * i + 2]]);
      ctx.beginPath();
      ctx.arc(s[0], s[1], 3.2, 0, 2 * Math.PI);
      ctx.fillStyle = s[2] ? '#d62828' : 'rgba(214,40,40,0.3)';
      ctx.fill();
    }
    const cp = result.cuspPositions;
    for (let i = 0; i < cp.length / 3; ++i) {
      const s = project([cp[3 * i], cp[3 * i + 1], cp[3 * i + 2]]);
      ctx.beginPath();
      ctx.moveTo(s[0], s[1] - 5); ctx.lineTo(s[0] - 4.5, s[1] + 3.5); ctx.lineTo(s[0] + 4.5, s[1] + 3.5); ctx.closePath();
      ctx.fillStyle = s[2] ? '#f77f00' : 'rgba(247,127,0,0.35)';
      ctx.fill();
    }
    drawTrain(ctx);
    drawPath(ctx);
  }

  // The train at carrier angle theta: the sun's pitch circle (angle a_s about Z), the planet's
  // (angle a_p about its axis Rz(theta) Rx(a2) Z), touching where the cones roll, and the tracer.
  function drawTrain(ctx) {
    const r = result, theta = view.theta % r.period;
    const ap = r.planetCone, as = r.a2 - ap;
    const axis = [Math.sin(r.a2) * Math.sin(theta), -Math.sin(r.a2) * Math.cos(theta), Math.cos(r.a2)];
    const sunDrawn = as > 1e-9 && as < Math.PI - 1e-9;
    if ($('cones').checked) {
      if (sunDrawn) drawCone(ctx, [0, 0, 1], as, '29,111,216');
      drawCone(ctx, axis, ap, '42,157,75');
    }
    if (sunDrawn) strokeRuns(ctx, circlePoints([0, 0, 1], as), 180, '#1d6fd8', 'rgba(29,111,216,0.25)', true);
    strokeRuns(ctx, circlePoints(axis, ap), 180, '#2a9d4b', 'rgba(42,157,75,0.25)', true);
    const count = curve.points.length / 3;
    const i = Math.round(theta / r.period * count) % count;
    const tip = project([curve.points[3 * i], curve.points[3 * i + 1], curve.points[3 * i + 2]]);
    const hub = project(axis);
    ctx.beginPath();
    ctx.moveTo(hub[0], hub[1]);
    ctx.lineTo(tip[0], tip[1]);
    ctx.strokeStyle = '#2a9d4b';
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(tip[0], tip[1], 4.5, 0, 2 * Math.PI);
    ctx.fillStyle = '#7b2cbf';
    ctx.fill();
  }

  // A pitch cone: apex at the centre, half-angle `angle` about `axis`, its base the pitch circle on
  // the sphere: a light surface and a generator every 30 degrees (front solid, back faint).
  function drawCone(ctx, axis, angle, rgb) {
    const pts = circlePoints(axis, angle), count = pts.length / 3;
    const apex = project([0, 0, 0]);
    const at = (k) => project([pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]]);
    ctx.beginPath();
    for (let k = 0; k < count; ++k) {
      const a = at(k), b = at((k + 1) % count);
      ctx.moveTo(apex[0], apex[1]); ctx.lineTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.closePath();
    }
    ctx.fillStyle = 'rgba(' + rgb + ',0.08)';
    ctx.fill('nonzero');
    for (let k = 0; k < count; k += count / 12) {
      const a = at(k);
      ctx.beginPath();
      ctx.moveTo(apex[0], apex[1]);
      ctx.lineTo(a[0], a[1]);
      ctx.strokeStyle = 'rgba(' + rgb + ',' + (a[2] ? 0.45 : 0.12) + ')';  // project(): [2] is true in front
      ctx.lineWidth = 0.8;
      ctx.stroke();
    }
  }

  function setupSphereInput() {
    const canvas = $('sphere');
    let drag = null;
    canvas.addEventListener('pointerdown', (ev) => { drag = { x: ev.clientX, y: ev.clientY }; canvas.setPointerCapture(ev.pointerId); });
    canvas.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      view.spin += (ev.clientX - drag.x) * 0.01 / Math.sqrt(view.zoom);
      view.tilt += (ev.clientY - drag.y) * 0.01 / Math.sqrt(view.zoom);
      drag = { x: ev.clientX, y: ev.clientY };
      drawSphere();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
    $('cones').addEventListener('change', drawSphere);
    canvas.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      const rect = canvas.getBoundingClientRect();
      const cx = (ev.clientX - rect.left) * canvas.width / rect.width - canvas.width / 2;
      const cy = (ev.clientY - rect.top) * canvas.height / rect.height - canvas.height / 2;
      const factor = Math.exp(-ev.deltaY * 0.0015);
      const zoom = Math.min(1e5, Math.max(1, view.zoom * factor));
      const f = zoom / view.zoom;
      view.panX = zoom === 1 ? 0 : cx - (cx - view.panX) * f;
      view.panY = zoom === 1 ? 0 : cy - (cy - view.panY) * f;
      view.zoom = zoom;
      drawSphere();
    }, { passive: false });
  }

  function animate(time) {
    if ($('animate').checked && result) {
      view.theta = (time / 1000) * 0.6 * Math.max(1, result.q / 2);
      drawSphere();
    }
    window.requestAnimationFrame(animate);
  }

  // ---- the design map (node counts from a worker, coarse to fine) ------------------------------
  let worker = null;
  let map = null; // { size, counts, max, n }
  let loci = null; // the boundary curves: [{kind, name, points: a2 a3 ...}]

  function startMap() {
    if (worker) worker.terminate();
    map = null;
    loci = null;
    mapImage = null;
    byTestId('map-status').textContent = 'computing';
    const blob = new Blob([SPHTROCH_WORKER_SOURCE], { type: 'text/javascript' });
    worker = new Worker(URL.createObjectURL(blob));
    worker.onmessage = (ev) => {
      const m = ev.data;
      if (m.error) { byTestId('map-status').textContent = m.error; return; }
      if (m.loci) {
        loci = m.loci;
        byTestId('map-status').textContent = map.size + '² cells and the boundary curves, ' + m.seconds.toFixed(1) + ' s';
        mapImage = null;
        drawMap();
        return;
      }
      map = m;
      mapImage = null;
      byTestId('map-status').textContent = m.done ? m.size + '² cells, ' + m.seconds.toFixed(1) + ' s' : m.size + '² cells so far';
      drawMap();
    };
    worker.postMessage({ n: state.n, teeth: state.teeth, sizes: [16, 32, 64, 128] });
  }

  function countColour(count, max) {
    if (count < 0) return '#c9ccd1';
    if (count === 0) return '#ffffff';
    const t = Math.sqrt(count / Math.max(1, max));
    const hue = 210 - 200 * t, light = 88 - 50 * t;
    return 'hsl(' + hue + ',70%,' + light + '%)';
  }

  // The cells and the boundary curves are drawn once per worker message into an offscreen
  // canvas; a state change only copies it and draws the cross.
  let mapImage = null;

  function renderMapImage() {
    const canvas = $('map');
    mapImage = document.createElement('canvas');
    mapImage.width = canvas.width;
    mapImage.height = canvas.height;
    const ctx = mapImage.getContext('2d');
    ctx.fillStyle = '#eef0f3';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (map) {
      const cell = canvas.width / map.size;
      for (let j = 0; j < map.size; ++j)
        for (let i = 0; i < map.size; ++i) {
          ctx.fillStyle = countColour(map.counts[j * map.size + i], map.max);
          ctx.fillRect(i * cell, canvas.height - (j + 1) * cell, Math.ceil(cell), Math.ceil(cell));
        }
      renderLegend();
    }
    if (loci) drawLoci(ctx, canvas);
  }

  function drawMap() {
    const canvas = $('map');
    const ctx = canvas.getContext('2d');
    if (!mapImage) renderMapImage();
    ctx.drawImage(mapImage, 0, 0);
    if (result) {
      const x = result.a2 / Math.PI * canvas.width, y = canvas.height - result.a3 / Math.PI * canvas.height;
      ctx.strokeStyle = '#000';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.moveTo(x - 8, y); ctx.lineTo(x + 8, y); ctx.moveTo(x, y - 8); ctx.lineTo(x, y + 8);
      ctx.stroke();
    }
  }

  // The boundary curves over the cells: a sample step apart in a2, a polyline runs on while its
  // points are consecutive samples (a locus resolved to the step: no line across a gap).
  function drawLoci(ctx, canvas) {
    const step = Math.PI / 180 * 1.5;  // map_worker.js: LOCUS_STEPS samples across (0, pi)
    ctx.lineWidth = 1;
    for (const locus of loci) {
      ctx.strokeStyle = locus.kind === 'tangency' ? 'rgba(0,0,0,0.55)' : 'rgba(29,111,216,0.8)';
      ctx.beginPath();
      const p = locus.points;
      for (let i = 0; i < p.length; i += 2) {
        const x = p[i] / Math.PI * canvas.width, y = canvas.height - p[i + 1] / Math.PI * canvas.height;
        if (i === 0 || p[i] - p[i - 2] > step) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.stroke();
    }
  }

  // The legend by area: the (at most 8) node counts covering most of the map, each with its share
  // of the cells; the rest summed. data-count / data-cells on each entry (tests read them).
  function renderLegend() {
    const legend = $('map-legend');
    legend.textContent = '';
    const cells = new Map();
    for (const c of map.counts) cells.set(c, (cells.get(c) || 0) + 1);
    const byArea = Array.from(cells.entries()).sort((a, b) => b[1] - a[1] || a[0] - b[0]);
    const total = map.counts.length, share = (k) => (100 * k / total).toFixed(1) + '%';
    for (const [count, k] of byArea.slice(0, 8).sort((a, b) => a[0] - b[0])) {
      const item = document.createElement('span');
      item.className = 'swatch';
      item.dataset.testid = 'legend-entry';
      item.dataset.count = count;
      item.dataset.cells = k;
      item.innerHTML = '<i style="background:' + countColour(count, map.max) + '"></i>' +
        (count < 0 ? 'not certified' : count + ' nodes') + ' <small>(' + share(k) + ')</small>';
      legend.appendChild(item);
    }
    if (byArea.length > 8) {
      const rest = byArea.slice(8).reduce((sum, e) => sum + e[1], 0);
      const note = document.createElement('span');
      note.dataset.testid = 'legend-rest';
      note.dataset.counts = byArea.length - 8;
      note.dataset.cells = rest;
      note.dataset.largest = byArea[8][1];
      note.dataset.values = byArea.slice(8).map((e) => e[0]).join(' ');
      note.textContent = ' and ' + (byArea.length - 8) + ' more counts on ' + share(rest) + ' (a shade per count)';
      legend.appendChild(note);
    }
  }

  function setupMapInput() {
    const canvas = $('map');
    let dragging = false;
    const pick = (ev) => {
      const rect = canvas.getBoundingClientRect();
      const u = (ev.clientX - rect.left) / rect.width, v = (ev.clientY - rect.top) / rect.height;
      const clamp = (a) => Math.min(Math.PI - 1e-3, Math.max(1e-3, a));
      state.a2 = clamp(u * Math.PI).toFixed(4);
      state.a3 = clamp((1 - v) * Math.PI).toFixed(4);
      fillFields();
      update(true);
    };
    canvas.addEventListener('pointerdown', (ev) => { dragging = true; canvas.setPointerCapture(ev.pointerId); pick(ev); });
    canvas.addEventListener('pointermove', (ev) => { if (dragging) pick(ev); });
    canvas.addEventListener('pointerup', () => { dragging = false; });
  }

  // ---- inverse design: fit a path ------------------------------------------------------------
  // The wanted path: the textarea's points (drawn on the sphere as small squares). Shift-click on
  // the front of the sphere adds the point under the pointer (project() inverted).
  // (For drawing only: the fit reads the text with the CLI's reader.) Columns x, y, z by the
  // header's names when there is one, else the first three.
  function pathPoints() {
    const out = [];
    let columns = [0, 1, 2];
    for (const line of $('path-input').value.split('\n')) {
      const cells = line.split(',').map((c) => c.trim().replace(/^"|"$/g, '').toLowerCase());
      if (cells.some((c) => /[a-z]/.test(c) && !/^[-+.\d]+e[-+]?\d+$/.test(c))) {
        columns = ['x', 'y', 'z'].map((name) => cells.indexOf(name));
        continue;
      }
      const v = columns.map((k) => Number(cells[k]));
      if (v.every(Number.isFinite)) out.push(v);
    }
    return out;
  }

  function unproject(canvas, ev) {
    const rect = canvas.getBoundingClientRect();
    const radius = 0.46 * canvas.width * view.zoom;
    const x1 = ((ev.clientX - rect.left) * canvas.width / rect.width - canvas.width / 2 - view.panX) / radius;
    const z2 = -((ev.clientY - rect.top) * canvas.height / rect.height - canvas.height / 2 - view.panY) / radius;
    if (x1 * x1 + z2 * z2 >= 1) return null;
    const y2 = -Math.sqrt(1 - x1 * x1 - z2 * z2);  // the front half (project(): y2 < 0)
    const cs = Math.cos(view.spin), ss = Math.sin(view.spin), ct = Math.cos(view.tilt), st = Math.sin(view.tilt);
    const y1 = ct * y2 + st * z2, z1 = -st * y2 + ct * z2;
    return [cs * x1 + ss * y1, -ss * x1 + cs * y1, z1];
  }

  // The path as drawn: parsed when the text changes (not every frame), at most 2,000 squares.
  let pathShown = [];
  function pathChanged() {
    const all = pathPoints(), step = Math.max(1, Math.ceil(all.length / 2000));
    pathShown = all.filter((_, k) => k % step === 0);
    drawSphere();
  }

  function drawPath(ctx) {
    for (const p of pathShown) {
      const s = project(p);
      ctx.fillStyle = s[2] ? '#000' : 'rgba(0,0,0,0.3)';
      ctx.fillRect(s[0] - 2.5, s[1] - 2.5, 5, 5);
    }
  }

  // Runs search() (a module call) with the table and messages cleared first, so that a refusal
  // leaves no earlier result; shows its error line, or its status and rows.
  function runSearch(search, status, rows) {
    const body = byTestId('candidates').querySelector('tbody');
    body.textContent = '';
    byTestId('fit-error').textContent = '';
    byTestId('fit-status').textContent = '';
    const start = performance.now();
    let r;
    try {
      r = search();
    } catch (e) {  // the module returns errors; this is only for a failure of the module itself
      r = { error: 'sphtroch: internal error: ' + e };
    }
    if (r.error) {
      byTestId('fit-error').textContent = r.error;
      return;
    }
    byTestId('fit-status').textContent = status(r, (performance.now() - start).toFixed(0) + ' ms');
    rows(r).forEach((c, k) => body.appendChild(candidateRow(c, k)));
  }

  // Fits with the current n (or teeth), shows each candidate with the page's own census of it.
  function runFit() {
    runSearch(() => lib.fit($('path-input').value, state.n, state.teeth, $('fit-nodes').value.trim()),
      (r, ms) => r.candidates.length + ' candidate(s), ' + ms + (r.reason ? ': ' + r.reason : ''),
      (r) => r.candidates);
  }

  // Every train of the current n (or teeth) through exactly three points (sphtroch synth points),
  // certified or said not to be, and why; rms and max dev. are then the residual at the points.
  // A solution the search could not isolate (Newton's limit in an undecided box) says so.
  function runPoints() {
    const why = (r) => (r.boxes >= r.boxLimit
      ? 'NOT certified: the search stopped at its bound of ' + r.boxLimit + ' boxes (sphtroch synth points searches further)'
      : 'NOT certified: ' + r.undecided + ' box(es) stayed undecided (a near-singular root, e.g. a point at a node or cusp)');
    runSearch(() => lib.points($('path-input').value, state.n, state.teeth),
      (r, ms) => r.solutions.length + ' train(s) through the 3 points, ' + (r.certified ? 'all of them (certified)' : why(r)) + ', ' + ms,
      (r) => r.solutions.map((x) => Object.assign(x, { rms: x.residual, maxDeviation: x.residual, margin: NaN,
        note: x.isolated ? '' : 'root not proven single (undecided box)' })));
  }

  function candidateRow(c, k) {
    const texts = { a2: lib.numberText(c.a2), a3: lib.numberText(c.a3), phase: lib.numberText(c.phase) };
    const census = lib.classify(texts.a2, texts.a3, c.n, texts.phase, '');
    const row = document.createElement('tr');
    row.dataset.testid = 'candidate';
    Object.assign(row.dataset, { n: c.n, a2: texts.a2, a3: texts.a3, phase: texts.phase, isolated: c.isolated === false ? '0' : '1' });
    if (!census.error) Object.assign(row.dataset, { nodes: census.nodes, cusps: census.cusps, certified: census.certified ? '1' : '0' });
    const cells = [k + 1, c.n, fmt(c.a2), fmt(c.a3), fmt(c.phase), c.rms.toExponential(2), c.maxDeviation.toExponential(2),
      Number.isFinite(c.margin) ? fmt(c.margin) : '', census.error ? '' : census.nodes, census.error ? '' : census.cusps,
      (census.error ? census.error : census.certified ? 'two censuses agree' : 'not certified here') + (c.note ? '; ' + c.note : '')];
    for (const v of cells) row.appendChild(Object.assign(document.createElement('td'), { textContent: String(v) }));
    const use = Object.assign(document.createElement('button'), { type: 'button', textContent: 'use' });
    use.dataset.testid = 'use-candidate';
    use.addEventListener('click', () => {
      state = { a2: texts.a2, a3: texts.a3, n: c.n, teeth: '', phase: texts.phase };
      fillFields();
      update(true);
    });
    const last = document.createElement('td');
    last.appendChild(use);
    row.appendChild(last);
    return row;
  }

  function setupFit() {
    $('fit').addEventListener('click', runFit);
    $('through-points').addEventListener('click', runPoints);
    $('clear-path').addEventListener('click', () => { $('path-input').value = ''; pathChanged(); });
    $('path-input').addEventListener('input', pathChanged);
    $('sphere').addEventListener('click', (ev) => {
      if (!ev.shiftKey) return;
      const p = unproject($('sphere'), ev);
      if (!p) return;
      const area = $('path-input');
      if (area.value.trim() === '') area.value = 'x,y,z\n';
      else if (!area.value.endsWith('\n')) area.value += '\n';
      area.value += p.map((v) => lib.numberText(v)).join(',') + '\n';
      pathChanged();
    });
  }

  // ---- controls and exports -------------------------------------------------------------------
  function setupControls() {
    for (const f of FIELDS) {
      $(f + '-text').addEventListener('input', () => {
        // n and teeth exclude each other (as --n and --teeth): typing one clears the other.
        if (f === 'n' && $('n-text').value.trim() !== '') $('teeth-text').value = '';
        if (f === 'teeth' && $('teeth-text').value.trim() !== '') $('n-text').value = '';
        state = readFields();
        update(true);
      });
    }
    for (const f of ['a2', 'a3', 'phase']) {
      $(f + '-slider').addEventListener('input', (ev) => {
        state[f] = String(Number(ev.target.value));
        $(f + '-text').value = state[f];
        update(true);
      });
    }
    window.addEventListener('hashchange', () => { state = readHash(); fillFields(); update(false); });
    $('export-csv').addEventListener('click', () => {
      if (!curve) return;
      const lines = ['t,x,y,z'];
      for (let i = 0; i < curve.params.length; ++i)
        lines.push([curve.params[i], curve.points[3 * i], curve.points[3 * i + 1], curve.points[3 * i + 2]].map(lib.numberText).join(','));
      download('trace.csv', lines.join('\n') + '\n', 'text/csv');
    });
    $('export-svg').addEventListener('click', () => download('sphere.svg', sphereSvg(), 'image/svg+xml'));
    $('export-scene').addEventListener('click', () => download('explorer_scene.json', sceneJson(), 'application/json'));
    $('copy-command').addEventListener('click', () => navigator.clipboard && navigator.clipboard.writeText(commandLine()));
  }

  // The current train as a scene for `sphtroch scene FILE.json` (docs/cli.md): its texts as typed
  // (n as p/q when given as teeth), the trace, nodes, classification and plot as files.
  function sceneJson() {
    const s = state;
    const train = { name: 'explorer', a2: s.a2, a3: s.a3, n: s.teeth !== '' && result ? result.n : s.n, phase: s.phase,
      effects: { trace: 'explorer_trace.csv', nodes: 'explorer_nodes.csv', classification: 'explorer.json',
        plot: 'explorer.svg' } };
    return JSON.stringify({ description: 'from the sphtroch explorer: ' + window.location.hash, trains: [train] }, null, 1) + '\n';
  }

  function download(name, text, type) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type }));
    a.download = name;
    a.click();
  }

  function sphereSvg() {
    const canvas = $('sphere');
    const parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="' + canvas.width + '" height="' + canvas.height + '">'];
    if (curve) {
      const count = curve.points.length / 3;
      for (const front of [false, true]) {
        let d = '', open = false;
        for (let k = 0; k <= count; ++k) {
          const i = k % count;
          const s = project([curve.points[3 * i], curve.points[3 * i + 1], curve.points[3 * i + 2]]);
          if (s[2] === front) { d += (open ? 'L' : 'M') + s[0].toFixed(2) + ' ' + s[1].toFixed(2); open = true; } else open = false;
        }
        parts.push('<path fill="none" stroke="' + (front ? '#1c2733' : '#c8ccd2') + '" d="' + d + '"/>');
      }
    }
    parts.push('</svg>');
    return parts.join('\n');
  }

  // ---- start ----------------------------------------------------------------------------------
  createSphtroch().then((module) => {
    lib = module;
    state = readHash();
    fillFields();
    setupControls();
    setupSphereInput();
    setupMapInput();
    setupFit();
    update(false);
    // For tests and automation: the state's texts and the node points shown (x0 y0 z0 x1 ...).
    window.sphtrochExplorer = { state: () => Object.assign({}, state), nodePositions: () => (result ? Array.from(result.nodePositions) : []),
      cuspPositions: () => (result ? Array.from(result.cuspPositions) : []),
      timing: () => Object.assign({}, timing), project: (p) => project(p), lib };
    document.body.dataset.ready = '1';
    window.requestAnimationFrame(animate);
  });
})();
