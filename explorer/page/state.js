// state.js — the explorer's state: the texts of a2, a3, n (or teeth) and the phase and the marker
// mode, kept in the URL hash and the controls, and update(): the library's results for them
// (classify, trace, the ruler's events, which markers to draw), then every view redrawn. Loaded first: it creates window.Explorer, the
// namespace the page's scripts share (classic scripts, not modules: a page opened from disk may
// not load modules). Each script keeps its names in a block and puts on the namespace only what
// the other scripts use; the shared state lives there too:
//   X.lib     the WebAssembly module (sphtroch.js), set by main.js
//   X.state   the texts {a2, a3, n, teeth, phase} and markers (auto | all | none)
//   X.result  classify() of the current state (the root census), or null after an error
//   X.marks   marks() of the current state: {draw, note, dense} (draw/mark_density.hpp's rule)
//   X.curve   trace() of the current state
//   X.ruler   events() at the current a2 and n
//   X.view    the sphere view {spin, tilt, zoom, panX, panY, theta}
//   X.tolerance  tolerance() of the current state and half-widths (tolerance.js), or null
// The clinostat panel's texts live in X.state too (clinostat: on | off, and the CLI's options
// outer, inner, tilt, frame-angle, window, epsilon), in the hash only while the panel is on.
// So do the chain panel's (chain: on | off, and `sphtroch chain`'s options twists, rates, phases),
// in the hash only while it is on; a hash giving twists turns it on (#twists=pi/2,1&rates=1,3).
'use strict';
window.Explorer = {};
{
  const X = window.Explorer;
  const FIELDS = ['a2', 'a3', 'n', 'teeth', 'phase'];  // the text fields (id FIELD-text)
  // The clinostat panel's text fields (id and data-testid clinostat-FIELD): `sphtroch clinostat`'s
  // options, the hash's keys.
  const CLINOSTAT_FIELDS = ['outer', 'inner', 'tilt', 'frame-angle', 'window', 'epsilon'];
  // The chain panel's text fields (id and data-testid chain-FIELD): `sphtroch chain`'s options.
  const CHAIN_FIELDS = ['twists', 'rates', 'phases'];
  const DEFAULT_STATE = { a2: 'pi/3', a3: 'pi/2', n: '2', teeth: '', phase: '0', markers: 'auto', clinostat: 'off',
    outer: '1.33', inner: '2', tilt: '90', 'frame-angle': '90', window: '600', epsilon: '0.01',
    chain: 'off', twists: 'pi/2,1.2,0.4', rates: '1,-2/3,5/3', phases: '0,0.3,-1' };
  const $ = (id) => document.getElementById(id);
  const byTestId = (id) => document.querySelector('[data-testid="' + id + '"]');

  Object.assign(X, { FIELDS, CLINOSTAT_FIELDS, CHAIN_FIELDS, $, byTestId, lib: null, state: Object.assign({}, DEFAULT_STATE), result: null, curve: null,
    ruler: null, marks: null, view: { spin: 0.5, tilt: 1.1, zoom: 1, panX: 0, panY: 0, theta: 0 } });

  // ---- the URL hash and the text fields -------------------------------------------------------
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
      if (key in DEFAULT_STATE) s[key] = decode(part.slice(eq + 1));
    }
    if (s.teeth !== '' && !/[#&]n=/.test('&' + hash)) s.n = ''; // teeth given instead of n
    if (/[#&]twists=/.test('&' + hash)) {  // a chain given: on, its rates and phases as given ("" when not)
      if (!/[#&]chain=/.test('&' + hash)) s.chain = 'on';
      for (const f of ['rates', 'phases']) if (!new RegExp('[#&]' + f + '=').test('&' + hash)) s[f] = '';
    }
    return s;
  }

  function hashOf(s) {
    const enc = (v) => encodeURIComponent(v).replace(/%2F/g, '/').replace(/%3A/g, ':');
    const parts = ['a2=' + enc(s.a2), 'a3=' + enc(s.a3)];
    if (s.teeth !== '') parts.push('teeth=' + enc(s.teeth));
    if (s.n !== '' || s.teeth === '') parts.push('n=' + enc(s.n));
    parts.push('phase=' + enc(s.phase));
    if (s.markers !== DEFAULT_STATE.markers) parts.push('markers=' + enc(s.markers));  // links stay short
    if (s.clinostat === 'on') for (const f of ['clinostat'].concat(CLINOSTAT_FIELDS)) parts.push(f + '=' + enc(s[f]));
    if (s.chain === 'on') for (const f of ['chain'].concat(CHAIN_FIELDS)) parts.push(f + '=' + enc(s[f]));
    return '#' + parts.join('&');
  }

  // The current state into the hash (a view is a link).
  function writeHash() {
    history.replaceState(null, '', hashOf(X.state));
  }

  function fillFields() {
    for (const f of FIELDS) $(f + '-text').value = X.state[f];
    $('markers').value = X.state.markers;
    for (const f of CLINOSTAT_FIELDS) $('clinostat-' + f).value = X.state[f];
    $('clinostat-on').checked = X.state.clinostat === 'on';
    for (const f of CHAIN_FIELDS) $('chain-' + f).value = X.state[f];
    $('chain-on').checked = X.state.chain === 'on';
  }

  function readFields() {
    const s = {};
    for (const f of FIELDS) s[f] = $(f + '-text').value.trim();
    s.markers = $('markers').value;
    for (const f of CLINOSTAT_FIELDS) s[f] = $('clinostat-' + f).value.trim();
    s.clinostat = $('clinostat-on').checked ? 'on' : 'off';
    for (const f of CHAIN_FIELDS) s[f] = $('chain-' + f).value.trim();
    s.chain = $('chain-on').checked ? 'on' : 'off';
    return s;
  }

  // ---- computing ------------------------------------------------------------------------------
  // A worker running the module and the page's worker jobs (worker_bundle.js: map_worker.js,
  // census_worker.js), started from a Blob: a page opened from disk may not start one from a file.
  function newWorker() {
    return new Worker(URL.createObjectURL(new Blob([SPHTROCH_WORKER_SOURCE], { type: 'text/javascript' })));
  }

  // A panel's job in a worker of its own (clinostat.js, chain.js): run(message) posts {job, id,
  // ...message} once typing rests (DELAY_MS), ending a worker still busy with an older job (a
  // search cannot be interrupted otherwise); onAnswer gets the messages of the newest job only,
  // which is over at its {part: 'done'}. stop() drops every job and ends the worker.
  function panelWorker(job, onAnswer) {
    const DELAY_MS = 120;  // typing starts one job when it rests, not one per key
    let worker = null, busy = false, id = 0, timer = null;
    function start(message) {
      timer = null;
      if (busy) { worker.terminate(); worker = null; }
      if (!worker) {
        worker = newWorker();
        worker.onmessage = (ev) => {
          if (ev.data.part === 'done') busy = false;
          if (ev.data.id === id) onAnswer(ev.data);
        };
      }
      busy = true;
      worker.postMessage(Object.assign({ job, id }, message));
    }
    return {
      run(message) {
        if (timer) clearTimeout(timer);
        ++id;  // an answer for an older message is dropped
        timer = setTimeout(() => start(message), DELAY_MS);
      },
      stop() {
        if (timer) clearTimeout(timer);
        timer = null;
        ++id;
        if (worker) worker.terminate();
        worker = null;
        busy = false;
      } };
  }

  // Samples of the drawn curve (and of the trace CSV export).
  function samplesFor(r) {
    return Math.min(200000, Math.max(2000, 600 * r.q * Math.min(40, Math.abs(r.p) + r.q)));
  }

  // The ruler's events depend on a2 and n only: kept while a3 or the phase moves.
  let eventsCache = { key: null, value: null };

  function eventsOf(s) {
    const key = s.a2 + '|' + s.n + '|' + s.teeth;
    if (eventsCache.key !== key) eventsCache = { key, value: X.lib.events(s.a2, s.n, s.teeth) };
    return eventsCache.value;
  }

  function compute() {
    const s = X.state, lib = X.lib;
    const c = lib.classify(s.a2, s.a3, s.n, s.phase, s.teeth);
    if (c.error) return { error: c.error };
    const t = lib.trace(s.a2, s.a3, s.n, s.phase, s.teeth, samplesFor(c), false);
    if (t.error) return { error: t.error };
    const e = eventsOf(s);
    if (e.error) return { error: e.error };
    const m = lib.marks(s.markers, c.nodes, c.cusps);
    if (m.error) return { error: m.error };
    return { c, t, e, m };
  }

  // Timings of the last update (ms), for bench/explorer.js: compute (the library) and all of it.
  const timing = { compute: 0, total: 0 };

  function update(pushHash) {
    const start = performance.now();
    const out = compute();
    timing.compute = performance.now() - start;
    if (out.error) {
      X.result = X.curve = X.ruler = X.marks = null;
      byTestId('error').textContent = out.error;
    } else {
      byTestId('error').textContent = '';
      const mapKeyChanged = !X.result || X.result.n !== out.c.n;
      // The view of `sphtroch plot` (chosen from the curve) when the page opens and when n
      // changes, until the sphere is turned by hand.
      if (mapKeyChanged && !X.view.turnedByHand) X.lookFrom(out.t.view);
      X.result = out.c;
      X.curve = out.t;
      X.ruler = out.e;
      X.marks = out.m;
      if (mapKeyChanged) X.startMap();
      syncSliders();
    }
    if (pushHash) writeHash();
    X.renderReadouts();
    X.scheduleCertificate();
    X.renderRuler();
    X.followDensity();
    X.drawSphere();
    X.drawMap();
    X.scheduleTolerance();
    X.scheduleClinostat();
    X.scheduleChain();
    timing.total = performance.now() - start;
  }

  function syncSliders() {
    $('a2-slider').value = X.result.a2;
    $('a3-slider').value = X.result.a3;
    $('phase-slider').value = X.result.phase;
  }

  Object.assign(X, { readHash, writeHash, fillFields, readFields, newWorker, panelWorker, samplesFor, update, timing });
}
