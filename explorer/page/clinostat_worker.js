// clinostat_worker.js — the clinostat panel's jobs in the page's worker (run from a Blob with
// sphtroch.js before it; see bundle_worker.js): for a message {job: 'clinostat', id, texts} (the
// options of `sphtroch clinostat`: outer, inner, tilt, frame-angle, window, epsilon; window and
// epsilon may be ""), the module's answers posted one by one as {id, part, value}, each value the
// module's object (or {error}: the CLI's line):
//   part 'report'   clinostat(): the train, period, mean over a period and the gravity path
//   part 'window'   clinostatWindow(): M(W) for the window (only when one is given)
//   part 'epsilon'  clinostatEpsilon(): the time to epsilon (only when one is given)
//   part 'windows'  clinostatWindows(): M(W) at WINDOW_COUNT windows, as `sphtroch clinostat
//                   --plot` draws it: up to 1.25 times the time from which every window stays
//                   below epsilon, else three periods up to two hours
// then {id, part: 'done'}. After a report with an error nothing else is posted but 'done'. The
// module is instantiated once per worker, at its first job.
'use strict';
const PATH_SAMPLES = 200000;  // the gravity path's samples at most (the module takes 100 per turn)
const WINDOW_COUNT = 100;
let clinostatModule = null;

// The longest window of the M(W) curve (the rule of `sphtroch clinostat --plot`).
function longestWindow(report, epsilon) {
  const period = report.periodS === null ? 60 : report.periodS;
  if (epsilon && !epsilon.error && epsilon.staysBelowFromS !== null) return 1.25 * epsilon.staysBelowFromS;
  return Math.min(3 * period, 7200);
}

function runClinostat(lib, id, t) {
  const post = (part, value) => self.postMessage({ id, part, value });
  const args = [t.outer, t.inner, t.tilt, t['frame-angle']];
  const report = lib.clinostat(...args, PATH_SAMPLES);
  post('report', report);
  if (report.error) return post('done');
  if (t.window !== '') post('window', lib.clinostatWindow(...args, t.window));
  const epsilon = t.epsilon !== '' ? lib.clinostatEpsilon(...args, t.epsilon) : null;
  if (epsilon) post('epsilon', epsilon);
  post('windows', lib.clinostatWindows(...args, longestWindow(report, epsilon), WINDOW_COUNT));
  post('done');
}

self.addEventListener('message', (ev) => {
  if (ev.data.job !== 'clinostat') return;
  const { id, texts } = ev.data;
  if (!clinostatModule) clinostatModule = createSphtroch();
  clinostatModule.then((lib) => runClinostat(lib, id, texts));
});
