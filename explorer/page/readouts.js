// readouts.js — the readouts of the current train: class and counts (the root census; their
// certificate is certificate.js's), ratio, period, z range, pitch cone, the nearest event of the
// ruler, the report's criteria, the equivalent `sphtroch classify` command and the list of node
// points and cusps.
// And the clinostat panel's readouts (X.clinostat, clinostat.js): the CLI's one line when refused;
// else the members of the report of `sphtroch clinostat --json` (the train, period, mean over a
// period, M(W), time to epsilon, in the CLI's shortest texts), the equivalent `sphtroch clinostat`
// command and the one that draws the dwell map.
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

  // ---- the clinostat panel ------------------------------------------------------------------
  // The report is the object of `sphtroch clinostat --json` (X.clinostat.report: its members, in
  // its names and units). Test contract: data-testid clinostat-error (the CLI's line or empty),
  // clinostat-train (data-n, data-a2, data-a3, data-phase), clinostat-period (data-value),
  // clinostat-mean (data-x, data-y, data-z), clinostat-worst (M(W): data-lower, data-upper,
  // data-start, data-certified: 1 | 0), clinostat-time (to epsilon: data-first, data-stays, "" for
  // none; data-certified), clinostat-command, clinostat-coverage; numbers as shortest round-trip texts.
  const CLINOSTAT_CELLS = ['train', 'period', 'mean', 'worst', 'time', 'command', 'coverage'];
  const good = (v) => v && !v.error;

  // The first refusal (the report's, read in the CLI's order, then the pictures'), or "".
  function clinostatError(c) {
    for (const part of ['report', 'path', 'windows']) if (c && c[part] && c[part].error) return c[part].error;
    return '';
  }

  function setCell(id, text, data) {
    const cell = byTestId('clinostat-' + id);
    cell.textContent = text;
    for (const k of Object.keys(cell.dataset)) if (k !== 'testid') delete cell.dataset[k];
    Object.assign(cell.dataset, data || {});
  }

  function renderClinostatReadouts(c) {
    const error = clinostatError(c);
    byTestId('clinostat-error').textContent = error;
    for (const id of CLINOSTAT_CELLS) setCell(id, '');
    if (!c || error || !good(c.report)) return;
    const t = X.lib.numberText, r = c.report;
    if (r.train) {
      const deg = (v) => t(v * 180 / Math.PI);
      setCell('train', 'n = ' + r.train.n + ', a2 = ' + deg(r.train.a2) + ' deg, a3 = ' + deg(r.train.a3) + ' deg, phase = ' +
        t(r.train.phase) + ' rad', { n: r.train.n, a2: t(r.train.a2), a3: t(r.train.a3), phase: t(r.train.phase) });
    } else {
      setCell('train', r.train_note);
    }
    setCell('period', r.period_s === null ? 'none (the gravity does not move in the sample)'
      : t(r.period_s) + ' s (' + t(r.period_s / 60) + ' min)', { value: r.period_s === null ? '' : t(r.period_s) });
    const m = r.mean_over_period;
    setCell('mean', '(' + m.map((v) => t(v)).join(', ') + ') g0, |mean| = ' + t(Math.hypot(...m)) + ' g0',
      { x: t(m[0]), y: t(m[1]), z: t(m[2]) });
    renderWindowReadout(r.worst_window_mean);
    renderEpsilonReadout(r.time_to_epsilon);
    setCell('command', clinostatCommand(['--window', X.state.window], ['--epsilon', X.state.epsilon]));
    setCell('coverage', clinostatCommand(['--plot', 'clinostat.svg']));
  }

  const certifiedText = (w) => (w.certified ? ' (certified)' : ' (NOT CERTIFIED)');

  // M(W): the report's worst_window_mean (absent until the worker's second report).
  function renderWindowReadout(w) {
    if (X.state.window === '') return setCell('worst', 'no window given');
    if (!w) return setCell('worst', 'computing …');
    const t = X.lib.numberText;
    setCell('worst', 'M(' + t(w.window_s) + ' s) in [' + t(w.lower) + ', ' + t(w.upper) + '] g0, reached by the window starting at ' +
      t(w.start_s) + ' s' + certifiedText(w),
    { lower: t(w.lower), upper: t(w.upper), start: t(w.start_s), certified: w.certified ? '1' : '0' });
  }

  // The time to epsilon: the report's time_to_epsilon (absent until the worker's second report).
  function renderEpsilonReadout(e) {
    if (X.state.epsilon === '') return setCell('time', 'no epsilon given');
    if (!e) return setCell('time', 'computing …');
    const t = X.lib.numberText, data = { first: e.first_s === null ? '' : t(e.first_s),
      stays: e.stays_below_from_s === null ? '' : t(e.stays_below_from_s), certified: e.certified ? '1' : '0' };
    const text = e.first_s !== null ? 'the first window below ' + t(e.epsilon) + ' g0 is ' + t(e.first_s) + ' s; every window from ' +
      t(e.stays_below_from_s) + ' s on, of any length, is below' + (e.above_s === null ? '' : ' (one of ' + t(e.above_s) + ' s is above)') +
      '; windows in steps of ' + t(e.resolution_s) + ' s' + certifiedText(e)
      : (e.certified ? 'none: ' : 'NOT CERTIFIED: ') + e.reason;
    setCell('time', text, data);
  }

  // `sphtroch clinostat` for the machine's texts and the option pairs given (those with a text).
  function clinostatCommand(...options) {
    const s = X.state, words = ['sphtroch clinostat'];
    for (const [option, value] of [['--outer', s.outer], ['--inner', s.inner], ['--tilt', s.tilt], ['--frame-angle', s['frame-angle']],
      ...options]) if (value !== '') words.push(option, shellWord(value));
    return words.join(' ');
  }

  Object.assign(X, { fmt, renderReadouts, commandLine, shellWord, renderClinostatReadouts, clinostatError });
}
