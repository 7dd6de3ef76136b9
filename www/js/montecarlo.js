// Monte Carlo (ch. 5.4): trials spread over several workers, merged by the page's worker, and the
// study's tables and plots (Table 5.8, Figs. 5-20 to 5-25).
import { MC } from './config.js';
import { el, fmt } from './dom.js';
import { StudyPool } from './pool.js';

// A Monte Carlo study on the page's study pool (pool.js); stop() terminates its workers (their
// requests fail as cancelled).
export class MonteCarlo {
  constructor() { this.pool = new StudyPool(MC.maxWorkers); }

  stop() { this.pool.cancel(); }

  // The number of trials the page runs for a scenario, or a reason it will not.
  static refusal(sc) {
    const n = Number(sc.monte_carlo && sc.monte_carlo.trials) || 0;
    if (sc.sea.kind === 'calm') return 'Monte Carlo needs a sea: choose a random sea (or the mc-… studies).';
    if (!(n >= 1 && n <= MC.maxTrials)) return `monte_carlo.trials must be from 1 to ${MC.maxTrials} in the page.`;
    return null;
  }

  // Runs trials 0..n of `sc` on the pool, about ten chunks a worker (progress after each, and few
  // shards to merge: each carries whole envelopes), merged and summarised by the pool's first
  // worker. onProgress(done, k, preparing) after each chunk (preparing: before the first trial). Resolves to {summary, constants}. (`client`,
  // the page's own worker, is not needed: the pool's workers hold the RAO table.)
  async run(client, sc, onProgress) {
    const n = Number(sc.monte_carlo.trials);
    const scenario = JSON.stringify(sc);
    const k = this.pool.size(n);
    const chunk = Math.max(1, Math.ceil(n / (k * 10)));
    return this.pool.run({ kind: 'monte-carlo', scenario, spec: scenario, n, chunk, constants: true, item: 'trial', onProgress: (done, _, preparing) => onProgress(done, k, preparing) });
  }
}

// The moments of the exponential distribution of rate `lam` (Rice's first-passage model):
// mean, std, skewness, kurtosis, median, mode.
function exponentialMoments(lam) { return [1 / lam, 1 / lam, 2, 9, Math.LN2 / lam, 0]; }

// A share as a person reads it: "71 %", "106 %", "4.6 %".
const percent = (x) => `${100 * x >= 10 ? Math.round(100 * x) : fmt(100 * x, 2)} %`;

// Two means in words computed from their numbers: `ours` with its standard error `se` against
// `ref` with its own (`refSe`, 0 for a number without one, like an analytic value): they agree
// within two joint standard errors; otherwise how far apart, in the unit, in per cent of `ref` and
// in joint standard errors, and which way. Without a spread to judge by (one trial, or trials all
// equal) it says so and claims no agreement. `unit` follows each number ('' for none).
export function meanWords(ours, se, ref, refSe = 0, unit = '') {
  const u = unit ? ` ${unit}` : '';
  const d = ours - ref, joint = Math.hypot(Number.isFinite(se) ? se : NaN, Number.isFinite(refSe) ? refSe : 0);
  const k = Math.abs(d) / joint;
  if (d === 0) return { agree: true, text: `agree: they are equal` };
  const pct = ref !== 0 ? ` (${percent(Math.abs(d) / Math.abs(ref))})` : '';
  const seWords = `${refSe > 0 ? 'joint ' : ''}standard error${Math.abs(k - 1) < 1e-9 ? '' : 's'} (${fmt(joint, 2)}${u})`;
  if (Number.isFinite(k) && k <= 2) return { agree: true, text: `agree: they differ by ${fmt(Math.abs(d), 2)}${u}, ${fmt(k, 2)} ${seWords}` };
  const way = d < 0 ? 'below' : 'above';
  const why = Number.isFinite(k) ? `${fmt(k, 2)} ${seWords}` : joint === 0 && Number.isFinite(se) ? 'with no spread between the trials to judge by' : 'with no standard error (one trial)';
  return { agree: false, text: `differ: ours is ${fmt(Math.abs(d), 2)}${u}${pct} ${way}, ${why}` };
}

// Rice against the trials in words computed from the numbers compared: the mean of min(T, cap),
// Rice's counting the trials that start past the level at 0, against the Monte Carlo's within
// two of its standard errors; the shape of the arrival times against the exponential's.
export function riceComparison(a, r, trials) {
  const mc = a.mean_censored, rice = r.mean_censored_with_start_s;
  if (mc == null || !trials) return MC.riceNote;
  const se = a.std_censored == null || trials < 2 ? NaN : a.std_censored / Math.sqrt(trials);
  const d = mc - rice, k = Math.abs(d) / se;
  const why = Number.isFinite(k) ? `${fmt(k, 2)} standard errors of the Monte Carlo (${fmt(se, 2)} s)`
    : trials < 2 ? 'with no standard error (one trial)' : `with no spread between the ${trials} trials to judge by`;
  const means = Number.isFinite(k) && k <= 2
    ? `The means of min(T, cap) agree: they differ by ${fmt(Math.abs(d), 2)} s, ${why}.`
    : d === 0 ? `The means of min(T, cap) are equal, ${why}.`
      : `The means of min(T, cap) differ by ${fmt(Math.abs(d), 2)} s, ${why}: the Monte Carlo's first surface effect comes ${d < 0 ? 'sooner' : 'later'} than Poisson arrivals at Rice's rate${Number.isFinite(k) ? '' : ' (too few trials to tell)'}.`;
  const word = (x, ref) => (x == null ? 'undefined' : x < ref ? `${fmt(x, 2)}, short of the exponential's ${ref}` : `${fmt(x, 2)}, above the exponential's ${ref}`);
  const shape = a.events > 2 ? ` Skewness ${word(a.skewness, 2)}; kurtosis ${word(a.kurtosis, 9)} (each trial is cut off at ${a.cap_s} s).` : '';
  return `${MC.riceNote} ${means}${shape}`;
}

// Ours against the thesis' Table 5.8 in words from the numbers of the table: the Monte Carlo mean
// arrival time (standard errors of both, the thesis' from its trials) and Rice's mean (analytic on
// both sides: within 1 % or how far and which way). `th(key)` gives a thesis row's value (null
// when missing).
export function table58Comparison(a, r, th) {
  const [thRice, thMc, thStd, thTrials] = ['table_5_8.rice.mean_s', 'table_5_8.monte_carlo.mean_s', 'table_5_8.monte_carlo.std_s', 'table_5_8.monte_carlo.trials'].map(th);
  const parts = [];
  if (a.mean != null && thMc != null) {
    const w = meanWords(a.mean, a.events > 1 ? a.std / Math.sqrt(a.events) : NaN, thMc, thStd != null && thTrials ? thStd / Math.sqrt(thTrials) : 0, 's');
    parts.push(`the Monte Carlo means (ours ${fmt(a.mean)} s from ${a.events} events, the thesis' ${fmt(thMc)} s from ${thTrials || 'its'} trials) ${w.text}`);
  }
  if (r && r.rate_per_s > 0 && thRice != null) {
    const ours = 1 / r.rate_per_s, rel = (ours - thRice) / thRice;
    parts.push(`Rice's means (ours ${fmt(ours)} s, the thesis' ${fmt(thRice)} s) ${Math.abs(rel) <= 0.01 ? 'agree within 1 %' : `differ: ours is ${percent(Math.abs(rel))} ${rel < 0 ? 'shorter' : 'longer'}`}`);
  }
  return parts.length ? `Against the thesis' Table 5.8: ${parts.join('; ')}. docs/validation.md (Table 5.8) gives what is known of the causes.` : '';
}

// The excess energy in words from its numbers: against the submerged counterpart (its sign and
// whether it is distinguishable from nil), and against calm water beside the thesis' figure of the
// same kind when there is one (`thesis`: {mean, std}; its trials are not in the thesis' numbers,
// so only our standard error counts).
export function excessComparison(e, trials, thesis = null) {
  const se = (m) => (trials > 1 && m.std != null ? m.std / Math.sqrt(trials) : NaN);
  const sub = se(e), calm = se(e.vs_calm_water);
  const zero = meanWords(e.mean, sub, 0, 0, 'MJ');
  const vsSub = zero.agree
    ? `Against the same sea without surface losses, ${fmt(e.mean)} ± ${fmt(sub, 2)} MJ (mean ± standard error): no difference the trials can tell from nil (${fmt(Math.abs(e.mean) / sub, 2)} standard errors).`
    : `Against the same sea without surface losses, one motor draws ${fmt(Math.abs(e.mean))} MJ ${e.mean < 0 ? 'less' : 'more'} over the run (± ${fmt(sub, 2)} MJ, standard error${Number.isFinite(sub) && sub > 0 ? `; ${fmt(Math.abs(e.mean) / sub, 2)} standard errors from nil` : ''}): surface effects ${e.mean < 0 ? 'shed load (the motor works less)' : 'cost energy'}.`;
  const c = e.vs_calm_water;
  let vsCalm = `Against calm water: ${fmt(c.mean)} ± ${fmt(calm, 2)} MJ (mean ± standard error).`;
  if (thesis && thesis.mean != null) {
    const w = meanWords(c.mean, calm, thesis.mean, 0, 'MJ');
    const printed = `${thesis.printedMean || fmt(thesis.mean)}${thesis.std != null ? ` ± ${thesis.printedStd || fmt(thesis.std)}` : ''} MJ`;
    vsCalm += ` Ours against calm water and the thesis' ${printed} (against a reference it does not print) ${w.text}${w.agree || !(thesis.mean > 0) ? '' : `, ${fmt(c.mean / thesis.mean, 3)} times the thesis'`}. docs/validation.md (ch. 5.4.1) gives what is known of the causes.`;
  }
  return `${MC.excessNote} ${vsSub} ${vsCalm}`;
}

function table(caption, rows, head) {
  const t = el('table');
  t.createCaption().textContent = caption;
  if (head) {
    const tr = t.createTHead().insertRow();
    for (const h of head) tr.append(el('th', { scope: 'col', textContent: h }));
  }
  const body = t.createTBody();
  for (const [k, ...vals] of rows) {
    const tr = body.insertRow();
    tr.append(el('th', { scope: 'row', textContent: k }));
    for (const v of vals) tr.insertCell().textContent = v;
  }
  return t;
}

// A thesis number as the thesis prints it, from the worker's thesisValues rows ('missing' when the
// rows lack the key: the registry test keeps the page's keys in the file).
function thesisPrinted(thesis, key) {
  const row = (thesis || []).find((t) => t.key === key);
  return row ? row.printed : 'missing';
}
// The same row's value as a number (null when missing).
function thesisValue(thesis, key) {
  const row = (thesis || []).find((t) => t.key === key);
  return row && Number.isFinite(Number(row.value)) ? Number(row.value) : null;
}

// The study's summary: tables, then envelopes, histograms, onset and periodogram plots.
// onReplay(i): replay trial i as a single run in the live views; onPickBar(hist, bin): replay a
// trial from a histogram bar; thesis: the worker's thesisValues rows (the reference columns).
export function showMonteCarlo(box, s, signals, constants, { onReplay = null, onPickBar = null, thesis = [], study = null } = {}) {
  box.clear();
  // The thesis' numbers stand only beside the thesis' own study (not beside a Wigley hull's).
  const own = (which) => MC.thesisStudies[which].includes(study);
  const a = s.arrival_time_s, r = s.rice, e = s.excess_energy_mj;
  const th = (key) => thesisPrinted(thesis, key);
  const rows = [['Trials', s.trials], ['Seed', s.seed]];
  const [calmMean, calmStd] = MC.calmWater.map(th);
  if (e) rows.push(['Excess energy vs submerged counterpart [MJ], mean ± std', `${fmt(e.mean)} ± ${fmt(e.std)}`], [`Excess energy vs calm water [MJ], mean ± std${own('calmWater') ? ` (thesis: ${calmMean} ± ${calmStd})` : ''}`, `${fmt(e.vs_calm_water.mean)} ± ${fmt(e.vs_calm_water.std)}`]);
  rows.push(['First surface effects / censored', `${a.events} / ${a.censored} (cap ${a.cap_s} s)`]);
  // An h2 before the plots' h3 titles (the run's summary, which has one, is hidden here).
  const info = box.panel(null, box.generation, false, el('h2', { textContent: `Monte Carlo: ${s.trials} trials` }), table('Monte Carlo summary', rows));
  if (r) {
    info.append(
      // One row a statistic, ours beside the thesis': narrow enough for a phone.
      el('div', { className: 'scroll', tabIndex: 0, attrs: { role: 'region', 'aria-label': 'Table 5.8' } }, table('Arrival time of the first surface effect [s] (Table 5.8)',
        (() => {
          const rice = exponentialMoments(r.rate_per_s), mc = [a.mean, a.std, a.skewness, a.kurtosis, a.median, a.mode];
          return MC.table58.map(([name, riceKey, mcKey], k) => [name, fmt(rice[k]), fmt(mc[k]), ...(own('table58') ? [th(riceKey), th(mcKey)] : [])]);
        })(), ['statistic', 'Rice', 'Monte Carlo', ...(own('table58') ? ['thesis: Rice', 'thesis: Monte Carlo'] : [])])),
      el('p', { className: 'about', textContent: `Rice: the level Z = ${fmt(r.z_m, 3)} m. The trials count the first surface effect on either shaft: Rice's rate of that event is ${fmt(r.rate_per_s, 3)} per second, the union of the two hubs' up-crossings from their joint statistics (each hub alone ${r.hubs.map((h) => `${h.shaft} ${fmt(h.rate_per_s, 3)}`).join(', ')} per second, correlation ${fmt(r.hub_correlation, 3)}; their sum, an upper bound, ${fmt(r.sum_bound_rate_per_s, 3)}).` }),
      el('p', { className: 'about', textContent: `Censored at ${a.cap_s} s alike: Monte Carlo mean of min(T, cap) ${fmt(a.mean_censored)} s, Rice ${fmt(r.mean_censored_with_start_s)} s (with the ${fmt(100 * r.start_past_level_probability, 2)} % of trials that start with a hub past the level counted at 0).` }),
      el('p', { className: 'about', id: 'rice-note', textContent: riceComparison(a, r, s.trials) }));
    if (own('table58')) info.append(el('p', { className: 'about', id: 'thesis-note', textContent: table58Comparison(a, r, (key) => thesisValue(thesis, key)) }));
  }
  if (e) {
    const [mean, std] = MC.calmWater.map((key) => thesisValue(thesis, key));
    info.append(el('p', { className: 'about', id: 'excess-note', textContent: excessComparison(e, s.trials, own('calmWater') ? { mean, std, printedMean: calmMean, printedStd: calmStd } : null) }));
  }
  if (onReplay) {
    // Any trial replays as a single run: its seed, trial_seed(seed, i), reproduces it.
    const first = (s.traces || [])[0];
    const input = el('input', { type: 'number', id: 'mc-trial', min: '0', max: String(s.trials - 1), step: '1', value: String(first ? first.trial : 0) });
    const go = el('button', { type: 'button', id: 'mc-replay', textContent: 'Replay this trial in the live views' });
    const replay = () => {
      const i = Number(input.value);
      if (Number.isInteger(i) && i >= 0 && i < s.trials) onReplay(i); else input.setAttribute('aria-invalid', 'true');
    };
    go.addEventListener('click', replay);
    input.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') replay(); });
    input.addEventListener('input', () => input.removeAttribute('aria-invalid'));
    info.append(el('div', { className: 'row buttons' }, el('label', { htmlFor: 'mc-trial', textContent: `Trial (0 to ${s.trials - 1})` }), input, go),
      el('p', { className: 'hint', textContent: `The red line in the envelopes is trial ${first ? first.trial : 0}. A replayed trial runs alone with its own sea (the same seed), so its plots and live views are that trial's.` }));
  }
  const time = `time [${signals.meta('t_s').unit}]`;
  for (const [sig, env] of Object.entries(s.envelopes)) {
    const series = [
      { data: env.mean, label: 'mean', color: '#0b5cad' }, { data: env.plus_2sigma, label: 'mean + 2 std', color: '#2e86c1', dash: [6, 3] },
      { data: env.minus_2sigma, label: 'mean - 2 std', color: '#2e86c1', dash: [6, 3] }, { data: env.min, label: 'lowest', color: '#6b6b6b', dash: [2, 3] },
      { data: env.max, label: 'highest', color: '#6b6b6b', dash: [2, 3] }];
    const tr = (s.traces || [])[0];
    const c = tr && tr.columns.find(([n]) => n === sig);
    if (c) series.push({ data: c[1].slice(0, env.t_s.length), label: `trial ${tr.trial}`, color: '#b03a2e' });
    // Trials still running under the envelope (a trial stopped after its first event leaves it).
    const n = env.n || [];
    const fewer = n.findIndex((k) => k < s.trials);
    const axes = [{ scale: 'y', label: signals.axisLabel(sig, constants) }];
    if (fewer >= 0) {
      series.push({ data: n, label: 'trials still running', color: '#7d3c98', dash: [10, 3, 2, 3], width: 1.5, scale: 'n' });
      axes.push({ scale: 'n', label: 'trials still running [-]' });
    }
    box.line(`${signals.labelWithUnit(sig, constants)}: envelope over ${s.trials} trials (Fig. 5-20)`, { data: env.t_s, label: time }, series, axes,
      { time: true, key: fewer >= 0 ? [`From t = ${fmt(env.t_s[fewer], 3)} s fewer trials are running (purple dash-dot line, right axis): the envelope after that is drawn from those left.`] : null });
  }
  const ht = s.histogram_at_t;
  const pick = (hist) => (onPickBar ? (bin) => onPickBar(hist, bin) : null);
  if (ht.n > 0) box.histogram(`${signals.labelWithUnit(ht.signal, constants)} at t = ${ht.t_s} s (Fig. 5-21), skewness ${fmt(ht.skewness, 3)}${ht.n < s.trials ? `, from the ${ht.n} of ${s.trials} trials still running then` : ''}`, ht.histogram, signals.labelWithUnit(ht.signal, constants), null, undefined, pick('at_time'));
  // Fig. 5-22's kind is the excess against calm water (the thesis' reference is not printed; against
  // the submerged counterpart the sign can differ): each caption says which it is.
  if (e) {
    box.histogram(`Excess energy per trial vs calm water [MJ] (ch. 5.4.1's kind, Fig. 5-22): mean ${fmt(e.vs_calm_water.mean)}, std ${fmt(e.vs_calm_water.std)}`, e.vs_calm_water.histogram, 'excess energy vs calm water [MJ]', null, undefined, pick('excess_vs_calm'));
    box.histogram(`Excess energy per trial vs the submerged counterpart [MJ] (surface losses alone): mean ${fmt(e.mean)}, std ${fmt(e.std)}`, e.histogram, 'excess energy vs submerged [MJ]', null, undefined, pick('excess'));
  }
  if (a.events > 0) {
    const h = a.histogram, w = (h.hi - h.lo) / h.counts.length, total = s.trials;
    const overlay = r ? { label: `exponential, Rice rate ${fmt(r.rate_per_s, 3)}/s`, values: h.counts.map((_, i) => total * (Math.exp(-r.rate_per_s * (h.lo + i * w)) - Math.exp(-r.rate_per_s * (h.lo + (i + 1) * w)))) } : null;
    const from = a.events < total ? `, from the ${a.events} of ${total} trials that had one (the other ${total - a.events} ended without, at ${a.cap_s} s)` : '';
    box.histogram(`Arrival time of the first surface effect [s] (Fig. 5-24)${from}`, h, time, overlay, undefined, pick('arrival'));
  }
  if (s.onset && s.onset.t_s.length > 1) {
    const o = s.onset;
    box.line(`${signals.labelWithUnit(MC.onsetSignal, constants)} after the onset of a surface effect (Fig. 5-25)`, { data: o.t_s, label: 'time after onset [s]' },
      [{ data: o.mean, label: 'mean', color: '#0b5cad' }, { data: o.plus_2sigma, label: 'mean + 2 std', color: '#2e86c1', dash: [6, 3] }, { data: o.min, label: 'lowest', color: '#6b6b6b', dash: [2, 3] }],
      [{ scale: 'y', label: signals.axisLabel(MC.onsetSignal, constants) }]);
  }
  const pg = s.periodogram;
  if (pg.freq_hz.length > 2) {
    const k = pg.freq_hz.findIndex((f) => f > MC.periodogramMaxHz);
    const n = k > 0 ? k : pg.freq_hz.length;
    const pos = (v) => v.slice(1, n).map((x) => Math.max(x, 1e-9));
    const unit = pg.unit.replace('^2', '²');
    // Only trials that run one whole Welch segment count (a trial that ends early at its first
    // surface effect does not): with few of them the lowest and highest lines meet the mean.
    const counted = pg.trials === s.trials ? `${pg.trials} trials` : `${pg.trials} of ${s.trials} trials (the rest ended before one ${pg.segment_s} s segment)`;
    box.line(`Periodogram of one motor's power [${unit}] (Welch, Fig. 5-23), ${counted}`, { data: pg.freq_hz.slice(1, n), label: 'frequency [Hz]' },
      [{ data: pos(pg.mean), label: 'mean over trials', color: '#0b5cad' }, { data: pos(pg.min), label: 'lowest', color: '#6b6b6b', dash: [2, 3] }, { data: pos(pg.max), label: 'highest', color: '#b03a2e', dash: [6, 3] }],
      [{ scale: 'y', label: `PSD [${unit}]` }], { scales: { y: { distr: 3, log: 10 } } });
  }
}
