// map_worker.js — the design map's jobs in the page's worker (run from a Blob with sphtroch.js
// before it; see bundle_worker.js): for a message {job: 'map', n, teeth, sizes}, the boundary
// set's node count (node_count_off_events, not certified) of the (a2, a3) cells for one n, grid
// after grid, coarse to fine, each posted as {size, counts, max, done, seconds} (counts row-major
// from the lowest a3; -1: no train there), then the boundary curves as {loci, seconds}; or {error}.
'use strict';
// a2 samples of the boundary curves: ~10 ms each here (boundary_events.hpp: the scan in double).
const LOCUS_STEPS = 180;
self.addEventListener('message', (ev) => {
  if (ev.data.job !== 'map') return;
  const { n, teeth, sizes } = ev.data;
  createSphtroch().then((lib) => {
    const start = performance.now();
    for (const size of sizes) {
      const r = lib.mapCounts(n, teeth, 0, Math.PI, 0, Math.PI, size, size);
      if (r.error) {
        self.postMessage({ error: r.error });
        return;
      }
      let max = 0;
      for (const c of r.counts) max = Math.max(max, c);
      const done = size === sizes[sizes.length - 1];
      self.postMessage({ size, counts: r.counts, max, done, seconds: (performance.now() - start) / 1000 });
    }
    const l = lib.loci(n, teeth, LOCUS_STEPS);
    if (!l.error) self.postMessage({ loci: l.loci, seconds: (performance.now() - start) / 1000 });
  });
});
