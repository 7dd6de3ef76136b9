// Fuel per nautical mile against ordered speed, over seas of several seeds (core's
// studies::fuel_per_mile, `aes-sim fuel-per-mile`): the study of the form as it stands, run on the
// study pool (pool.js) with progress and Cancel, as a table and a plot. All of it is this module:
// the fold's DOM, its inputs, the computation and the drawing.
import { $, el, fmt, row } from '../dom.js';
import { announce } from '../state.js';
import { PlotBox } from '../plots.js';
import { StudyPool } from '../pool.js';
import { StudyFold } from '../fold.js';
import { registerView } from '../views.js';

// The page's defaults: six speeds, two seas each, 120 s runs measured over their second half
// (about 25 s on four workers for a study in waves).
const FUEL = { speeds: '12, 15, 18, 21, 24, 27', seeds: 2, durationS: 120, maxWorkers: 4 };

const TEMPLATE = `
<section class="fuel" aria-labelledby="fuel-h">
  <p class="about">The study of the form as it stands, sailed at each ordered speed for ${FUEL.durationS} s in the seas of
    several seeds: the fuel the turbines burn (their fuel power over the fuel's heating value) over the distance run
    through the water, measured over the second half of each run. Where is the ship most economical in this sea, and how
    much does the sea's realisation move it?</p>
  <div class="row">
    <label for="fuel-speeds">Ordered speeds [kn]</label> <input id="fuel-speeds" type="text" value="${FUEL.speeds}" aria-describedby="fuel-err">
    <label for="fuel-seeds">Seas per speed</label> <input id="fuel-seeds" type="number" min="1" max="20" step="1" value="${FUEL.seeds}" aria-describedby="fuel-err">
  </div>
  <div class="ferr" id="fuel-err" aria-live="polite"></div>
  <div class="row buttons">
    <button id="fuel-compute" type="button">Compute</button>
    <button id="fuel-cancel" type="button" disabled>Cancel</button>
    <progress id="fuel-progress" max="1" value="0" aria-label="Progress of the fuel study"></progress>
    <span id="fuel-eta" aria-live="polite"></span>
  </div>
  <div id="fuel-status" role="status" aria-live="polite"></div>
  <div id="fuel-body" hidden>
    <div id="fuel-table" class="scroll" tabindex="0" role="region" aria-label="Fuel per nautical mile by speed"></div>
    <div id="fuel-plot"></div>
  </div>
</section>`;

const pool = new StudyPool(FUEL.maxWorkers);
let plots = null;
let fold = null;

// What a result depends on: the form's scenario and the fold's inputs.
const keyOf = (inp, ask) => JSON.stringify([inp.scenario, ask.speeds, ask.seeds]);

// The speeds and seeds typed, or the reason they are refused.
function inputs() {
  const speeds = $('fuel-speeds').value.split(',').map((t) => t.trim()).filter((t) => t !== '').map(Number);
  const seeds = Number($('fuel-seeds').value);
  if (!speeds.length || speeds.some((v) => !Number.isFinite(v))) return { error: 'Ordered speeds: numbers in knots, separated by commas.' };
  if (!(Number.isInteger(seeds) && seeds >= 1 && seeds <= 20)) return { error: 'Seas per speed: a whole number from 1 to 20.' };
  return { speeds, seeds };
}

function show(s) {
  $('fuel-body').hidden = false;
  const head = el('tr', {}, ...['ordered [kn]', 'mean speed [kn]', 'fuel [kg/nmi], mean', 'std', 'lowest', 'highest'].map((h) => el('th', { scope: 'col', textContent: h })));
  $('fuel-table').replaceChildren(el('table', {}, el('caption', { textContent: s.most_economical_kn == null ? 'Fuel per nautical mile' : `Fuel per nautical mile: least at ${s.most_economical_kn} kn` }),
    el('thead', {}, head),
    el('tbody', {}, ...s.rows.map((r) => row(String(r.ordered_kn), [fmt(r.mean_speed_kn, 3), fmt(r.kg_per_nmi_mean, 4), fmt(r.kg_per_nmi_std, 2), fmt(r.kg_per_nmi_min, 4), fmt(r.kg_per_nmi_max, 4)])))));
  plots.clear();
  const x = { data: s.rows.map((r) => r.ordered_kn), label: 'ordered speed [kn]' };
  plots.line('Fuel per nautical mile against ordered speed', x, [
    { data: s.rows.map((r) => r.kg_per_nmi_mean), label: 'mean over the seas', color: '#0b5cad' },
    { data: s.rows.map((r) => r.kg_per_nmi_min), label: 'lowest', color: '#6b6b6b', dash: [2, 3] },
    { data: s.rows.map((r) => r.kg_per_nmi_max), label: 'highest', color: '#6b6b6b', dash: [2, 3] },
  ], [{ scale: 'y', label: 'fuel [kg/nmi]' }]);
}

async function compute(ctx) {
  const inp = ctx.studyInputs();
  if (!inp || fold.busy) return;
  const ask = inputs();
  $('fuel-err').textContent = ask.error || '';
  if (ask.error) return;
  if (inp.invalid) { fold.status('A value of the form is refused (marked at its field): correct it first.'); return; }
  const sc = JSON.parse(JSON.stringify(inp.scenario));
  sc.sim.duration_s = FUEL.durationS;
  const scenario = JSON.stringify(sc);
  const spec = JSON.stringify({ scenario: sc, speeds_kn: ask.speeds, seeds: ask.seeds, from_s: FUEL.durationS / 2 });
  const n = ask.speeds.length * ask.seeds;
  const started = performance.now();
  await fold.compute(async () => {
    const { summary } = await pool.run({
      kind: 'fuel-per-mile', scenario, spec, n, item: 'run',
      onStart: (k) => fold.status(`${n} runs of ${FUEL.durationS} s on ${k} worker${k > 1 ? 's' : ''}...`),
      onProgress: (done, _, preparing) => fold.progress(done, n, started, 'run', preparing),
    });
    show(summary);
    fold.shownKey = keyOf(inp, ask); // the inputs it was started with
    fold.status(`Done: ${n} runs in ${((performance.now() - started) / 1000).toFixed(1)} s (${inp.title}).`);
    announce('fuel', summary);
  }, { after: () => sync(ctx) }); // inputs edited while it ran: the result is of the old ones
}

// A result of other inputs is not shown under these (it would read as theirs).
function sync(ctx) {
  const inp = ctx.studyInputs();
  const ask = inputs();
  if (inp) fold.drop(ask.error ? null : keyOf(inp, ask), 'The study or the fold\'s inputs changed since the last result: compute again.');
}

registerView({
  id: 'fuel',
  sync,
  init(ctx) {
    $('fuel-box').insertAdjacentHTML('beforeend', TEMPLATE);
    plots = new PlotBox($('fuel-plot'));
    fold = new StudyFold('fuel', { failed: 'The fuel study failed', cancel: () => pool.cancel() });
    $('fuel-compute').addEventListener('click', () => compute(ctx));
    for (const id of ['fuel-speeds', 'fuel-seeds']) $(id).addEventListener('input', () => sync(ctx));
  },
});
