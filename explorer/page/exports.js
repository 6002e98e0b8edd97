// exports.js — the exports of the current train: the trace CSV and the sphere SVG are written by
// the library (the module's traceCsv and plotSvg: the bytes of `sphtroch trace --samples N` and
// of `sphtroch plot --markers MODE` for the same texts and the page's marker mode), the scene JSON for
// `sphtroch scene`, and the command line copied.
'use strict';
{
  const X = window.Explorer;
  const { $, byTestId } = X;

  function download(name, text, type) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type }));
    a.download = name;
    a.click();
  }

  // Downloads what make() (a module call) returns: {text}, or {error} shown as the page's error line.
  function downloadFromModule(name, type, make) {
    if (!X.result) return;  // no train: nothing to export
    const r = make(X.lib, X.state);
    if (r.error) byTestId('error').textContent = r.error;
    else download(name, r.text, type);
  }

  // The current train as a scene for `sphtroch scene FILE.json` (docs/cli.md): its texts as typed
  // (n as p/q when given as teeth), the trace, nodes, classification and plot as files. Written
  // here, not by the module: the library has the scene's reader only (exact/scene.hpp, in the
  // CGAL layer, not in the module) and no writer of it.
  function sceneJson() {
    const s = X.state, result = X.result;
    const train = { name: 'explorer', a2: s.a2, a3: s.a3, n: s.teeth !== '' && result ? result.n : s.n, phase: s.phase,
      effects: { trace: 'explorer_trace.csv', nodes: 'explorer_nodes.csv', classification: 'explorer.json',
        plot: 'explorer.svg' } };
    return JSON.stringify({ description: 'from the sphtroch explorer: ' + window.location.hash, trains: [train] }, null, 1) + '\n';
  }

  function setupExports() {
    // The samples drawn (X.samplesFor): `sphtroch trace ... --samples N` writes the same bytes.
    $('export-csv').addEventListener('click', () => downloadFromModule('trace.csv', 'text/csv',
      (lib, s) => lib.traceCsv(s.a2, s.a3, s.n, s.phase, s.teeth, X.samplesFor(X.result))));
    $('export-svg').addEventListener('click', () => downloadFromModule('sphere.svg', 'image/svg+xml',
      (lib, s) => lib.plotSvg(s.a2, s.a3, s.n, s.phase, s.teeth, s.markers)));
    $('export-scene').addEventListener('click', () => download('explorer_scene.json', sceneJson(), 'application/json'));
    $('copy-command').addEventListener('click', () => navigator.clipboard && navigator.clipboard.writeText(X.commandLine()));
  }

  X.setupExports = setupExports;
}
