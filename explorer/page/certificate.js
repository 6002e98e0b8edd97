// certificate.js — the certificate of the readouts' count: the module's certify(), the rule of
// `sphtroch classify` (exact/certified_census.hpp: the polyline census against the root census),
// run in a worker (census_worker.js) a moment after each change, since it takes milliseconds
// (report Fig. 3) to seconds (a dense curve, n = 133/200: about 13 s). Until it answers, the
// count check says the count is not certified yet; a change while it runs ends that worker and
// starts another. Sets X.certificate (certify()'s object, or null while none holds for the state
// shown). Test contract: data-testid="certified" with data-state = pending | certified |
// not-certified | error, or "" when no train is shown.
'use strict';
{
  const X = window.Explorer;
  const { byTestId } = X;
  const DELAY_MS = 150;  // a slider drag starts one census when it rests, not one per step
  let worker = null, busy = false, job = 0, timer = null;
  X.certificate = null;

  function show(state, text) {
    const cell = byTestId('certified');
    cell.dataset.state = state;
    cell.textContent = text;
  }

  function certificateText(c) {
    const last = c.runs[c.runs.length - 1];
    if (c.certified)
      return 'certified: two independent censuses agree (' + c.rootNodes + ' node(s); polyline census of ' +
        last.samples + ' samples)';
    return 'not certified: ' + (c.stopped || c.disagreement) + ' (root census ' + c.rootNodes + ', polyline census ' +
      last.nodes + '): run sphtroch classify';
  }

  function scheduleCertificate() {
    if (timer) clearTimeout(timer);
    ++job;  // an answer for an earlier state is dropped
    X.certificate = null;
    if (!X.result) { show('', ''); return; }
    show('pending', 'not certified yet: the certified census is running');
    timer = setTimeout(startCensus, DELAY_MS);
  }

  function startCensus() {
    timer = null;
    if (busy) { worker.terminate(); worker = null; }  // a census cannot be interrupted otherwise
    if (!worker) {
      worker = X.newWorker();
      worker.onmessage = receive;
    }
    busy = true;
    worker.postMessage({ job: 'certify', id: job, state: Object.assign({}, X.state) });
  }

  function receive(ev) {
    busy = false;
    if (ev.data.id !== job) return;
    const c = ev.data.certificate;
    if (c.error) {
      show('error', c.error);
      return;
    }
    X.certificate = c;
    show(c.certified ? 'certified' : 'not-certified', certificateText(c));
    X.refreshToleranceText();
  }

  Object.assign(X, { scheduleCertificate });
}
