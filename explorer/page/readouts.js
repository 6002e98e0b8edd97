// readouts.js — the readouts of the current train: class and counts (the root census; their
// certificate is certificate.js's), ratio, period, z range, pitch cone, the nearest event of the
// ruler, the report's criteria, the equivalent `sphtroch classify` command and the list of node
// points and cusps.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;

  const fmt = (v) => (Math.abs(v) < 1e-3 && v !== 0 ? v.toExponential(3) : v.toFixed(6));

  function renderReadouts() {
    const r = X.result;
    const set = (id, text) => { byTestId(id).textContent = text; };
    for (const id of ['class', 'nodes', 'crossings', 'tangencies', 'cusps', 'ratio', 'period',
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
    set('ratio', r.n + (X.state.teeth ? ' (teeth ' + X.state.teeth + ')' : ''));
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
    X.result.nodePoints.forEach((node, i) => rows.push(['N' + (i + 1), node.kind, node.x, node.y, node.z]));
    const cp = X.result.cuspPositions;
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
    const ruler = X.ruler, result = X.result;
    if (!ruler || ruler.events.length === 0) return 'none at this a2';
    let best = null;
    for (const e of ruler.events) if (!best || Math.abs(e.a3 - result.a3) < Math.abs(best.a3 - result.a3)) best = e;
    return fmt(Math.abs(best.a3 - result.a3)) + ' rad to ' + best.name + ' at a3 = ' + best.text;
  }

  function shellWord(s) {
    return /^[A-Za-z0-9_.\/:+-]+$/.test(s) ? s : "'" + s.replace(/'/g, "'\\''") + "'";
  }

  function commandLine() {
    const s = X.state;
    const ratio = s.teeth !== '' ? '--teeth ' + shellWord(s.teeth) : '--n ' + shellWord(s.n);
    return 'sphtroch classify --a2 ' + shellWord(s.a2) + ' --a3 ' + shellWord(s.a3) + ' ' + ratio +
      ' --phase ' + shellWord(s.phase);
  }

  Object.assign(X, { fmt, renderReadouts, commandLine });
}
