// The stability tab (thesis ch. 4): operating point from the controls, steady state, poles, a
// pole map and Bode plots of the linearized IPS models, recomputed as the controls move.
import { IPS } from './config.js';
import { $, el, row } from './dom.js';
import { REQUEST } from './protocol.js';
import { sizedCanvas } from './plots.js';

const STEADY = {
  motor: [['t_m0', 'T_m0 [N m]'], ['t_ref0', 'T** [N m]'], ['omega_r0', 'ω_r0 [rad/s]'], ['omega_s0', 'ω_s0 [rad/s]'], ['i_s_mag', '|i_s| [A]'], ['i_r_mag', '|i_r| [A]'], ['v_s_mag', '|v_s| [V]'],
    ['t_threshold', 'torque threshold [N m]']],
  generator: [['v_gs_mag', '|v_gs| [V]'], ['i_gs_mag', '|i_gs| [A]'], ['i_fd', 'i_fd [A]'], ['v_rect_v', 'ṽ_dc, rectifier output [V]'], ['v_dc', 'v_dc, bus [V]'], ['i_dc', 'i_dc [A]'], ['cos_phi', 'cos φ']],
};
// The controls of the operating point, by declaration path (ipsMeta); the other inputs (the
// synchronous speed, the Bode range) take their declared defaults.
const CONTROLS = { torque_nm: 'ips-torque', load_a: 'ips-load', v_fd_v: 'ips-vfd' };
const TRANSFER = {
  closed: { motor: 'torque command to torque', generator: 'voltage set point to bus voltage' },
  open: { motor: 'stator voltage to stator current magnitude', generator: 'field voltage to droop feedback' },
};

export class StabilityTab {
  // client(): the current worker client (it changes after a cancel); box: a PlotBox.
  constructor(client, box) {
    this.client = client;
    this.box = box;
    this.timer = null;
    this.changed = null;
    this.meta = null;
    for (const id of ['ips-side', 'ips-loop', ...Object.values(CONTROLS)]) $(id).addEventListener('input', () => { this.changed = $(id); this.update(); });
  }

  // The declarations of the operating point (the wasm's ipsMeta): each control's label, range (a
  // declaration's span: the part of the model's range the page offers) and starting value.
  setMeta(meta) {
    this.meta = Object.fromEntries(meta.map((m) => [m.path, m]));
    for (const [path, id] of Object.entries(CONTROLS)) {
      const m = this.meta[path], input = $(id);
      const [lo, hi] = m.span || [m.min, m.max];
      document.querySelector(`label[for="${id}"]`).textContent = `${m.label} [${m.unit}]`;
      input.title = m.help;
      Object.assign(input, { min: lo, max: hi, step: IPS.steps[path] });
      input.value = m.default;
    }
    if (!$('panel-ips').hidden) this.update();
  }

  results() { return [$('ips-steady'), $('ips-poles'), $('ips-plots')]; }

  args() {
    const point = Object.fromEntries(Object.values(this.meta).map((m) => [m.path, m.default]));
    for (const [path, id] of Object.entries(CONTROLS)) point[path] = Number($(id).value);
    return { side: $('ips-side').value, closed: $('ips-loop').value === 'closed', point };
  }

  update() {
    clearTimeout(this.timer);
    if (!this.meta) return; // the simulator is loading: the tab is filled once it is ready
    this.timer = setTimeout(() => {
      const a = this.args();
      for (const e of document.querySelectorAll('.ips-motor')) e.hidden = a.side !== 'motor';
      for (const e of document.querySelectorAll('.ips-gen')) e.hidden = a.side !== 'generator';
      $('ips-torque-out').textContent = a.point.torque_nm;
      $('ips-load-out').textContent = a.point.load_a;
      const vfd = this.meta.v_fd_v;
      const bad = a.side === 'generator' ? numberBoxError($('ips-vfd'), `${vfd.label} [${vfd.unit}]`) : null;
      if (bad) { markStale(this.results(), $('ips-status'), true, $('ips-vfd'), bad); return; }
      this.client().request(REQUEST.ips, { args: a }).then(({ result }) => {
        markStale(this.results(), $('ips-status'), false);
        $('ips-status').textContent = result.linear.stable ? 'Stable: every pole in the left half plane.' : 'UNSTABLE: a pole in the right half plane (the red ring on the pole map).';
        $('ips-status').className = result.linear.stable ? '' : 'error';
        this.show(result, a);
      }, (e) => {
        if (e.cancelled) return;
        markStale(this.results(), $('ips-status'), true, this.changed, e.message);
      });
    }, IPS.debounceMs);
  }

  show(r, a) {
    const st = r.steady_state;
    const rows = STEADY[a.side].map(([k, label]) => row(label, [Number(st[k]).toPrecision(5)]));
    // Eqs. 4.23-4.24: above the torque threshold the rotor-flux limit alters the slip (Figs. 4-8
    // and 4-9 compare the two regimes).
    if (a.side === 'motor') rows.push(row('rotor-flux limit', [st.above_threshold ? 'active (T** above the threshold)' : 'not active (T** below the threshold)']));
    $('ips-steady').querySelector('tbody').replaceChildren(...rows);
    $('ips-poles').querySelector('tbody').replaceChildren(...r.linear.poles.map((p) => el('tr', {}, ...poleCells(p))));
    this.box.clear();
    const what = TRANSFER[a.closed ? 'closed' : 'open'][a.side];
    const curves = { magnitude_db: r.bode.magnitude_db, phase_deg: unwrapDeg(r.bode.phase_deg) };
    for (const [key, label] of [['magnitude_db', 'magnitude [dB]'], ['phase_deg', 'phase [deg]']]) {
      this.box.line(`Bode ${label}: ${what}`, { data: r.bode.frequency_hz, label: 'frequency [Hz]', distr: 3 },
        [{ data: curves[key], label, color: '#0b5cad' }], [{ scale: 'y', label }]);
    }
    // After the Bode pair, which stands one above the other (one column: their frequency axes line up).
    this.poleMap(r.linear.poles);
  }

  poleMap(poles) { drawPoleMap(this.box, poles, IPS.poleMapMax); }
}

// Phase without the +-180 deg jumps of the principal value: each step taken the short way round
// (a Bode phase plot drawn with vertical jumps reads as a resonance that is not there).
export function unwrapDeg(phase) {
  const out = [];
  let shift = 0;
  for (let i = 0; i < phase.length; i++) {
    if (i > 0 && phase[i] !== null && phase[i - 1] !== null) {
      const d = phase[i] - phase[i - 1];
      shift -= 360 * Math.round(d / 360);
    }
    out.push(phase[i] === null ? null : phase[i] + shift);
  }
  return out;
}

// The complex plane with the stable half shaded, one scale on both axes (a damping ratio's line
// keeps its angle: zeta = 0.7 is drawn at 45 deg); stable poles as crosses, unstable ones as red
// rings with a cross, the right half plane wide enough to hold them. Poles faster than `max`
// [1/s] are listed but left off the picture so the slow ones stay readable.
export function drawPoleMap(box, poles, max) {
  const shown = poles.filter((p) => Math.hypot(p.re, p.im) < max);
  const off = poles.length - shown.length;
  const unstable = shown.filter((p) => p.re > 0);
  const title = `Pole map [1/s, rad/s]${off ? ` (${off} pole(s) faster than ${max} /s off the picture)` : ''}`;
  const name = (p) => `${p.re.toPrecision(3)}${p.im >= 0 ? '+' : ''}${p.im.toPrecision(3)}j`;
  const aria = `Pole map: ${shown.map(name).join(', ')}${unstable.length ? `; unstable: ${unstable.map(name).join(', ')}` : ''}${off ? `; ${off} faster pole(s) not drawn` : ''}`;
  box.canvas(title, aria, (cv) => {
    const { g, w, h } = sizedCanvas(cv, 320);
    const left = Math.max(1, ...shown.map((p) => -p.re)) * 1.15;
    const right = Math.max(0.18 * left, ...unstable.map((p) => p.re * 1.3));
    const up = Math.max(...shown.map((p) => Math.abs(p.im)), 0) * 1.15;
    // One scale [px per unit] on both axes: the tighter of width and height.
    const k = Math.min((w - 8) / (left + right), up > 0 ? (h - 8) / (2 * up) : Infinity);
    const x0 = 4 + ((w - 8) - k * (left + right)) / 2 + k * left, y0 = h / 2;
    const px = (x) => x0 + x * k, py = (y) => y0 - y * k;
    g.fillStyle = '#eef6ee'; g.fillRect(0, 0, px(0), h);
    g.strokeStyle = '#888'; g.lineWidth = 1; g.beginPath(); g.moveTo(0, y0); g.lineTo(w, y0); g.moveTo(px(0), 0); g.lineTo(px(0), h); g.stroke();
    g.lineWidth = 2;
    for (const p of shown) {
      const X = px(p.re), Y = py(p.im);
      g.strokeStyle = p.re > 0 ? '#c0392b' : '#1f3a5f';
      g.beginPath(); g.moveTo(X - 5, Y - 5); g.lineTo(X + 5, Y + 5); g.moveTo(X + 5, Y - 5); g.lineTo(X - 5, Y + 5); g.stroke();
      if (p.re > 0) { g.beginPath(); g.arc(X, Y, 9, 0, 2 * Math.PI); g.stroke(); }
    }
    g.fillStyle = '#4a4a4a'; g.font = '11px system-ui';
    // The values at the picture's left and top edges.
    g.fillText(`${(-x0 / k).toPrecision(3)} /s`, 4, y0 - 4);
    // Right of the imaginary axis where it fits, else left of it (a phone's narrow picture).
    const top = (y0 / k).toPrecision(3);
    const im = `${top} rad/s`, tw = g.measureText(im).width;
    g.fillText(im, px(0) + 4 + tw <= w - 2 ? px(0) + 4 : px(0) - 4 - tw, 12);
    if (unstable.length) { g.fillStyle = '#c0392b'; g.fillText('unstable', Math.min(px(unstable[0].re) + 12, w - 50), py(unstable[0].im) - 10); }
  });
}

// A pole's table cells: real part, imaginary part (rounding noise of a real pole shown as 0) and
// damping.
export function poleCells(p) {
  const im = Math.abs(p.im) <= 1e-9 * Math.max(1, Math.abs(p.re)) ? 0 : p.im;
  return [p.re, im, p.damping].map((x) => el('td', { textContent: Number(x).toPrecision(4) }));
}

// A number box's own problem (empty, not a number, outside its min..max), or null.
export function numberBoxError(input, name) {
  const v = input.value.trim() === '' ? NaN : Number(input.value);
  const [lo, hi] = [Number(input.min), Number(input.max)];
  if (Number.isFinite(v) && v >= lo && v <= hi) return null;
  return `${name} = ${input.value.trim() === '' ? '(empty)' : input.value.slice(0, 20)}: must be a number from ${lo} to ${hi}`;
}

// After an error the last results stay, dimmed and marked as not following the controls; the box
// at fault is marked invalid (aria-invalid, its message read by aria-describedby).
export function markStale(results, status, stale, input = null, message = '') {
  for (const r of results) r.classList.toggle('stale', stale);
  if (stale) {
    status.textContent = `${message} (the results below are still those of the last valid values)`;
    status.className = 'error';
  }
  for (const i of document.querySelectorAll(`[aria-describedby="${status.id}"]`)) { i.removeAttribute('aria-invalid'); i.removeAttribute('aria-describedby'); }
  if (stale && input) { input.setAttribute('aria-invalid', 'true'); input.setAttribute('aria-describedby', status.id); }
}
