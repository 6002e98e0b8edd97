// inverse_design.js — inverse design: the wanted path (the textarea's points, drawn on the sphere;
// a shift-click on the sphere adds one), fit (the trains of the current n nearest the path,
// `sphtroch synth fit`), through 3 points (every train through them, `sphtroch synth points`),
// and the candidates' rows with the page's own census of each (the root census, certified by
// the module's certify(): the CLI's rule, run here for each row) and a "use" button.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;

  // The wanted path: the textarea's points (drawn on the sphere as small squares). Shift-click on
  // the front of the sphere adds the point under the pointer (X.unproject).
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

  // The path as drawn: parsed when the text changes (not every frame), at most 2,000 squares.
  let pathShown = [];
  function pathChanged() {
    const all = pathPoints(), step = Math.max(1, Math.ceil(all.length / 2000));
    pathShown = all.filter((_, k) => k % step === 0);
    X.drawSphere();
  }

  function drawPath(ctx) {
    for (const p of pathShown) {
      const s = X.project(p);
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
    const s = X.state;
    runSearch(() => X.lib.fit($('path-input').value, s.n, s.teeth, $('fit-nodes').value.trim()),
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
    runSearch(() => X.lib.points($('path-input').value, X.state.n, X.state.teeth),
      (r, ms) => r.solutions.length + ' train(s) through the 3 points, ' + (r.certified ? 'all of them (certified)' : why(r)) + ', ' + ms,
      (r) => r.solutions.map((x) => Object.assign(x, { rms: x.residual, maxDeviation: x.residual, margin: NaN,
        note: x.isolated ? '' : 'root not proven single (undecided box)' })));
  }

  function candidateRow(c, k) {
    const lib = X.lib, fmt = X.fmt;
    const texts = { a2: lib.numberText(c.a2), a3: lib.numberText(c.a3), phase: lib.numberText(c.phase) };
    const census = lib.classify(texts.a2, texts.a3, c.n, texts.phase, '');
    if (!census.error) census.certified = lib.certify(texts.a2, texts.a3, c.n, texts.phase, '').certified === true;
    const row = document.createElement('tr');
    row.dataset.testid = 'candidate';
    Object.assign(row.dataset, { n: c.n, a2: texts.a2, a3: texts.a3, phase: texts.phase, isolated: c.isolated === false ? '0' : '1' });
    if (!census.error) Object.assign(row.dataset, { nodes: census.nodes, cusps: census.cusps, certified: census.certified ? '1' : '0' });
    const cells = [k + 1, c.n, fmt(c.a2), fmt(c.a3), fmt(c.phase), c.rms.toExponential(2), c.maxDeviation.toExponential(2),
      Number.isFinite(c.margin) ? fmt(c.margin) : '', census.error ? '' : census.nodes, census.error ? '' : census.cusps,
      (census.error ? census.error : census.certified ? 'certified: two censuses agree' : 'not certified: run sphtroch classify') +
      (c.note ? '; ' + c.note : '')];
    for (const v of cells) row.appendChild(Object.assign(document.createElement('td'), { textContent: String(v) }));
    const use = Object.assign(document.createElement('button'), { type: 'button', textContent: 'use' });
    use.dataset.testid = 'use-candidate';
    use.addEventListener('click', () => {
      X.state = Object.assign({}, X.state, { a2: texts.a2, a3: texts.a3, n: c.n, teeth: '', phase: texts.phase });
      X.fillFields();
      X.update(true);
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
      const p = X.unproject($('sphere'), ev);
      if (!p) return;
      const area = $('path-input');
      if (area.value.trim() === '') area.value = 'x,y,z\n';
      else if (!area.value.endsWith('\n')) area.value += '\n';
      area.value += p.map((v) => X.lib.numberText(v)).join(',') + '\n';
      pathChanged();
    });
  }

  Object.assign(X, { drawPath, setupFit });
}
