// clinostat.js — the clinostat panel: a two-axis clinostat or random positioning machine as
// `sphtroch clinostat` takes it (outer and inner rpm, tilt, frame angle, the window W and epsilon:
// the CLI's options and texts), computed by the module in a worker (clinostat_worker.js: the
// library's report through the CLI's reader), shown as readouts (readouts.js), the gravity path on
// a sphere of its own (sphere.js's drawPathSphere; drag to turn) and M(W) against W with epsilon
// dashed (the library's curve of `--plot`). A change while the worker runs ends it and starts
// another. Sets X.clinostat: {key, report, path, windows, done} of the texts shown, or null while
// the panel is off: report is the object `sphtroch clinostat --json` prints (JSON.parse of the
// module's text; first without the window and epsilon, then with them), path and windows the
// module's objects; each may be {error}. The dwell map needs HEALPix, which the module does not
// have: readouts.js shows the command that draws it.
// Test contract: data-testid="clinostat-on" (the panel's box), clinostat-FIELD (the texts),
// clinostat-status (data-state: computing | done | error), the readouts of readouts.js.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;
  const view = { spin: 0.6, tilt: 0.35, zoom: 1, panX: 0, panY: 0 };
  const jobs = X.panelWorker('clinostat', receive);
  X.clinostat = null;

  const textsOf = (s) => Object.fromEntries(X.CLINOSTAT_FIELDS.map((f) => [f, s[f]]));

  function setStatus(state, text) {
    const status = byTestId('clinostat-status');
    status.dataset.state = state;
    status.textContent = text;
  }

  // Called after every change of the state: starts a job when the panel is on and its texts
  // differ from the ones shown (or being computed).
  function scheduleClinostat() {
    const on = X.state.clinostat === 'on';
    $('clinostat-panel').hidden = !on;
    const key = JSON.stringify(textsOf(X.state));
    if (on && X.clinostat && X.clinostat.key === key) return;
    X.clinostat = on ? { key, report: null, path: null, windows: null, done: false } : null;
    if (!on) return jobs.stop();
    setStatus('computing', 'computing …');
    render();
    jobs.run({ texts: textsOf(X.state) });
  }

  // The newest job's answers (clinostat_worker.js); a report is the library's JSON text.
  function receive({ part, value }) {
    if (!X.clinostat) return;
    if (part === 'done') X.clinostat.done = true;
    else X.clinostat[part] = part === 'report' && !value.error ? JSON.parse(value.json) : value;
    render();
    if (part === 'done') {
      const error = X.clinostatError(X.clinostat);
      setStatus(error ? 'error' : 'done', error ? 'refused' : 'done');
    }
  }

  function render() {
    X.renderClinostatReadouts(X.clinostat);
    drawPath();
    drawWindows();
  }

  function drawPath() {
    const c = X.clinostat;
    X.drawPathSphere($('clinostat-sphere'), view, c && c.path && !c.path.error ? c.path.path : null);
  }

  // M(W) (the upper ends of the brackets) against W, M on a logarithmic scale, epsilon dashed; the
  // library's note under it when the curve is the bound over every frame angle.
  function drawWindows() {
    const svg = $('clinostat-mw'), c = X.clinostat;
    svg.textContent = '';
    const w = c && c.windows && !c.windows.error ? c.windows : null;
    $('clinostat-mw-note').textContent = w ? w.note : '';
    if (!w) return;
    const width = Number(svg.getAttribute('width')), height = Number(svg.getAttribute('height'));
    const epsilon = w.epsilon;
    const top = Math.max(...w.upper, epsilon || 0);
    if (!(top > 0)) return;
    let floor = Math.max(top * 1e-6, Math.min(...Array.from(w.upper).filter((v) => v > 0), epsilon || Infinity));
    if (!(floor < top)) floor = top / 10;
    const x = (s) => 40 + (width - 50) * s / w.windows[w.windows.length - 1];
    const y = (m) => 10 + (height - 30) * (1 - Math.log(Math.max(m, floor) / floor) / Math.log(top / floor));
    const points = Array.from(w.windows, (s, k) => x(s).toFixed(1) + ',' + y(w.upper[k]).toFixed(1)).join(' ');
    const items = ['<polyline class="mw" points="' + points + '"/>',
      '<text x="40" y="' + (height - 4) + '">0 s</text>',
      '<text x="' + (width - 10) + '" y="' + (height - 4) + '" text-anchor="end">W = ' + X.lib.numberText(w.windows[w.windows.length - 1]) + ' s</text>',
      '<text x="2" y="14">' + top.toExponential(1) + '</text>', '<text x="2" y="' + (height - 20) + '">' + floor.toExponential(1) + '</text>'];
    if (epsilon !== null) items.push('<line class="epsilon" x1="40" x2="' + (width - 10) + '" y1="' + y(epsilon) + '" y2="' + y(epsilon) + '"/>');
    svg.innerHTML = items.join('');
  }

  // The current panel's train as the explorer's design (a2, a3, n, phase as the module's shortest texts).
  function useTrain() {
    const c = X.clinostat, t = c && c.report && !c.report.error ? c.report.train : null;
    if (!t) return;
    Object.assign(X.state, { a2: X.lib.numberText(t.a2), a3: X.lib.numberText(t.a3), n: t.n, teeth: '',
      phase: X.lib.numberText(t.phase) });
    X.fillFields();
    X.update(true);
  }

  function setupClinostat() {
    for (const f of X.CLINOSTAT_FIELDS) {
      $('clinostat-' + f).addEventListener('input', () => {
        X.state[f] = $('clinostat-' + f).value.trim();
        X.writeHash();
        scheduleClinostat();
      });
    }
    $('clinostat-on').addEventListener('change', () => {
      X.state.clinostat = $('clinostat-on').checked ? 'on' : 'off';
      X.writeHash();
      scheduleClinostat();
    });
    $('clinostat-use-train').addEventListener('click', useTrain);
    X.turnOnDrag($('clinostat-sphere'), view, drawPath);
  }

  Object.assign(X, { scheduleClinostat, setupClinostat });
}
