// chain_worker.js — the chain panel's job in the page's worker (run from a Blob with sphtroch.js
// before it; see bundle_worker.js): for a message {job: 'chain', id, texts} (twists, rates,
// phases: the options of `sphtroch chain`; markers: `--markers`), the module's chainPlot() ({text:
// `sphtroch chain plot`'s SVG, json: the JSON text of `sphtroch chain classify --json`}, {train} for
// a gear train, or {error}: the CLI's line) posted as {id, part: 'value', value}, then {id, part:
// 'done'}. The module is instantiated once per worker, at its first job.
'use strict';
let chainModule = null;

self.addEventListener('message', (ev) => {
  if (ev.data.job !== 'chain') return;
  const { id, texts } = ev.data;
  if (!chainModule) chainModule = createSphtroch();
  chainModule.then((lib) => {
    self.postMessage({ id, part: 'value', value: lib.chainPlot(texts.twists, texts.rates, texts.phases, texts.markers) });
    self.postMessage({ id, part: 'done' });
  });
});
