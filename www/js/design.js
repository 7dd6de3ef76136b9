// The controller design tab (thesis ch. 3.1): LQG/LTR on our own drive train. The tuning comes
// from the controls; the worker designs and analyses (Rust, sim::lqg::analyse); the page draws the
// loop singular values beside the Kalman target (LTR visible as q grows), command following,
// the closed-loop pole map and the margins, and can run the acceleration with this controller
// next to the PI loops.
import { DESIGN } from './config.js';
import { $, el } from './dom.js';
import { REQUEST } from './protocol.js';
import { drawPoleMap, poleCells, numberBoxError, markStale } from './stability.js';

// The tuning kept across a reload (the address carries it too).
const STORE = 'aes-sim/design/v1';
const db = (x) => 20 * Math.log10(Math.max(x, 1e-12));
const CURVES = ['#0b5cad', '#c2410c'];
const INPUTS = ['throttle', 'field voltage'];
// The controls: element id, the controllers.lqg_ltr field, whether its slider is in decades.
const DESIGN_CONTROLS = [['design-mu', 'mu', true], ['design-q', 'q', true], ['design-omega', 'omega_p_rad_s', false],
  ['design-speed', 'design_speed_kn', false], ['design-weight', 'turbine_speed_weight', false]];

export class DesignTab {
  // client(): the current worker client; box: a PlotBox; baseScenario(): the study scenario the
  // plant comes from; onRun(tuning): run the acceleration with this tuning beside the PI loops.
  constructor(client, box, baseScenario, onRun) {
    this.client = client;
    this.box = box;
    this.baseScenario = baseScenario;
    this.timer = null;
    this.ok = false;
    this.defaults = null;
    this.onChange = () => {}; // after the user moves a control (the page follows it in the address)
    for (const id of ['design-mu', 'design-q', 'design-omega', 'design-speed', 'design-weight']) {
      $(id).addEventListener('input', () => this.update());
      $(id).addEventListener('change', () => { this.store(); this.onChange(); });
    }
    $('design-run').addEventListener('click', () => { if (this.ok) onRun(this.tuning()); });
  }

  // Sets each control's label, range and starting value from the registry (paramMeta: the
  // controllers.lqg_ltr declarations); a slider spans DESIGN.spans within the declared range.
  configure(meta) {
    const byPath = new Map(meta.params.map((m) => [m.path, m]));
    for (const [id, field, log] of DESIGN_CONTROLS) {
      const m = byPath.get(`controllers.lqg_ltr.${field}`);
      const input = $(id);
      const f = log ? Math.log10 : (x) => x;
      const span = DESIGN.spans[field];
      const lo = span ? Math.max(span[0], f(m.min)) : f(m.min), hi = span ? Math.min(span[1], f(m.max)) : f(m.max);
      Object.assign(input, { min: String(lo), max: String(hi), value: String(f(m.default)) });
      if (input.type === 'range') input.step = String(DESIGN.steps[field]);
      else input.step = 'any';
      const unit = m.unit && m.unit !== '-' ? ` [${m.unit}]` : '';
      const label = m.label.replace(/^LQG\/LTR /, '');
      document.querySelector(`label[for="${id}"]`).textContent = label[0].toUpperCase() + label.slice(1) + unit;
      input.title = m.help;
    }
    this.readouts();
    this.defaults = this.tuning();
  }

  // The tuning when it differs from the declared defaults (for the address and the store), else null.
  changed() {
    if (!this.defaults) return null;
    const t = this.tuning();
    return Object.keys(t).some((k) => t[k] !== this.defaults[k]) ? t : null;
  }

  // The controls set to a tuning (from a link, or kept from the last visit when t is null); a value
  // outside a control's range is left at the control's own.
  restore(t) {
    if (!this.defaults) return;
    if (t === null) { try { t = JSON.parse(localStorage.getItem(STORE) || 'null'); } catch (_) { t = null; } }
    const want = { ...this.defaults, ...(t && typeof t === 'object' ? t : {}) };
    for (const [id, field, log] of DESIGN_CONTROLS) {
      const v = want[field];
      if (typeof v !== 'number' || !Number.isFinite(v) || (log && v <= 0)) continue;
      const x = log ? Math.log10(v) : v;
      const input = $(id);
      if (input.type === 'range' && (x < Number(input.min) || x > Number(input.max))) continue;
      input.value = String(x);
    }
    this.readouts();
    this.store();
  }

  store() {
    try { const t = this.changed(); if (t) localStorage.setItem(STORE, JSON.stringify(t)); else localStorage.removeItem(STORE); } catch (_) { /* storage blocked */ }
  }

  // controllers.lqg_ltr as the controls set it (mu and q on log sliders).
  tuning() {
    const round = (x) => Number(x.toPrecision(3));
    return {
      mu: round(10 ** Number($('design-mu').value)),
      q: round(10 ** Number($('design-q').value)),
      omega_p_rad_s: Number($('design-omega').value),
      design_speed_kn: Number($('design-speed').value),
      turbine_speed_weight: Number($('design-weight').value),
    };
  }

  // The readouts beside the sliders (and what a screen reader says for the log sliders).
  readouts() {
    const t = this.tuning();
    $('design-mu-out').textContent = t.mu;
    $('design-q-out').textContent = t.q;
    $('design-omega-out').textContent = t.omega_p_rad_s;
    $('design-speed-out').textContent = t.design_speed_kn;
    $('design-mu').setAttribute('aria-valuetext', `mu = ${t.mu}`);
    $('design-q').setAttribute('aria-valuetext', `q = ${t.q}`);
    return t;
  }

  update() {
    // The readouts follow at once; the design waits for the slider to rest.
    const t = this.readouts();
    clearTimeout(this.timer);
    const results = [$('design-margins'), $('design-poles'), $('design-plots')];
    const bad = numberBoxError($('design-weight'), 'turbine-speed weight');
    if (bad) {
      this.ok = false;
      $('design-run').disabled = true;
      markStale(results, $('design-status'), true, $('design-weight'), bad);
      return;
    }
    this.timer = setTimeout(() => {
      const sc = this.baseScenario();
      sc.controllers.lqg_ltr = t;
      this.client().request(REQUEST.design, { scenario: JSON.stringify(sc) }).then(({ result }) => {
        this.ok = true;
        markStale(results, $('design-status'), false);
        $('design-run').disabled = !result.stable;
        const pms = result.input_margins.map((m) => m.phase_margin_deg).filter((x) => x !== null && x !== undefined);
        const worst = pms.length ? ` Smallest phase margin at a plant input: ${Math.min(...pms).toFixed(0)}°.` : '';
        $('design-status').textContent = result.stable ? `Stable.${worst}` : 'UNSTABLE: a closed-loop pole in the right half plane.';
        $('design-status').className = result.stable ? '' : 'error';
        this.show(result);
      }, (e) => {
        if (e.cancelled) return;
        this.ok = false;
        $('design-run').disabled = true;
        markStale(results, $('design-status'), true, null, e.message);
      });
    }, DESIGN.debounceMs);
  }

  show(r) {
    const num = (x, d = 1) => (x === null || x === undefined ? '∞' : Number(x).toFixed(d));
    $('design-margins').querySelector('tbody').replaceChildren(...r.input_margins.map((m) => el('tr', {},
      el('th', { scope: 'row', textContent: INPUTS[m.input] || `input ${m.input + 1}` }),
      el('td', { textContent: `+${num(m.gain_margin_db)} / ${m.gain_reduction_margin_db === null ? '−∞' : num(m.gain_reduction_margin_db)}` }),
      el('td', { textContent: num(m.phase_margin_deg, 0) }),
      el('td', { textContent: m.crossover_rad_s === null ? '–' : Number(m.crossover_rad_s).toPrecision(3) }))));
    $('design-poles').querySelector('tbody').replaceChildren(...r.closed_loop_poles.map((p) => el('tr', {}, ...poleCells(p))));
    this.box.clear();
    const sv = r.singular_values;
    const x = { data: sv.frequency_rad_s, label: 'frequency [rad/s]', distr: 3 };
    const axis = [{ scale: 'y', label: 'singular value [dB]' }];
    const zero = [{ value: 0, label: '0 dB', color: '#6b6b6b' }];
    this.box.line('Loop G(s)(I/s)K(s) (solid) and the Kalman target it recovers (dashed)', x, [
      ...sv.loop.map((c, k) => ({ data: c.map(db), label: `loop σ${k + 1}`, color: CURVES[k] })),
      ...sv.kalman_target.map((c, k) => ({ data: c.map(db), label: `target σ${k + 1}`, color: CURVES[k], dash: [6, 4] })),
    ], axis, { levels: zero });
    this.box.line('Command following (I + L)⁻¹L', x,
      sv.command_following.map((c, k) => ({ data: c.map(db), label: `σ${k + 1}`, color: CURVES[k] })), axis, { levels: zero });
    drawPoleMap(this.box, r.closed_loop_poles, DESIGN.poleMapMax);
  }
}
