// chain.js — the chain panel: a rotation chain as `sphtroch chain` takes it (twists, rates,
// phases: the CLI's options and texts), its certified census and picture computed by the module in
// a worker (chain_worker.js: the chain census and chain_picture_svg, the bytes of `sphtroch chain
// plot`), shown with the census line and the equivalent command. A change while the worker runs
// ends it and starts another (state.js's panelWorker). Sets X.chain: {key, value, done} of the
// texts shown, or null while the panel is off; value is the module's object ({text: the SVG,
// census: the object `sphtroch chain classify --json` prints, JSON.parse of the module's text},
// {train} or {error}).
// A two-stage chain with both rates not 0 is a gear train: the module gives its a2, a3, n, phase,
// shown with a button that makes it the page's design (its census is the train's, as the CLI's).
// Test contract: data-testid="chain-on" (the panel's box), chain-FIELD (the texts), chain-status
// (data-state: computing | done | error), chain-error (the CLI's line or empty), chain-census
// (data-nodes, data-cusps, data-certified: 1 | 0), chain-command, chain-picture (the SVG),
// chain-train (the gear train's texts, data-a2, data-a3, data-n, data-phase; empty otherwise).
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;
  const jobs = X.panelWorker('chain', receive);
  X.chain = null;

  const textsOf = (s) => ({ twists: s.twists, rates: s.rates, phases: s.phases, markers: s.markers });

  function setStatus(state, text) {
    const status = byTestId('chain-status');
    status.dataset.state = state;
    status.textContent = text;
  }

  // Called after every change of the state: starts a job when the panel is on and its texts
  // differ from the ones shown (or being computed).
  function scheduleChain() {
    const on = X.state.chain === 'on';
    $('chain-panel').hidden = !on;
    const key = JSON.stringify(textsOf(X.state));
    if (on && X.chain && X.chain.key === key) return;
    X.chain = on ? { key, value: null, done: false } : null;
    if (!on) return jobs.stop();
    setStatus('computing', 'computing …');
    render();
    jobs.run({ texts: textsOf(X.state) });
  }

  // The newest job's answer (chain_worker.js): its value (the census as the library's JSON text),
  // then 'done'.
  function receive({ part, value }) {
    if (part !== 'value' || !X.chain) return;
    X.chain.value = value.json ? { text: value.text, census: JSON.parse(value.json) } : value;
    X.chain.done = true;
    render();
    setStatus(value.error ? 'error' : 'done', value.error ? 'refused' : 'done');
  }

  function renderTrain(t) {
    const cell = byTestId('chain-train');
    cell.querySelector('span').textContent = t ? 'a two-stage chain is the gear train a2 = ' + t.a2 + ', a3 = ' + t.a3 + ', n = ' + t.n +
      ', phase ' + t.phase + ':' : '';
    Object.assign(cell.dataset, t || { a2: '', a3: '', n: '', phase: '' });
    $('chain-use-train').hidden = !t;
  }

  // The gear train of a two-stage chain as the page's design.
  function useTrain() {
    const v = X.chain && X.chain.value, t = v && v.train;
    if (!t) return;
    Object.assign(X.state, { a2: t.a2, a3: t.a3, n: t.n, teeth: '', phase: t.phase });
    X.fillFields();
    X.update(true);
  }

  function render() {
    const c = X.chain, v = c && c.done ? c.value : null, ok = v && !v.error && !v.train;
    renderTrain(v && v.train ? v.train : null);
    byTestId('chain-error').textContent = v && v.error ? v.error : '';
    const census = byTestId('chain-census');
    const k = ok ? v.census : null;  // the object of `sphtroch chain classify --json`
    census.textContent = k ? k.counts.nodes + ' node(s), ' + k.counts.cusps + ' cusp(s), class ' + k.class + ', ' +
      (k.certified ? 'certified' : 'NOT CERTIFIED: ' + k.certificate.why) : '';
    Object.assign(census.dataset, k ? { nodes: k.counts.nodes, cusps: k.counts.cusps, certified: k.certified ? '1' : '0' }
      : { nodes: '', cusps: '', certified: '' });
    const s = X.state, shellWord = X.shellWord, words = ['sphtroch chain plot --twists', shellWord(s.twists), '--rates', shellWord(s.rates)];
    if (s.phases !== '') words.push('--phases', shellWord(s.phases));
    if (s.markers !== 'auto') words.push('--markers', s.markers);
    byTestId('chain-command').textContent = ok ? words.concat(['-o', 'chain.svg']).join(' ') : '';
    $('chain-picture').innerHTML = ok ? v.text : '';  // the library's SVG (its texts escaped by the library)
  }

  function setupChain() {
    for (const f of X.CHAIN_FIELDS) {
      $('chain-' + f).addEventListener('input', () => {
        X.state[f] = $('chain-' + f).value.trim();
        X.writeHash();
        scheduleChain();
      });
    }
    $('chain-use-train').addEventListener('click', useTrain);
    $('chain-on').addEventListener('change', () => {
      X.state.chain = $('chain-on').checked ? 'on' : 'off';
      X.writeHash();
      scheduleChain();
    });
  }

  Object.assign(X, { scheduleChain, setupChain });
}
