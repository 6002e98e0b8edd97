// census_worker.js — the readouts' certificate in the page's worker (run from a Blob with
// sphtroch.js before it; see bundle_worker.js): for a message {job: 'certify', id, state} (the
// texts a2, a3, n, teeth, phase), the module's certify() — the certified census of `sphtroch
// classify`, milliseconds to seconds — posted as {id, certificate} (certify()'s object, or
// {error}). The module is instantiated once per worker, at its first job.
'use strict';
let censusModule = null;
self.addEventListener('message', (ev) => {
  if (ev.data.job !== 'certify') return;
  const { id, state: s } = ev.data;
  if (!censusModule) censusModule = createSphtroch();
  censusModule.then((lib) => {
    self.postMessage({ id, certificate: lib.certify(s.a2, s.a3, s.n, s.phase, s.teeth) });
  });
});
