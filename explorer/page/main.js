// main.js — starts the explorer page: controls, readouts, the sphere view, the design map (in a
// worker) and the a3 ruler, all computed by the library's WebAssembly module (sphtroch.js). The
// page's scripts, loaded in this order by index.html, share window.Explorer (state.js):
//   state.js           the state, the URL hash, the text fields; compute and update
//   readouts.js        the readouts, the node list, the equivalent command
//   certificate.js     the readouts' certificate: certify() (the CLI's rule) in a worker
//   ruler.js           the a3 ruler and the list of events
//   sphere.js          the sphere view: projection, drawing, its input
//   palette.js         the count scale's colours (d3-scale-chromatic's viridis)
//   map.js             the design map: worker, cells, boundary curves, legend, its input
//   map_axes.js        the design map's axes in degrees and the hover readout
//   inverse_design.js  the wanted path, fit, through 3 points, the candidates
//   tolerance.js       the certified margin and the tolerance box (readouts; map.js draws them)
//   controls.js        text fields, sliders, hash changes
//   exports.js         trace CSV, sphere SVG, scene JSON, the command copied
//   clinostat.js       the clinostat panel: its texts, worker (clinostat_worker.js), path and M(W)
//   chain.js           the chain panel: its texts, worker (chain_worker.js), census and picture
//   main.js            this: the start
// Test contract (docs/explorer.md): data-testid nodes, crossings, tangencies, cusps, class, error,
// one data-testid="event" per a3 event (data-a3: shortest round-trip text, data-kind); the state
// lives in the URL hash (#a2=pi/3&a3=pi/2&n=2&phase=0) and is applied on load; body[data-ready]
// is "1" once the first state is drawn.
'use strict';
{
  const X = window.Explorer;

  function start(module) {
    X.lib = module;
    X.state = X.readHash();
    X.fillFields();
    X.setupControls();
    X.setupExports();
    X.setupSphereInput();
    X.setupMapInput();
    X.setupMapAxes();
    X.setupFit();
    X.setupTolerance();
    X.setupClinostat();
    X.setupChain();
    X.update(false);
    // For tests and automation: the state's texts and the node points shown (x0 y0 z0 x1 ...).
    window.sphtrochExplorer = { state: () => Object.assign({}, X.state),
      nodePositions: () => (X.result ? Array.from(X.result.nodePositions) : []),
      cuspPositions: () => (X.result ? Array.from(X.result.cuspPositions) : []),
      timing: () => Object.assign({}, X.timing), project: (p) => X.project(p), lib: module,
      // The clinostat panel's gravity path shown (x0 y0 z0 x1 ...; [] when none).
      clinostatPath: () => (X.clinostat && X.clinostat.path && X.clinostat.path.path ? Array.from(X.clinostat.path.path) : []),
      // The clinostat panel's report shown: the object of `sphtroch clinostat --json` (null when none).
      clinostatReport: () => (X.clinostat && X.clinostat.report && !X.clinostat.report.error ? X.clinostat.report : null),
      // The chain panel's picture as the module returned it (its SVG text; "" when none).
      chainSvg: () => (X.chain && X.chain.value && X.chain.value.text ? X.chain.value.text : ''),
      // The chain panel's census shown: the object of `sphtroch chain classify --json` (null when none).
      chainCensus: () => (X.chain && X.chain.value && X.chain.value.census ? X.chain.value.census : null) };
    document.body.dataset.ready = '1';
    window.requestAnimationFrame(X.animate);
  }

  createSphtroch().then(start);
}
