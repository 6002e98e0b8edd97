// node wasm_dump.js SPHTROCH_JS < trains.json > results.json — what the explorer's WebAssembly
// module computes for each train {a2, a3, n, phase} (the CLI's texts): the root census counts,
// class, node points, trace(samples) points and the boundary events at its a2, and for a train
// with `certify` set the certificate of certify() (certified, rootNodes); or {error}. Used by
// test_wasm_vs_native.py.
'use strict';
const fs = require('fs');
const create = require(require('path').resolve(process.argv[2]));
const trains = JSON.parse(fs.readFileSync(0, 'utf8'));
create().then((lib) => {
  const out = trains.map((t) => {
    const c = lib.classify(t.a2, t.a3, t.n, t.phase, '');
    if (c.error) return { error: c.error };
    const tr = lib.trace(t.a2, t.a3, t.n, t.phase, '', t.samples, true);
    if (tr.error) return { error: tr.error };
    const ev = lib.events(t.a2, t.n, '');
    const cert = t.certify ? lib.certify(t.a2, t.a3, t.n, t.phase, '') : null;
    return {
      certificate: cert && { certified: cert.certified, rootNodes: cert.rootNodes },
      events: ev.error ? null : ev.events.map((e) => ({ a3: e.a3, kind: e.kind, below: e.nodesBelow, above: e.nodesAbove })),
      class: c.class, nodes: c.nodes, crossings: c.crossings, tangencies: c.tangencies, cusps: c.cusps,
      nodePositions: Array.from(c.nodePositions), points: Array.from(tr.points), velocities: Array.from(tr.velocities),
      params: Array.from(tr.params),
    };
  });
  process.stdout.write(JSON.stringify(out));
});
