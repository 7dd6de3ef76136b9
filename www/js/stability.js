// The stability tab (thesis ch. 4): operating point from the controls, steady state, poles, a
// pole map and Bode plots of the linearized IPS models, recomputed as the controls move.
import { IPS } from './config.js';
import { $, el, row } from './dom.js';
import { REQUEST } from './protocol.js';
import { sizedCanvas } from './plots.js';

const STEADY = {
  motor: [['t_m0', 'T_m0 [N m]'], ['t_ref0', 'T** [N m]'], ['omega_r0', 'ω_r0 [rad/s]'], ['omega_s0', 'ω_s0 [rad/s]'], ['i_s_mag', '|i_s| [A]'], ['i_r_mag', '|i_r| [A]'], ['v_s_mag', '|v_s| [V]']],
  generator: [['v_gs_mag', '|v_gs| [V]'], ['i_gs_mag', '|i_gs| [A]'], ['i_fd', 'i_fd [A]'], ['v_dc_rect', 'ṽ_dc [V]'], ['v_dc', 'v_dc, bus [V]'], ['i_dc', 'i_dc [A]'], ['cos_phi', 'cos φ']],
};
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
    for (const id of ['ips-side', 'ips-loop', 'ips-torque', 'ips-load', 'ips-vfd']) $(id).addEventListener('input', () => this.update());
  }

  args() {
    return {
      side: $('ips-side').value, closed: $('ips-loop').value === 'closed',
      omega: IPS.omegaRadS, vfd: Number($('ips-vfd').value), load: Number($('ips-load').value), torque: Number($('ips-torque').value),
      from_hz: IPS.fromHz, to_hz: IPS.toHz, points: IPS.points,
    };
  }

  update() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => {
      const a = this.args();
      for (const e of document.querySelectorAll('.ips-motor')) e.hidden = a.side !== 'motor';
      for (const e of document.querySelectorAll('.ips-gen')) e.hidden = a.side !== 'generator';
      $('ips-torque-out').textContent = a.torque;
      $('ips-load-out').textContent = a.load;
      this.client().request(REQUEST.ips, { args: a }).then(({ result }) => {
        $('ips-status').textContent = result.stable ? 'Stable: every pole in the left half plane.' : 'UNSTABLE: a pole in the right half plane.';
        $('ips-status').className = result.stable ? '' : 'error';
        this.show(result, a);
      }, (e) => {
        if (e.cancelled) return;
        $('ips-status').textContent = e.message;
        $('ips-status').className = 'error';
      });
    }, IPS.debounceMs);
  }

  show(r, a) {
    const st = r.steady_state;
    $('ips-steady').querySelector('tbody').replaceChildren(...STEADY[a.side].map(([k, label]) => row(label, [Number(st[k]).toPrecision(5)])));
    $('ips-poles').querySelector('tbody').replaceChildren(...r.poles.map((p) => {
      const tr = document.createElement('tr');
      tr.append(...[p.re, p.im, p.damping].map((x) => el('td', { textContent: Number(x).toPrecision(4) })));
      return tr;
    }));
    this.box.clear();
    this.poleMap(r.poles);
    const what = TRANSFER[a.closed ? 'closed' : 'open'][a.side];
    for (const [key, label] of [['magnitude_db', 'magnitude [dB]'], ['phase_deg', 'phase [deg]']]) {
      this.box.line(`Bode ${label}: ${what}`, { data: r.bode.frequency_hz, label: 'frequency [Hz]', distr: 3 },
        [{ data: r.bode[key], label, color: '#0b5cad' }], [{ scale: 'y', label }]);
    }
  }

  poleMap(poles) { drawPoleMap(this.box, poles, IPS.poleMapMax); }
}

// The complex plane with the stable half shaded; poles faster than `max` [1/s] are listed
// but left off the picture so the slow ones stay readable.
export function drawPoleMap(box, poles, max) {
  const shown = poles.filter((p) => Math.hypot(p.re, p.im) < max);
  const off = poles.length - shown.length;
  const title = `Pole map [1/s, rad/s]${off ? ` (${off} pole(s) faster than ${max} /s off the picture)` : ''}`;
  const aria = `Pole map: ${shown.map((p) => `${p.re.toPrecision(3)}${p.im >= 0 ? '+' : ''}${p.im.toPrecision(3)}j`).join(', ')}`;
  box.canvas(title, aria, (cv) => {
    const { g, w, h } = sizedCanvas(cv, 320);
    const span = Math.max(1, ...shown.map((p) => Math.max(Math.abs(p.re), Math.abs(p.im)))) * 1.15;
    const px = (x) => w * 0.85 + (x / span) * w * 0.8, py = (y) => h / 2 - (y / span) * h * 0.45;
    g.fillStyle = '#eef6ee'; g.fillRect(0, 0, px(0), h);
    g.strokeStyle = '#888'; g.beginPath(); g.moveTo(0, py(0)); g.lineTo(w, py(0)); g.moveTo(px(0), 0); g.lineTo(px(0), h); g.stroke();
    g.strokeStyle = '#c0392b'; g.lineWidth = 2;
    for (const p of shown) {
      const X = px(p.re), Y = py(p.im);
      g.beginPath(); g.moveTo(X - 5, Y - 5); g.lineTo(X + 5, Y + 5); g.moveTo(X + 5, Y - 5); g.lineTo(X - 5, Y + 5); g.stroke();
    }
    g.fillStyle = '#4a4a4a'; g.font = '11px system-ui';
    g.fillText(`${(-span).toPrecision(3)} /s`, 4, py(0) - 4);
    // Right of the imaginary axis where it fits, else left of it (a phone's narrow picture).
    const im = `${span.toPrecision(3)} rad/s`, tw = g.measureText(im).width;
    g.fillText(im, px(0) + 4 + tw <= w - 2 ? px(0) + 4 : px(0) - 4 - tw, 12);
  });
}
