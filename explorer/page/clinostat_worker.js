// clinostat_worker.js — the clinostat panel's jobs in the page's worker (run from a Blob with
// sphtroch.js before it; see bundle_worker.js): for a message {job: 'clinostat', id, texts} (the
// options of `sphtroch clinostat`: outer, inner, tilt, frame-angle, window, epsilon; each may be
// "": not given), the module's answers posted one by one as {id, part, value}, each value the
// module's object (or {error}: the CLI's line):
//   part 'report'   clinostatReport(): {json}, the JSON text of `sphtroch clinostat --json`; first
//                   without window and epsilon (fast), then, when one is given, with them
//   part 'path'     clinostatPath(): the gravity path over one period
//   part 'windows'  clinostatWindows(): M(W) as `sphtroch clinostat --plot` draws it
// then {id, part: 'done'}. After a report with an error nothing else is posted but 'done'. The
// module is instantiated once per worker, at its first job.
'use strict';
const PATH_SAMPLES = 200000;  // the gravity path's samples at most (the module takes 100 per turn)
let clinostatModule = null;

function runClinostat(lib, id, t) {
  const post = (part, value) => self.postMessage({ id, part, value });
  const machine = [t.outer, t.inner, t.tilt, t['frame-angle']];
  const asked = [t.window, t.epsilon, ''];
  const first = lib.clinostatReport(...machine, '', '', '');
  post('report', first);
  if (first.error) return post('done');
  post('path', lib.clinostatPath(...machine, PATH_SAMPLES));
  if (t.window !== '' || t.epsilon !== '') {
    const report = lib.clinostatReport(...machine, ...asked);
    post('report', report);
    if (report.error) return post('done');
  }
  post('windows', lib.clinostatWindows(...machine, ...asked));
  post('done');
}

self.addEventListener('message', (ev) => {
  if (ev.data.job !== 'clinostat') return;
  const { id, texts } = ev.data;
  if (!clinostatModule) clinostatModule = createSphtroch();
  clinostatModule.then((lib) => runClinostat(lib, id, texts));
});
