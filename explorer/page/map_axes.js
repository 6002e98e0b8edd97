// map_axes.js — reading the design map: its axes in degrees (a2 across, a3 up, 0..180°, a tick
// every 30°) beside the canvas, and the hover readout: the pointer over the map shows the cell
// under it (its centre's a2 and a3 in degrees and radians, and its count: the boundary set's
// count, not certified) without moving the design (a click or a drag moves it: map.js). Test
// contract: data-testid="map-hover" with data-a2, data-a3 (radians, the cell's centre) and
// data-count, empty off the map.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;
  const TICK_DEGREES = 30;

  function drawAxes() {
    for (const [axis, side] of [['a2', 'left'], ['a3', 'top']]) {
      const box = byTestId('map-axis-' + axis);
      box.textContent = '';
      for (let d = 0; d <= 180; d += TICK_DEGREES) {
        const tick = document.createElement('span');
        tick.textContent = d + '°';
        tick.style[side] = (axis === 'a2' ? d / 180 : 1 - d / 180) * 100 + '%';
        box.appendChild(tick);
      }
    }
  }

  function showCell(ev) {
    const canvas = $('map'), out = byTestId('map-hover');
    const rect = canvas.getBoundingClientRect();  // the cells fill the canvas inside its border
    const x = ev.clientX - rect.left - canvas.clientLeft, y = ev.clientY - rect.top - canvas.clientTop;
    const cell = X.mapCell(x / canvas.clientWidth, y / canvas.clientHeight);
    if (!cell) { clearCell(); return; }
    const angle = (v) => (v * 180 / Math.PI).toFixed(2) + '° (' + v.toFixed(4) + ' rad)';
    out.textContent = 'a2 = ' + angle(cell.a2) + ', a3 = ' + angle(cell.a3) + ': ' +
      (cell.count < 0 ? 'no train' : cell.count + ' nodes') + ' (the cell centre\'s count off events, not certified)';
    Object.assign(out.dataset, { a2: cell.a2, a3: cell.a3, count: cell.count });
  }

  function clearCell() {
    const out = byTestId('map-hover');
    out.textContent = '';
    for (const k of ['a2', 'a3', 'count']) delete out.dataset[k];
  }

  function setupMapAxes() {
    drawAxes();
    $('map').addEventListener('pointermove', showCell);
    $('map').addEventListener('pointerleave', clearCell);
  }

  X.setupMapAxes = setupMapAxes;
}
