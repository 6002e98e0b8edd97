// map.js — the design map for the current n: node counts of the (a2, a3) cells from a worker
// (worker_bundle.js: the module and map_worker.js, started from a Blob), coarse to fine, then the
// boundary curves over them; the legend by area with the count scale (palette.js); the cross at
// the current design; a click or a drag on the map moves the design; the certified margin's
// square and the tolerance box about the cross (X.tolerance, tolerance.js). A cell's count is the
// boundary set's count at its centre (node_count_off_events), not certified: the map says so.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;

  let worker = null;
  let map = null; // { size, counts, max, n }
  let colour = null; // count -> CSS colour (palette.js), for the current map
  let loci = null; // the boundary curves: [{kind, name, points: a2 a3 ...}]
  // The cells and the boundary curves are drawn once per worker message into an offscreen
  // canvas; a state change only copies it and draws the cross.
  let mapImage = null;

  function startMap() {
    if (worker) worker.terminate();
    map = null;
    loci = null;
    mapImage = null;
    byTestId('map-status').textContent = 'computing';
    worker = X.newWorker();
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
    worker.postMessage({ job: 'map', n: X.state.n, teeth: X.state.teeth, sizes: [16, 32, 64, 128] });
  }

  // The cell under a point of the map given as fractions (u across, v down) of its box:
  // {a2, a3 (its centre, radians), count}, or null before the first grid or off the map.
  function mapCell(u, v) {
    if (!map || !(u >= 0 && u < 1 && v > 0 && v <= 1)) return null;
    const i = Math.floor(u * map.size), j = Math.floor((1 - v) * map.size);
    return { a2: (i + 0.5) * Math.PI / map.size, a3: (j + 0.5) * Math.PI / map.size, count: map.counts[j * map.size + i] };
  }

  function renderMapImage() {
    const canvas = $('map');
    mapImage = document.createElement('canvas');
    mapImage.width = canvas.width;
    mapImage.height = canvas.height;
    const ctx = mapImage.getContext('2d');
    ctx.fillStyle = '#eef0f3';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (map) {
      const legend = legendCounts();
      colour = X.countPalette(map.counts, legend.shown.map((e) => e[0]));
      const cell = canvas.width / map.size;
      for (let j = 0; j < map.size; ++j)
        for (let i = 0; i < map.size; ++i) {
          ctx.fillStyle = colour(map.counts[j * map.size + i]);
          ctx.fillRect(i * cell, canvas.height - (j + 1) * cell, Math.ceil(cell), Math.ceil(cell));
        }
      renderLegend(legend);
    }
    if (loci) drawLoci(ctx, canvas);
  }

  function drawMap() {
    const canvas = $('map');
    const ctx = canvas.getContext('2d');
    if (!mapImage) renderMapImage();
    ctx.drawImage(mapImage, 0, 0);
    const result = X.result;
    if (result) {
      const x = result.a2 / Math.PI * canvas.width, y = canvas.height - result.a3 / Math.PI * canvas.height;
      ctx.beginPath();
      ctx.moveTo(x - 8, y); ctx.lineTo(x + 8, y); ctx.moveTo(x, y - 8); ctx.lineTo(x, y + 8);
      for (const [style, width] of [['#fff', 4], ['#000', 2]]) {  // a white halo: seen on every cell colour
        ctx.strokeStyle = style;
        ctx.lineWidth = width;
        ctx.stroke();
      }
      if (X.tolerance) drawToleranceSquares(ctx, canvas, x, y);
    }
  }

  // About the cross (x, y): the certified margin's square (magenta dashes; half-width `lower`, at least 3
  // pixels so that it shows) and the tolerance box (its colour the verdict).
  const VERDICT_COLOURS = { holds: '#1b7f3b', changes: '#b00020', undecided: '#8a6d00' };
  const MARGIN_COLOUR = '#e000e0';  // no cell colour is magenta (viridis runs purple-blue-green-yellow)
  function drawToleranceSquares(ctx, canvas, x, y) {
    const t = X.tolerance, scale = canvas.width / Math.PI;
    const half = Math.max(3, t.margin.lower * scale);
    ctx.save();
    ctx.strokeStyle = VERDICT_COLOURS[t.topology];
    ctx.lineWidth = 1.5;
    const w = Math.max(1, t.box.a2 * scale), h = Math.max(1, t.box.a3 * scale);
    ctx.strokeRect(x - w, y - h, 2 * w, 2 * h);
    // The margin's square over the box, magenta dashes with white between them (it stands out on
    // every cell colour).
    ctx.lineWidth = 2;
    ctx.strokeStyle = MARGIN_COLOUR;
    ctx.setLineDash([5, 3]);
    ctx.strokeRect(x - half, y - half, 2 * half, 2 * half);
    ctx.strokeStyle = '#ffffff';
    ctx.setLineDash([3, 5]);
    ctx.lineDashOffset = -5;
    ctx.strokeRect(x - half, y - half, 2 * half, 2 * half);
    ctx.restore();
  }


  // The boundary curves over the cells: a sample step apart in a2, a polyline runs on while its
  // points are consecutive samples (a locus resolved to the step: no line across a gap). Each on
  // a faint white halo, so that it shows on the dark and the light end of the count scale.
  function drawLoci(ctx, canvas) {
    const step = Math.PI / 180 * 1.5;  // map_worker.js: LOCUS_STEPS samples across (0, pi)
    for (const locus of loci) {
      ctx.beginPath();
      const p = locus.points;
      for (let i = 0; i < p.length; i += 2) {
        const x = p[i] / Math.PI * canvas.width, y = canvas.height - p[i + 1] / Math.PI * canvas.height;
        if (i === 0 || p[i] - p[i - 2] > step) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.strokeStyle = 'rgba(255,255,255,0.6)';
      ctx.lineWidth = 2.5;
      ctx.stroke();
      ctx.strokeStyle = locus.kind === 'tangency' ? 'rgba(0,0,0,0.7)' : 'rgba(29,111,216,0.9)';
      ctx.lineWidth = 1;
      ctx.stroke();
    }
  }

  // The legend by area: the (at most 8) node counts covering most of the map, sorted by count
  // (shown), and the others (rest), each [count, cells].
  function legendCounts() {
    const cells = new Map();
    for (const c of map.counts) cells.set(c, (cells.get(c) || 0) + 1);
    const byArea = Array.from(cells.entries()).sort((a, b) => b[1] - a[1] || a[0] - b[0]);
    return { shown: byArea.slice(0, 8).sort((a, b) => a[0] - b[0]), rest: byArea.slice(8) };
  }

  // The legend: the count scale (every count present, lowest to highest, in its colour; the
  // shown counts marked), then the shown counts, each with its share of the cells, and the rest
  // summed. data-count / data-cells on each entry (tests read them).
  function renderLegend({ shown, rest }) {
    const legend = $('map-legend');
    legend.textContent = '';
    legend.appendChild(countScale(shown, rest));
    const total = map.counts.length, share = (k) => (100 * k / total).toFixed(1) + '%';
    for (const [count, k] of shown) {
      const item = document.createElement('span');
      item.className = 'swatch';
      item.dataset.testid = 'legend-entry';
      item.dataset.count = count;
      item.dataset.cells = k;
      item.innerHTML = '<i style="background:' + colour(count) + '"></i>' +
        (count < 0 ? 'no train' : count + ' nodes') + ' <small>(' + share(k) + ')</small>';
      legend.appendChild(item);
    }
    if (rest.length > 0) {
      const cells = rest.reduce((sum, e) => sum + e[1], 0);
      const note = document.createElement('span');
      note.dataset.testid = 'legend-rest';
      note.dataset.counts = rest.length;
      note.dataset.cells = cells;
      note.dataset.largest = rest[0][1];
      note.dataset.values = rest.map((e) => e[0]).join(' ');
      note.textContent = ' and ' + rest.length + ' more counts on ' + share(cells) + ' (their place on the scale)';
      legend.appendChild(note);
    }
  }

  // The count scale: a bar of every count present (no train excluded), lowest to highest, each
  // its colour (a tick under the shown ones), with the lowest and highest count at its ends.
  function countScale(shown, rest) {
    const counts = shown.concat(rest).map((e) => e[0]).filter((c) => c >= 0).sort((a, b) => a - b);
    const marked = new Set(shown.map((e) => e[0]));
    const scale = document.createElement('div');
    scale.className = 'count-scale';
    scale.dataset.testid = 'count-scale';
    if (counts.length === 0) return scale;
    const bar = document.createElement('div');
    bar.className = 'bar';
    for (const c of counts) {
      const step = document.createElement('i');
      step.style.background = colour(c);
      step.title = c + ' nodes';
      step.dataset.count = c;
      if (marked.has(c)) step.className = 'shown';
      bar.appendChild(step);
    }
    scale.appendChild(bar);
    const ends = document.createElement('div');
    ends.className = 'ends';
    ends.innerHTML = '<span>' + counts[0] + '</span><span>node count (cells: at the centre, off events; not certified)</span><span>' +
      counts[counts.length - 1] + '</span>';
    scale.appendChild(ends);
    return scale;
  }

  function setupMapInput() {
    const canvas = $('map');
    let dragging = false;
    const pick = (ev) => {
      const rect = canvas.getBoundingClientRect();
      const u = (ev.clientX - rect.left) / rect.width, v = (ev.clientY - rect.top) / rect.height;
      const clamp = (a) => Math.min(Math.PI - 1e-3, Math.max(1e-3, a));
      X.state.a2 = clamp(u * Math.PI).toFixed(4);
      X.state.a3 = clamp((1 - v) * Math.PI).toFixed(4);
      X.fillFields();
      X.update(true);
    };
    canvas.addEventListener('pointerdown', (ev) => { dragging = true; canvas.setPointerCapture(ev.pointerId); pick(ev); });
    canvas.addEventListener('pointermove', (ev) => { if (dragging) pick(ev); });
    canvas.addEventListener('pointerup', () => { dragging = false; });
  }

  Object.assign(X, { startMap, drawMap, setupMapInput, mapCell });
}
