// tolerance.js — the certified margin of the current design and what a tolerance box about it
// keeps: the module's tolerance() (what `sphtroch tolerance` proves), run a moment after the view
// is drawn (the proof takes milliseconds, up to about a second on the hardest trains) and again
// when a half-width is edited. Sets X.tolerance, which map.js draws: the margin square and the
// tolerance box about the cross. The census it states is the readouts' (X.result), with its
// certificate (X.certificate, certificate.js): "not certified" until that certifies it. Test
// contract: data-testid="margin" (data-lower, data-upper: shortest round-trip texts),
// data-testid="tolerance" (data-verdict: holds | changes | undecided | error).
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;
  const DELAY_MS = 120;
  let timer = null;
  X.tolerance = null;

  function halfWidths() {
    return ['a2', 'a3', 'phase'].map((k) => $('tol-' + k + '-text').value.trim());
  }

  function show(margin, tolerance, verdict) {
    const m = byTestId('margin'), t = byTestId('tolerance');
    m.textContent = margin.text;
    m.dataset.lower = margin.lower || '';
    m.dataset.upper = margin.upper || '';
    t.textContent = tolerance;
    t.dataset.verdict = verdict;
    t.className = 'tolerance ' + verdict;
  }

  function scheduleTolerance() {
    if (timer) clearTimeout(timer);
    X.tolerance = null;
    show({ text: X.result ? 'proving …' : '' }, '', '');
    if (X.result) timer = setTimeout(computeTolerance, DELAY_MS);
  }

  function marginText(m) {
    const where = m.nearest ? ' to ' + m.nearest.name + ' at a2 = ' + X.fmt(m.nearest.a2) + ', a3 = ' + X.fmt(m.nearest.a3) : '';
    return X.fmt(m.lower) + ' … ' + X.fmt(m.upper) + ' rad' + where + (m.converged ? '' : ' (bracket wider than stated)');
  }

  function toleranceText(r) {
    const census = X.result.nodes + ' node(s), ' + X.result.cusps + ' cusp(s)';
    const c = X.certificate;
    const unchecked = c && c.certified ? '' : c ? ' (count not certified: run sphtroch tolerance)' : ' (count not certified yet)';
    if (r.topology === 'changes')
      return 'changes: ' + r.event.name + ' at a2 = ' + X.fmt(r.event.a2) + ', a3 = ' + X.fmt(r.event.a3) + ' lies in the box';
    if (r.topology === 'undecided') return 'undecided: ' + r.why;
    const moves = Array.from(r.nodes).concat(Array.from(r.cusps));
    const largest = moves.length === 0 ? null : Math.max(...moves);
    const move = largest === null ? '' : Number.isNaN(largest) ? '; a node move is not proved'
      : '; every node and cusp moves at most ' + X.fmt(largest) + ' rad';
    return 'holds: every train in the box draws ' + census + move + unchecked;
  }

  function computeTolerance() {
    timer = null;
    const s = X.state, [a2, a3, phase] = halfWidths();
    const r = X.lib.tolerance(s.a2, s.a3, s.n, s.phase, s.teeth, a2, a3, phase);
    if (r.error) {
      X.tolerance = null;
      show({ text: '' }, r.error, 'error');
    } else {
      X.tolerance = r;
      refreshToleranceText();
    }
    X.drawMap();
  }

  // Shows X.tolerance (again when the certificate arrives: the text states it).
  function refreshToleranceText() {
    const r = X.tolerance;
    if (!r) return;
    show({ text: marginText(r.margin), lower: X.lib.numberText(r.margin.lower), upper: X.lib.numberText(r.margin.upper) },
      toleranceText(r), r.topology);
  }

  function setupTolerance() {
    for (const k of ['a2', 'a3', 'phase']) $('tol-' + k + '-text').addEventListener('input', scheduleTolerance);
  }

  Object.assign(X, { scheduleTolerance, setupTolerance, refreshToleranceText });
}
