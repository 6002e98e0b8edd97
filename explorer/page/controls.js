// controls.js — the controls: the text fields (n and teeth exclude each other), the sliders of
// a2, a3 and the phase, the markers' mode, and the URL hash (a hash typed or followed loads that
// state).
'use strict';
{
  const X = window.Explorer;
  const { $ } = X;

  function setupControls() {
    for (const f of X.FIELDS) {
      $(f + '-text').addEventListener('input', () => {
        // n and teeth exclude each other (as --n and --teeth): typing one clears the other.
        if (f === 'n' && $('n-text').value.trim() !== '') $('teeth-text').value = '';
        if (f === 'teeth' && $('teeth-text').value.trim() !== '') $('n-text').value = '';
        X.state = X.readFields();
        X.update(true);
      });
    }
    for (const f of ['a2', 'a3', 'phase']) {
      $(f + '-slider').addEventListener('input', (ev) => {
        X.state[f] = String(Number(ev.target.value));
        $(f + '-text').value = X.state[f];
        X.update(true);
      });
    }
    $('markers').addEventListener('change', () => {
      X.state.markers = $('markers').value;
      X.update(true);
    });
    window.addEventListener('hashchange', () => { X.state = X.readHash(); X.fillFields(); X.update(false); });
  }

  X.setupControls = setupControls;
}
