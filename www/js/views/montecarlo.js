// The Monte Carlo study of the form's values (ch. 5.4): the run over the worker pool with its
// progress, the statistics drawn in the run's plot box, and a trial (typed, or the first in a
// picked histogram bar) replayed as a single run.
import { studyTitle } from '../config.js';
import { $ } from '../dom.js';
import { REQUEST } from '../protocol.js';
import { setPhase, isBusy, setResult, progress, status } from '../state.js';
import { MonteCarlo, showMonteCarlo } from '../montecarlo.js';
import { registerView } from '../views.js';

const monteCarlo = new MonteCarlo();
let thesis = []; // the thesis' numbers we compare with (the worker's thesisValues)

async function runMonteCarlo(ctx) {
  const { form, live } = ctx;
  if (isBusy() || !form || form.invalid.size) return;
  const sc = form.current();
  const why = MonteCarlo.refusal(sc);
  if (why) { status(why, true); return; }
  const n = Number(sc.monte_carlo.trials);
  const state = ctx.stateKey('mc'), study = form.name;
  setPhase('montecarlo');
  live.hide();
  const started = performance.now();
  let out;
  try {
    out = await monteCarlo.run(ctx.client, sc, (done, k, preparing) => {
      if (preparing) { progress(null); status(`Monte Carlo: preparing (the sea's response table), then ${n} trials on ${k} workers...`); return; }
      if (done === 0) { progress(0); status(`Monte Carlo: ${n} trials on ${k} workers...`); return; }
      const secs = (performance.now() - started) / 1000;
      progress(done / n, secs > 0.5 ? `${done} of ${n} trials, about ${((secs * (n - done)) / done).toFixed(1)} s left` : '');
    });
  } catch (e) { ctx.failed(e); return; }
  setPhase('idle');
  const draw = () => {
    setResult({ summary: out.summary, csv: '', scenario: sc, study, name: `${studyTitle(study)}, Monte Carlo` });
    live.hide();
    $('summary-box').hidden = true;
    $('compare-box').hidden = true;
    $('shown-what').hidden = true;
    showMonteCarlo(ctx.plots, out.summary, ctx.signals, out.constants, { onReplay: (i) => replayTrial(ctx, i), onPickBar: (h, b) => replayFromBar(ctx, h, b), thesis, study });
  };
  ctx.setMode('mc');
  draw();
  ctx.remember(state, state, draw);
  ctx.settle();
  ctx.showStale();
  status(`Monte Carlo done: ${n} trials in ${((performance.now() - started) / 1000).toFixed(1)} s.`);
  $('results').focus();
}

// A Monte Carlo trial as a single run (plots and live views): its scenario comes from the wasm
// with the trial's exact seed.
// A histogram bar picked: find its first trial (trials run in order in the worker), replay it.
async function replayFromBar(ctx, hist, bin) {
  if (isBusy() || !ctx.form) return;
  status('Finding a trial in that bar (trials run in order until one lands in it)...');
  let r;
  try {
    r = await ctx.client.request(REQUEST.findTrial, { scenario: JSON.stringify(ctx.form.current()), hist, bin }, (p) => status(`Finding a trial in that bar: ${p.tried} tried...`));
  } catch (e) { ctx.failed(e); return; }
  if (r.trial === null) { status('No trial of this study lands in that bar.', true); return; }
  if ($('mc-trial')) $('mc-trial').value = String(r.trial);
  await replayTrial(ctx, r.trial);
}

async function replayTrial(ctx, i) {
  if (isBusy() || !ctx.form) return;
  let r;
  try {
    r = await ctx.client.request(REQUEST.trial, { scenario: JSON.stringify(ctx.form.current()), i });
  } catch (e) { ctx.failed(e); return; }
  await ctx.run({ trial: { i, text: r.scenario } });
}

registerView({
  id: 'montecarlo',
  mode: 'mc',
  button: 'Monte Carlo',
  init: (ctx) => $('mc-run').addEventListener('click', () => runMonteCarlo(ctx)),
  ready: (ctx, m) => { thesis = m.thesis || []; },
  again: runMonteCarlo,
  cancel: () => monteCarlo.stop(),
});
