// The rare-event fold of the simulator's results (issue 32): its controls and result DOM, built
// here (only rare.js reads them), the RareView on the form's study as it stands (none in a lesson),
// and its replays through the page's run.
import { studyTitle } from '../config.js';
import { $ } from '../dom.js';
import { REQUEST } from '../protocol.js';
import { isBusy } from '../state.js';
import { PlotBox } from '../plots.js';
import { RareView } from '../rare.js';
import { registerView } from '../views.js';

// Under the fold's summary (which index.html keeps, so the page shows the fold before it loads).
const TEMPLATE = `
<section class="rare" aria-labelledby="rare-h">
  <p class="about">Each trial's random sea is made so that the chosen propeller hub falls through the event's h/R at one moment; the whole plant then runs through it. The trials give how often the event comes (per hour, with a 95 % interval, beside Rice's formula) and how bad its consequences are. It judges the study as it stands, with your edits: <strong id="rare-study"></strong>.</p>
  <p id="rare-nosea" class="hint" hidden></p>
  <div id="rare-controls" role="group" aria-label="The rare event">
    <div class="rare-fields">
      <div class="rare-field"><label for="rare-event">Event</label>
        <select id="rare-event"><option value="ventilation">ventilation starts</option><option value="emergence">the disc reaches the surface (emergence)</option></select></div>
      <div class="rare-field"><label for="rare-shaft">Shaft</label>
        <select id="rare-shaft"><option value="port">port</option><option value="starboard">starboard</option></select></div>
      <div class="rare-field"><label for="rare-h0">Hub depth h0 [m]</label>
        <input id="rare-h0" type="number" min="3" max="7" step="0.05" aria-describedby="rare-h0-err">
        <div class="ferr" id="rare-h0-err" aria-live="polite"></div></div>
      <div class="rare-field"><label for="rare-trials">Trials</label>
        <input id="rare-trials" type="number" min="2" max="1000" step="1" value="200" aria-describedby="rare-trials-err">
        <div class="ferr" id="rare-trials-err" aria-live="polite"></div></div>
    </div>
    <div class="row buttons">
      <button id="rare-compute" type="button" disabled>Compute</button>
      <button id="rare-cancel" type="button" disabled>Cancel</button>
      <progress id="rare-progress" max="1" value="0" aria-label="Progress of the rare-event trials"></progress>
      <span id="rare-eta" aria-live="polite"></span>
    </div>
  </div>
  <div id="rare-status" role="status" aria-live="polite"></div>
  <div id="rare-results" tabindex="-1">
    <div id="rare-stale" class="stale-box" role="status" hidden><p id="rare-stale-text"></p><button id="rare-stale-run" type="button">Compute these values</button></div>
    <div id="rare-body" hidden>
      <p id="rare-headline" class="rare-headline"></p>
      <p id="rare-event-line" class="rare-event-line"></p>
      <p id="rare-facts" class="about"></p>
      <div class="row buttons"><button id="rare-wave" type="button">Show the most likely wave group</button></div>
      <p id="rare-showing" class="hint" aria-live="polite"></p>
      <div class="rare-tables">
        <div class="rare-table"><p id="rare-thresholds-cap" class="rare-cap">Rate per hour past a threshold (type a threshold: the same trials are summarised again)</p>
          <div id="rare-thresholds" class="scroll" tabindex="0" role="region" aria-labelledby="rare-thresholds-cap"></div></div>
        <div class="rare-table"><p id="rare-worst-cap" class="rare-cap">The worst trials: replay one in the plots and live views</p>
          <div id="rare-worst" class="scroll" tabindex="0" role="region" aria-labelledby="rare-worst-cap"></div></div>
      </div>
      <div id="rare-plots"></div>
      <p id="rare-quantiles-cap" class="rare-cap">The consequences given the event: quantiles over the trials (weighted by their seas' crossing rates)</p>
      <div id="rare-quantiles" class="scroll" tabindex="0" role="region" aria-labelledby="rare-quantiles-cap"></div>
      <p id="rare-method" class="hint"></p>
    </div>
  </div>
</section>`;

let rareView = null;

// h/R of a rare event's hub at the event, read from the run's own trace.
function hrAt(cols, at, hr) {
  const i = cols.t_s.findIndex((x) => x >= at - 1e-9);
  return i >= 0 ? cols[hr][i].toFixed(3) : '–';
}

// A rare-event scenario through the page's run (plots and live views). Returns why it cannot.
function runRare(ctx, { text, name, words, key, at, hr, shaft }) {
  const { form } = ctx;
  if (!form) return 'The simulator is still loading.';
  if (isBusy()) return 'A run is in progress: wait for it or cancel it first.';
  if (form.invalid.size) return 'A value of the form is refused (marked at its field): correct it first.';
  ctx.run({ focus: false, replay: { text, name, words, at, shaft, hrAt: (cols) => hrAt(cols, at, hr), state: `rare|${key}`, isCurrent: () => rareView.currentKey() === key } });
  return null;
}

registerView({
  id: 'rare',
  init(ctx) {
    $('rare-box').insertAdjacentHTML('beforeend', TEMPLATE);
    rareView = new RareView({
      inputs: () => (ctx.lesson ? null : ctx.studyInputs()),
      sheet: (sc) => ctx.client.request(REQUEST.hullSheet, { scenario: JSON.stringify(sc) }),
      onRun: (r) => runRare(ctx, r),
    });
    rareView.setPlots(new PlotBox($('rare-plots')));
  },
  sync: () => rareView.sync(),
});
