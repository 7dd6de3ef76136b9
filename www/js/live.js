// Live views (issue 14): the drive train of Fig. 2-1 with its power flowing, the stern in waves
// (Figs. 5-13 to 5-15 as a picture) and the ship in its seaway from above, drawn from the trace
// at the playback time; play/pause, speed and a scrubber whose time is the plots' cursor.
// Every number drawn is a trace value at the cursor (rows interpolated linearly while playing,
// the row itself after a seek); the hull comes from hullProfile and the sea surface from the
// run's own wave components summed in Rust (Sea). No physics here.
import init, { Sea, hullProfile } from '../pkg/aes_web.js';
import { LIVE } from './config.js';
import { el } from './dom.js';

// The page's own copy of the wasm, for pictures only (the worker runs the simulations).
let wasm = null;
const loadWasm = () => (wasm = wasm || init());
const reducedMotion = window.matchMedia('(prefers-reduced-motion: reduce)');
const C = LIVE.colors;

// Index of the last row at or before t (t_s increasing).
function rowAt(ts, t) {
  let lo = 0, hi = ts.length - 1;
  if (t <= ts[0]) return 0;
  if (t >= ts[hi]) return hi;
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (ts[m] <= t) lo = m; else hi = m; }
  return lo;
}

const mw = (w) => `${(w / 1e6).toFixed(1)} MW`;
const pct = (x) => (Number.isFinite(x) ? `${(100 * x).toFixed(1)} %` : '–');
// What a stage keeps of the power through it: out/in flowing forward, in/out flowing back (a
// braking motor passes the shaft's power to the bus); none while the flow turns round.
const keeps = (out, into) => (into > 0 && out >= 0 ? `keeps ${pct(out / into)}` : into < 0 && out < 0 ? `keeps ${pct(into / out)}` : 'flow turning');
// The ship's share: above 100 % only while the ship slows (resistance above thrust; no propeller
// turns as much as 90 % of its shaft power into thrust power), its momentum then paying the rest.
const shipShare = (out, into) => (into > 0 && out > into ? `slows: ${pct(out / into)}` : keeps(out, into));
// The hub's place against the local surface (eq. 2.57 as printed can put it above).
const hubText = (hub) => (hub >= 0 ? `hub ${hub.toFixed(2)} m below the surface` : `hub ${(-hub).toFixed(2)} m above the surface`);
const signed = (x, d = 2) => `${x >= 0 ? '+' : '−'}${Math.abs(x).toFixed(d)}`;

// A canvas that follows its box's width at a CSS height; draw() redraws after a resize.
class View {
  constructor(title, label, heightVar, onResize) {
    this.canvas = el('canvas', { className: 'live-canvas', attrs: { role: 'img', 'aria-label': label, 'aria-describedby': 'live-text' } });
    this.canvas.style.height = `var(${heightVar})`;
    this.figure = el('figure', { className: 'plot live-view' }, el('h3', { textContent: title }), this.canvas);
    this.w = 0; this.h = 0;
    new ResizeObserver(() => {
      const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
      if (!w || !h || (w === this.w && h === this.h)) return;
      const dpr = window.devicePixelRatio || 1;
      this.w = w; this.h = h;
      this.canvas.width = Math.round(w * dpr); this.canvas.height = Math.round(h * dpr);
      this.g = this.canvas.getContext('2d');
      this.g.setTransform(dpr, 0, 0, dpr, 0, 0);
      onResize();
    }).observe(this.canvas);
  }
  ready() { return this.g && this.w > 0 && !this.figure.hidden; }
}

export class LiveViews {
  // root: the section to fill; plots: the PlotBox whose time plots share the cursor.
  constructor(root, plots) {
    this.root = root;
    this.plots = plots;
    this.cols = null;
    this.t = 0; this.playing = false; this.speed = LIVE.defaultSpeed;
    this.frameMs = []; this.log = []; this.dashPhase = 0; this.lastText = 0; this.drawn = {};
    this.play = el('button', { type: 'button', id: 'live-play', textContent: 'Play' });
    this.speedSel = el('select', { id: 'live-speed' }, ...LIVE.speeds.map((s) => el('option', { value: String(s), textContent: `${s}×` })));
    this.speedSel.value = String(this.speed);
    this.scrub = el('input', { type: 'range', id: 'live-time', min: '0', max: '1', step: 'any', value: '0' });
    this.clock = el('output', { id: 'live-clock', attrs: { for: 'live-time' } });
    const bar = el('div', { className: 'row live-bar' }, this.play,
      el('label', { htmlFor: 'live-speed', textContent: 'Speed (times real time)' }), this.speedSel,
      el('label', { htmlFor: 'live-time', textContent: 'Time' }), this.scrub, this.clock);
    const redraw = () => this.draw();
    this.train = new View('Drive train (Fig. 2-1): power flows from the turbines to the ship', 'The drive train: four gas turbines, four generators, two DC buses, two inverters, two motors, two propellers and the ship, with the power each passes on', '--live-train-h', redraw);
    this.stern = new View('The stern in waves, from the side (Figs. 5-13 to 5-15)', 'The stern from the side: the hull, the propeller disc at its hub depth and the wave surface', '--live-side-h', redraw);
    this.plan = new View('The ship in its seaway, from above', 'The ship from above on its wave field, with its track, heading and rudder', '--live-side-h', redraw);
    this.text = el('p', { id: 'live-text', className: 'live-text' });
    this.note = el('p', { className: 'hint' });
    root.replaceChildren(el('h2', { id: 'live-h', textContent: 'Watch it happen' }), bar,
      this.train.figure, el('div', { className: 'live-side' }, this.stern.figure, this.plan.figure), this.text, this.note);
    this.play.addEventListener('click', () => (this.playing ? this.pause() : this.start()));
    this.speedSel.addEventListener('change', () => { this.speed = Number(this.speedSel.value); this.rate = null; });
    this.scrub.addEventListener('input', () => this.seek(Number(this.scrub.value), { fromScrubber: true }));
    this.loop = (now) => this.frame(now);
    // A test hook: what was drawn, frame times and the playback rate (no pixel-peeping).
    window.__liveViews = this;
  }

  // After a run: the trace, pageConstants and the scenario. Resolves once the pictures are ready.
  show(cols, constants, scenario, text = JSON.stringify(scenario)) {
    return this.queued(async () => {
      this.streaming = false;
      await this.prepare(cols, constants, scenario, text);
      this.attachPlots();
      this.scrub.disabled = false; this.play.disabled = false;
      this.seek(this.t0);
    });
  }

  // During a run: the rows recorded since the last call ({name: Float64Array}); the first call of
  // a run brings the page constants. The views show the newest row; the plots come at the end.
  follow(rows, constants, scenario, text = JSON.stringify(scenario)) {
    return this.queued(async () => {
      if (constants) {
        this.streaming = true;
        this.followed = 0;
        await this.prepare(rows, constants, scenario, text);
        this.scrub.disabled = true; this.play.disabled = true;
      } else if (this.streaming && this.cols) {
        const cat = (a, b) => { const c = new Float64Array(a.length + b.length); c.set(a); c.set(b, a.length); return c; };
        const cols = {};
        for (const name of Object.keys(this.cols)) cols[name] = cat(this.cols[name], rows[name]);
        this.setColumns(cols);
      } else return;
      this.followed++;
      this.t = this.t1; this.snapped = true;
      this.scrub.value = String(this.t);
      this.draw();
    });
  }

  // Calls run one after another (a chunk may arrive while the wasm is still loading); a failed
  // call is reported by its own promise and does not stop the ones after it.
  queued(fn) {
    const next = (this.queue || Promise.resolve()).catch(() => {}).then(fn);
    this.queue = next;
    return next;
  }

  // text: the scenario as JSON text (a replayed trial's seed needs all 64 bits).
  async prepare(cols, constants, scenario, text) {
    this.pause();
    this.k = constants;
    this.from = scenario.sea.kind === 'calm' ? null : scenario.sea.from_deg;
    const w = constants.warnings;
    this.note.textContent = `Both plants draw the trace's figures (it records sums and means over machines; the shafts' speeds are each shaft's own). Block outlines turn red with a word when a limit is reached: turbine overspeed above ${w.turbine_overspeed_pu} pu, bus voltage outside ${w.bus_voltage_low_pu} to ${w.bus_voltage_high_pu} pu, motor at its ${w.motor_power_limit_pu} pu rating, brake resistor on. What a block keeps is its stage's share in Table 5.7's chain: an inverter's is the whole power electronics (rectifier, stator resistance, notching, inverter); the ship's passes 100 % only while it slows, its momentum adding to the propellers' work. Arrow width follows the power; dashes move with it${reducedMotion.matches ? ' (held still: your system asks for reduced motion)' : ''}.`;
    await loadWasm();
    if (this.sea) this.sea.free();
    this.sea = new Sea(text);
    this.hull = JSON.parse(hullProfile(text));
    this.setColumns(cols);
    this.root.hidden = false;
  }

  setColumns(cols) {
    this.cols = cols;
    const ts = cols.t_s;
    this.t0 = ts[0]; this.t1 = ts[ts.length - 1];
    this.inWaves = cols.h_over_r.some((v) => v !== cols.h_over_r[0]);
    this.stern.figure.hidden = !this.inWaves;
    this.scrub.min = String(this.t0); this.scrub.max = String(this.t1);
    this.scrub.step = String(ts.length > 1 ? ts[1] - ts[0] : 1);
    let m = 0.5;
    for (const x of cols.wave_stern_m) m = Math.max(m, Math.abs(x));
    this.waveScale = m;
  }

  // Where the views stand, for a link: {at, speed} (null when they show nothing).
  view() { return this.cols && !this.root.hidden && !this.streaming ? { at: this.t, speed: this.speed } : null; }

  // Opens the views at a link's place (after the run's show()); a speed not on the menu is the
  // nearest that is.
  place({ at, speed }) {
    return this.queued(() => {
      const near = LIVE.speeds.reduce((a, b) => (Math.abs(Math.log(b / speed)) < Math.abs(Math.log(a / speed)) ? b : a));
      this.speed = near; this.speedSel.value = String(near);
      this.seek(at);
      this.root.scrollIntoView({ block: 'start' });
    });
  }

  hide() { this.queued(() => { this.pause(); this.streaming = false; this.root.hidden = true; this.cols = null; }); }

  // The plots' cursor follows the playback; a click on a time plot moves the playback there.
  attachPlots() {
    for (const u of this.timePlots()) {
      if (u.liveAttached) continue;
      u.liveAttached = true;
      let down = null;
      u.over.addEventListener('mousedown', (e) => { down = [e.clientX, e.clientY]; });
      u.over.addEventListener('click', (e) => {
        if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 3) return; // a zoom drag
        const rect = u.over.getBoundingClientRect();
        this.seek(u.posToVal(e.clientX - rect.left, 'x'));
      });
      u.over.addEventListener('mouseleave', () => requestAnimationFrame(() => this.cursorToPlots()));
    }
  }

  timePlots() { return this.plots.plots.filter((u) => u.linked && u.over); }

  cursorToPlots() {
    if (!this.cols) return;
    for (const u of this.timePlots()) {
      const left = u.valToPos(this.t, 'x');
      u.setCursor({ left: left >= 0 && left <= u.over.clientWidth ? left : -10, top: u.over.clientHeight / 2 }, false, false);
    }
  }

  start() {
    if (!this.cols) return;
    if (this.t >= this.t1) this.t = this.t0;
    this.playing = true;
    this.play.textContent = 'Pause';
    this.log = []; this.frameMs = [];
    this.last = null; this.rate = null;
    requestAnimationFrame(this.loop);
  }

  pause() {
    this.playing = false;
    this.play.textContent = 'Play';
  }

  // Moves the playback to time t [s] (snapped to the trace's row at or before it).
  seek(t, { fromScrubber = false } = {}) {
    if (!this.cols) return;
    const ts = this.cols.t_s;
    // (a hair of tolerance: 10.5 from a link is the row recorded at 10.500000000000002)
    this.t = ts[rowAt(ts, Math.min(this.t1, Math.max(this.t0, t)) * (1 + 1e-12) + 1e-9)];
    this.snapped = true;
    this.lastText = 0;
    if (!fromScrubber) this.scrub.value = String(this.t);
    this.draw();
  }

  frame(now) {
    if (!this.playing) return;
    if (this.last != null) {
      const dt = Math.min(0.25, (now - this.last) / 1000);
      this.t = Math.min(this.t1, this.t + dt * this.speed);
      if (!reducedMotion.matches) this.dashPhase += dt;
      // Playback rate: simulated seconds per wall second since the play started.
      if (!this.rate) this.rate = { wall0: now, t0: this.t - dt * this.speed, frames: 0 };
      // (not the last frame, whose step the end of the trace cuts short)
      if (this.t < this.t1) { this.rate.frames++; this.rate.wall = now; this.rate.t = this.t; }
    }
    this.last = now;
    this.snapped = false;
    this.scrub.value = String(this.t);
    this.draw();
    if (this.t >= this.t1) { this.pause(); return; }
    requestAnimationFrame(this.loop);
  }

  // The value of a trace column at the playback time.
  v(name) {
    const c = this.cols[name];
    if (this.snapped || this.f === 0) return c[this.i];
    return c[this.i] + this.f * (c[this.i + 1] - c[this.i]);
  }

  draw() {
    if (!this.cols || this.root.hidden) return;
    const t0 = performance.now();
    const ts = this.cols.t_s;
    this.i = rowAt(ts, this.t);
    this.f = this.i + 1 < ts.length ? (this.t - ts[this.i]) / (ts[this.i + 1] - ts[this.i]) : 0;
    this.drawn = { t: this.t, row: this.i, snapped: this.snapped };
    if (this.train.ready()) this.drawTrain(this.train);
    if (this.inWaves && this.stern.ready()) this.drawStern(this.stern);
    if (this.plan.ready()) this.drawPlan(this.plan);
    if (!this.streaming) this.cursorToPlots();
    this.clock.value = this.streaming ? `running: ${this.t.toFixed(1)} s` : `${this.t.toFixed(1)} s of ${this.t1.toFixed(0)} s`;
    this.scrub.setAttribute('aria-valuetext', `${this.t.toFixed(1)} seconds of ${this.t1.toFixed(0)}`);
    const now = performance.now();
    if (!this.playing || now - this.lastText > LIVE.textEveryMs) { this.lastText = now; this.text.textContent = this.describe(); }
    if (this.playing && this.log.length < 20000) {
      const d = this.drawn;
      this.log.push({ t: this.t, h_over_r: d.stern ? d.stern.h_over_r : null, disc_out: d.stern ? d.stern.disc_out_of_water : null, turbine_pu: this.v('turbine_speed_pu'), turbine_warn: d.train ? d.train.warn.turbine : null, turbine_edge: d.train ? d.train.turbineEdge : null });
    }
    this.frameMs.push(performance.now() - t0);
    if (this.frameMs.length > 2000) this.frameMs.splice(0, 1000);
  }

  // The live figures as text (the views' text alternative).
  describe() {
    const v = (n) => this.v(n), w = this.k.warnings;
    const parts = [`At ${this.t.toFixed(1)} s: turbines ${mw(v('p_turbine_w') / 4)} each at ${v('turbine_speed_pu').toFixed(3)} pu speed${v('turbine_speed_pu') > w.turbine_overspeed_pu ? ' (OVERSPEED)' : ''}`,
      `generators ${mw(v('p_generator_w') / 4)} each`, `buses at ${v('bus_voltage_pu').toFixed(3)} pu (${(v('bus_voltage_v') / 1e3).toFixed(2)} kV)`,
      `motors ${mw(v('p_motor_w') / 2)} each (${v('im_power_pu').toFixed(2)} pu)`, `propellers ${v('prop_rpm_1').toFixed(0)} and ${v('prop_rpm_2').toFixed(0)} rpm`,
      `ship ${v('ship_speed_kn').toFixed(1)} kn, heading ${v('heading_deg').toFixed(0)}°, rudder ${v('rudder_deg').toFixed(1)}°${v('rudder_deg') > 0.05 ? ' (to port)' : v('rudder_deg') < -0.05 ? ' (to starboard)' : ''}`];
    if (v('brake_power_w') > 0) parts.push(`brake resistors ${mw(v('brake_power_w'))}`);
    if (this.inWaves) parts.push(`wave at the stern ${signed(v('wave_stern_m'))} m, ${hubText(v('hub_depth_m'))}, h/R ${v('h_over_r').toFixed(2)} (${this.discState().text}), thrust kept ${pct(v('beta_t'))}`);
    return parts.join('; ') + '.';
  }

  discState() {
    // The levels of eq. 2.14 on h/R (pageConstants): disk at the surface, disk out of the water.
    const hr = this.v('h_over_r'), bt = this.v('beta_t'), lv = this.k.h_over_r_levels.map((l) => l.value);
    if (hr <= Math.min(...lv)) return { text: 'disc out of the water', loud: true };
    if (hr < Math.max(...lv)) return { text: 'disc breaks the surface', loud: true };
    if (bt < 1) return { text: 'ventilating', loud: true };
    return { text: 'submerged', loud: false };
  }

  // A block: rounded box with lines of text; warn: a word shown and the warning colours.
  block(g, x, y, w, h, lines, warn, fsMax = 14) {
    g.fillStyle = warn ? C.warn : C.block;
    g.strokeStyle = warn ? C.warnEdge : C.blockEdge;
    g.lineWidth = warn ? 3 : 1.2;
    g.beginPath(); g.roundRect(x, y, w, h, 6); g.fill(); g.stroke();
    const all = warn ? [...lines, warn] : lines;
    const fs = Math.max(10, Math.min(fsMax, Math.floor((h - 6) / all.length) - 2, Math.floor(w / 7.5)));
    g.textAlign = 'center'; g.textBaseline = 'middle';
    all.forEach((s, j) => {
      g.font = `${j === 0 ? '600 ' : ''}${fs}px system-ui, sans-serif`;
      g.fillStyle = warn && j === all.length - 1 ? C.warnEdge : C.text;
      g.fillText(s, x + w / 2, y + h / 2 + (j - (all.length - 1) / 2) * (fs + 2), w - 6);
    });
    return warn ? C.warnEdge : C.blockEdge;
  }

  // An arrow from (x0, y0) to (x1, y1) (along one axis) for power p [W] against a link rating
  // [W]: width with the power, dashes moving with it; reversed (other colour) when power flows back.
  arrow(g, x0, y0, x1, y1, p, rating) {
    const frac = Math.min(1.5, Math.abs(p) / rating);
    const width = Math.max(1.5, LIVE.arrowMaxPx * frac);
    const back = p < 0;
    const [ax, ay, bx, by] = back ? [x1, y1, x0, y0] : [x0, y0, x1, y1];
    const len = Math.hypot(bx - ax, by - ay) || 1, ux = (bx - ax) / len, uy = (by - ay) / len;
    const head = Math.min(10, len / 3);
    g.save();
    g.strokeStyle = back ? C.back : C.flow; g.fillStyle = g.strokeStyle;
    g.lineWidth = width;
    g.setLineDash([10, 6]);
    g.lineDashOffset = -this.dashPhase * LIVE.dashPxPerS * frac * this.speed;
    g.beginPath(); g.moveTo(ax, ay); g.lineTo(bx - ux * head, by - uy * head); g.stroke();
    g.setLineDash([]);
    const hw = width / 2 + 4;
    g.beginPath(); g.moveTo(bx, by); g.lineTo(bx - ux * head - uy * hw, by - uy * head + ux * hw); g.lineTo(bx - ux * head + uy * hw, by - uy * head - ux * hw); g.closePath(); g.fill();
    g.restore();
  }

  // Fig. 2-1 left to right (top to bottom on a narrow screen): stages along one axis (turbines,
  // generators, buses, inverters, motors, propellers, ship), the four sets across the other.
  drawTrain(view) {
    const { g, w, h } = view;
    const v = (n) => this.v(n), k = this.k, lv = k.warnings;
    g.clearRect(0, 0, w, h);
    const down = w < LIVE.trainVerticalBelowPx; // stages from top to bottom
    const along = down ? h : w, across = down ? w : h;
    const stage = along / 7, lane = across / 4;
    // Block extents along the flow and across it, and the picture position of (stage, lane).
    const big = (this.big = document.body.classList.contains('presenting')) ? 1.45 : 1; // presentation: larger blocks and type
    const bs = Math.min(stage * (down ? 0.7 : 0.8), 130 * big), bl = Math.min(lane * (down ? 0.92 : 0.86), (down ? 130 : 64) * big);
    const at = (st, ln) => (down ? [ln * lane, (st + 0.5) * stage] : [(st + 0.5) * stage, ln * lane]);
    const box = (st, ln, ext, lines, warn) => {
      const [cx, cy] = at(st, ln);
      const [bw, bh] = down ? [ext, bs] : [bs, ext];
      return this.block(g, cx - bw / 2, cy - bh / 2, bw, bh, lines, warn, fsMax);
    };
    const link = (st, ln, p, rating) => {
      const [x0, y0] = at(st, ln), [x1, y1] = at(st + 1, ln);
      if (down) this.arrow(g, x0, y0 + bs / 2, x1, y1 - bs / 2, p, rating);
      else this.arrow(g, x0 + bs / 2, y0, x1 - bs / 2, y1, p, rating);
    };
    const short = (down ? lane : bs) < 100; // narrow blocks: short names
    // One type size for every block: four lines in the smallest (a block with more shrinks alone).
    const fsMax = Math.max(10, Math.min(big > 1 ? 20 : 14, Math.floor(((down ? bs : bl) - 6) / 4) - 2));
    const pT = v('p_turbine_w') / 4, pG = v('p_generator_w') / 4, pI = v('p_inverter_w') / 2, pM = v('p_motor_w') / 2, pS = v('p_ship_w');
    const setRating = k.motor_rated_power_w / 2, plantRating = k.motor_rated_power_w;
    const speedPu = v('turbine_speed_pu'), busPu = v('bus_voltage_pu'), imPu = v('im_power_pu'), brake = v('brake_power_w');
    const warn = {
      turbine: speedPu > lv.turbine_overspeed_pu ? 'OVERSPEED' : null,
      bus: busPu < lv.bus_voltage_low_pu ? 'LOW' : busPu > lv.bus_voltage_high_pu ? 'HIGH' : null,
      motor: imPu >= lv.motor_power_limit_pu * 0.999 ? 'AT RATING' : null,
      brake: brake > 0 ? 'BRAKE ON' : null,
    };
    const d = this.drawn.train = { turbine_mw: pT / 1e6, generator_mw: pG / 1e6, inverter_mw: pI / 1e6, motor_mw: pM / 1e6, ship_mw: pS / 1e6, warn };
    const setLn = (s) => s + 0.5, plantLn = (p) => 2 * p + 1;
    // Arrows first, blocks over their ends.
    for (let s = 0; s < 4; s++) { link(0, setLn(s), pT, setRating); link(1, setLn(s), pG, setRating); }
    for (let p = 0; p < 2; p++) {
      link(2, plantLn(p), pI, plantRating);
      link(3, plantLn(p), pI, plantRating);
      link(4, plantLn(p), pM, plantRating);
      // Useful power (resistance times speed), half per shaft, into the one ship; backwards
      // when the propellers brake the ship (negative thrust).
      link(5, plantLn(p) + (p ? -0.3 : 0.3), v('thrust_kn') < 0 ? -pS / 2 : pS / 2, plantRating);
    }
    for (let s = 0; s < 4; s++) {
      d.turbineEdge = box(0, setLn(s), bl, [`${short ? 'GT' : 'Gas turbine'} ${s + 1}`, mw(pT), `${speedPu.toFixed(3)} pu`], warn.turbine);
      box(1, setLn(s), bl, [`${short ? 'Gen.' : 'Generator'} ${s + 1}`, mw(pG), keeps(v('p_generator_w'), v('p_turbine_w'))], null);
    }
    const wide = Math.min(2 * lane * 0.9, bl * 1.6);
    for (let p = 0; p < 2; p++) {
      box(2, plantLn(p), wide, [`DC bus ${p + 1}`, `${busPu.toFixed(3)} pu`, `${(v('bus_voltage_v') / 1e3).toFixed(2)} kV`, ...(warn.brake ? [`brake ${mw(brake / 2)}`] : [])], warn.bus || warn.brake);
      box(3, plantLn(p), wide, [`${short ? 'Inv.' : 'Inverter'} ${p + 1}`, mw(pI), keeps(v('p_inverter_w'), v('p_generator_w')), ...(short ? [] : [`${v('motor_voltage_pu').toFixed(2)} pu V`])], null);
      box(4, plantLn(p), wide, [`Motor ${p + 1}`, mw(pM), `${imPu.toFixed(2)} pu`, keeps(v('p_motor_w'), v('p_inverter_w'))], warn.motor);
      box(5, plantLn(p), wide, [`${short ? 'Prop.' : 'Propeller'} ${p + 1}`, `${v(`prop_rpm_${p + 1}`).toFixed(0)} rpm`, `β_T ${v('beta_t').toFixed(2)}`], null);
    }
    box(6, 2, Math.min(across * 0.5, 4 * bl), ['Ship', `${v('ship_speed_kn').toFixed(1)} kn`, `useful ${mw(pS)}`, ...(down ? [] : [`thrust ${(v('thrust_kn') / 1e3).toFixed(2)} MN`]), shipShare(v('p_ship_w'), v('p_motor_w'))], null);
  }

  // Largest vertical excursion of the stern over the run [m]: |heave| + x_p |pitch| (and, in
  // `deepest`, the disc's lowest point below the calm waterline [m]).
  sternReach() {
    const c = this.cols;
    if (!c || !c.heave_m || !c.pitch_deg) { this.deepest = 0; return 0; }
    if (this.reachOf === c) return this.reach;
    const xp = (this.k && this.k.prop_x_aft_m) || 0;
    let r = 0, deep = 0;
    for (let i = 0; i < c.heave_m.length; i++) r = Math.max(r, Math.abs(c.heave_m[i]) + xp * Math.abs((c.pitch_deg[i] * Math.PI) / 180));
    // The disc's lowest point below the calm waterline: the hub drawn at its depth below the
    // wave at the stern (a deep hub in a trough goes further down than the stern's own motion).
    if (c.hub_depth_m && c.wave_stern_m) {
      for (let i = 0; i < c.hub_depth_m.length; i++) deep = Math.max(deep, c.hub_depth_m[i] - c.wave_stern_m[i]);
    }
    this.reachOf = c;
    this.reach = Number.isFinite(r) ? r : 0;
    this.deepest = Number.isFinite(deep) ? deep + ((this.k && this.k.propeller_radius_m) || 0) : 0;
    return this.reach;
  }

  drawStern(view) {
    const { g, w, h } = view;
    const v = (n) => this.v(n), hull = this.hull, W = LIVE.stern, k = this.k;
    g.clearRect(0, 0, w, h);
    // The frame grows to hold the run's largest heave and pitch at the stern (the thesis' Appendix
    // A as printed heaves the ship by 16-18 m), so nothing leaves the picture.
    const reach = this.sternReach();
    const up = Math.max(W.upM, reach + 1), down = Math.max(W.downM, reach + 3, (this.deepest || 0) + 1);
    const s = Math.min(w / (W.aftM + W.foreM), h / (up + down));
    const ox = (w - (W.aftM + W.foreM) * s) / 2, oy = (h - (up + down) * s) / 2 + up * s;
    const X = (x) => ox + (x + W.aftM) * s, Z = (z) => oy - z * s; // hull x from the AP, z up
    // The hull x at the picture's edges: when a deep disc shrinks the scale, the water and the
    // hull still reach across the whole picture.
    const xLo = -ox / s - W.aftM, xHi = (w - ox) / s - W.aftM;
    const heave = v('heave_m'), pitch = (v('pitch_deg') * Math.PI) / 180, lcg = hull.lcg_m;
    const hx = lcg - k.prop_x_aft_m; // the hub, from the AP
    // Ship-fixed point -> picture: heave up, pitch bow down about the centre of gravity (small
    // angles, as the trace's motions are first order).
    const ship = (x, z) => [X(x), Z(z + heave - (x - lcg) * pitch)];
    // Sky and the wave surface along the ship's centreline: the run's wave components summed at
    // the ship's track position (Rust), the point at the hub drawn at the trace's value.
    g.fillStyle = C.sky; g.fillRect(0, 0, w, h);
    const n = 64, xs = new Float64Array(n + 1), north = new Float64Array(n + 1), east = new Float64Array(n + 1);
    const psi = (v('heading_deg') * Math.PI) / 180, x0 = v('x_m'), y0 = v('y_m');
    for (let j = 0; j <= n; j++) {
      xs[j] = xLo - 2 + ((xHi - xLo + 4) * j) / n;
      north[j] = x0 + (xs[j] - lcg) * Math.cos(psi); east[j] = y0 + (xs[j] - lcg) * Math.sin(psi);
    }
    const eta = this.sea.elevations(this.t, north, east);
    const waveStern = v('wave_stern_m'), hub = v('hub_depth_m'), R = k.propeller_radius_m;
    // The port hub (the trace's wave_stern_m): x_p aft of G and y to port (port is heading - 90 deg).
    const yPort = (k.shaft_y_m || [0])[0];
    const kernelAtHub = this.sea.elevations(this.t, Float64Array.of(x0 - k.prop_x_aft_m * Math.cos(psi) + yPort * Math.sin(psi)), Float64Array.of(y0 - k.prop_x_aft_m * Math.sin(psi) - yPort * Math.cos(psi)))[0];
    // The kernel's profile shifted so that it passes through the trace's value at the hub.
    const shift = waveStern - kernelAtHub;
    const surf = (x) => { const j = Math.max(0, Math.min(n - 1, Math.floor(((x - xs[0]) / (xs[n] - xs[0])) * n))); const f = (x - xs[j]) / (xs[j + 1] - xs[j]); return eta[j] + f * (eta[j + 1] - eta[j]) + shift; };
    const water = new Path2D();
    water.moveTo(X(xs[0]), h);
    for (let j = 0; j <= n; j++) water.lineTo(X(xs[j]), Z(eta[j] + shift));
    water.lineTo(X(xs[n]), h); water.closePath();
    // Hull profile, stern part.
    const hp = new Path2D();
    const idx = hull.x_m.map((x, j) => j).filter((j) => hull.x_m[j] <= Math.max(W.foreM, xHi) + 10);
    idx.forEach((j, m) => { const [px, pz] = ship(hull.x_m[j], hull.deck_z_m[j]); if (m) hp.lineTo(px, pz); else hp.moveTo(px, pz); });
    for (const j of [...idx].reverse()) { const [px, pz] = ship(hull.x_m[j], hull.keel_z_m[j]); hp.lineTo(px, pz); }
    hp.closePath();
    g.fillStyle = C.hull; g.fill(hp); g.strokeStyle = C.hullEdge; g.lineWidth = 1.2; g.stroke(hp);
    // The disc at the trace's hub depth below the trace's surface at the stern.
    const hubZ = waveStern - hub;
    const [dx] = ship(hx, 0);
    const dz = Z(hubZ), rpx = R * s;
    // Shaft from the hub into the hull.
    const [sx, sz] = ship(hx + 14, -k.hub_depth_m + 2.2);
    g.strokeStyle = C.hullEdge; g.lineWidth = 3; g.beginPath(); g.moveTo(dx, dz); g.lineTo(sx, sz); g.stroke();
    g.save(); g.fillStyle = 'rgba(46, 134, 193, 0.55)'; g.fill(water); g.restore();
    g.strokeStyle = '#1a5276'; g.lineWidth = 2;
    g.beginPath(); for (let j = 0; j <= n; j++) { const px = X(xs[j]), pz = Z(eta[j] + shift); if (j) g.lineTo(px, pz); else g.moveTo(px, pz); } g.stroke();
    // Disc seen from the side is a blade line; drawn as a circle (the disc turned to face us) so
    // the part out of the water shows.
    const disc = new Path2D(); disc.arc(dx, dz, rpx, 0, 2 * Math.PI);
    g.save(); g.clip(water); g.fillStyle = 'rgba(27, 27, 27, 0.55)'; g.fill(disc); g.restore();
    const air = new Path2D(); air.rect(0, 0, w, h); air.addPath(water);
    g.save(); g.clip(air, 'evenodd'); g.fillStyle = C.warn; g.fill(disc); g.restore();
    const state = this.discState();
    g.strokeStyle = state.loud ? C.discOut : C.disc; g.lineWidth = state.loud ? 3 : 2; g.stroke(disc);
    g.fillStyle = C.disc; g.beginPath(); g.arc(dx, dz, 3, 0, 2 * Math.PI); g.fill();
    // The surface at the stern (trace value) marked with a tick.
    const surfPx = Z(waveStern);
    g.strokeStyle = C.discOut; g.lineWidth = 2; g.beginPath(); g.moveTo(dx - rpx - 8, surfPx); g.lineTo(dx - rpx - 2, surfPx); g.stroke();
    if (state.text === 'ventilating') {
      g.fillStyle = 'rgba(255, 255, 255, 0.85)';
      for (let b = 0; b < 7; b++) { const a = (b / 7) * 2 * Math.PI + 0.4; g.beginPath(); g.arc(dx + Math.cos(a) * rpx * 0.8, dz - Math.sin(a) * rpx * 0.8, 3 + (b % 3), 0, 2 * Math.PI); g.fill(); }
    }
    this.drawn.stern = { hub_depth_m: hub, wave_stern_m: waveStern, kernel_wave_stern_m: kernelAtHub, h_over_r: v('h_over_r'), disc_top_px: dz - rpx, surface_px: surfPx,
      disc_out_of_water: dz - rpx < surfPx, state: state.text, surface_at_hub_m: surf(hx) };
    // Labels: a box in the top left corner (never over the disc).
    const lines = [[`h/R ${v('h_over_r').toFixed(2)}: ${state.text}`, state.loud], [`β_T ${v('beta_t').toFixed(2)} (thrust kept)`, false],
      [hubText(hub), false], [`wave at the stern ${signed(waveStern)} m`, false],
      [`heave ${signed(heave)} m, pitch ${signed(v('pitch_deg'), 1)}° bow down`, false]];
    const fs = Math.max(11, Math.min(this.big ? 20 : 15, Math.round(w / 45)));
    g.font = `${fs}px system-ui, sans-serif`; g.textAlign = 'left'; g.textBaseline = 'top';
    // Each line measured in its own font (a loud one is bold, so wider).
    const font = (loud) => `${loud ? '700 ' : ''}${fs}px system-ui, sans-serif`;
    const tw = Math.max(...lines.map(([t, loud]) => { g.font = font(loud); return g.measureText(t).width; })) + 10;
    g.fillStyle = 'rgba(255, 255, 255, 0.88)'; g.fillRect(4, 4, tw, lines.length * (fs + 3) + 6);
    lines.forEach(([t, loud], j) => { g.font = font(loud); g.fillStyle = loud ? C.discOut : C.text; g.fillText(t, 9, 7 + j * (fs + 3)); });
    // Scale and direction.
    g.fillStyle = C.text; g.strokeStyle = C.text; g.lineWidth = 2; g.textBaseline = 'bottom';
    const bar = 10 * s; g.beginPath(); g.moveTo(w - bar - 10, h - 8); g.lineTo(w - 10, h - 8); g.stroke();
    g.textAlign = 'right'; g.font = `${fs - 1}px system-ui, sans-serif`; g.fillText('10 m', w - 10, h - 11);
    g.fillText('bow →', w - 10, h - 12 - fs);
    g.textAlign = 'left'; g.fillStyle = C.muted;
    g.fillText(`${hull.name} stern, to scale`, 8, h - 8);
  }

  drawPlan(view) {
    const { g, w, h } = view;
    const v = (n) => this.v(n), hull = this.hull, P = LIVE.plan;
    const half = hull.lpp_m * P.spanOfLpp * Math.max(1, h / w);
    const s = Math.min(w, h) / (2 * half);
    const x0 = v('x_m'), y0 = v('y_m'), psi = (v('heading_deg') * Math.PI) / 180;
    const px = (east) => w / 2 + (east - y0) * s, py = (north) => h / 2 - (north - x0) * s;
    // The wave field on a coarse grid (summed in Rust), smoothed up to the canvas.
    const gw = P.grid, gh = Math.max(4, Math.round((P.grid * h) / w));
    if (!this.grid || this.grid.w !== gw || this.grid.h !== gh) {
      const c = document.createElement('canvas'); c.width = gw; c.height = gh;
      this.grid = { w: gw, h: gh, canvas: c, ctx: c.getContext('2d'), img: c.getContext('2d').createImageData(gw, gh), north: new Float64Array(gw * gh), east: new Float64Array(gw * gh) };
    }
    const G = this.grid;
    if (this.sea.components > 0) {
      for (let r = 0; r < gh; r++) for (let c = 0; c < gw; c++) {
        G.east[r * gw + c] = y0 + ((c + 0.5) / gw - 0.5) * (w / s);
        G.north[r * gw + c] = x0 - ((r + 0.5) / gh - 0.5) * (h / s);
      }
      const e = this.sea.elevations(this.t, G.north, G.east);
      for (let q = 0; q < e.length; q++) {
        const a = Math.max(0, Math.min(1, 0.5 + e[q] / (2 * this.waveScale)));
        for (let ch = 0; ch < 3; ch++) G.img.data[4 * q + ch] = C.trough[ch] + a * (C.crest[ch] - C.trough[ch]);
        G.img.data[4 * q + 3] = 255;
      }
      G.ctx.putImageData(G.img, 0, 0);
      g.imageSmoothingEnabled = true;
      g.drawImage(G.canvas, 0, 0, w, h);
    } else {
      g.fillStyle = `rgb(${C.trough.map((a, j) => (a + C.crest[j]) / 2).join(',')})`; g.fillRect(0, 0, w, h);
    }
    // Track behind the ship.
    const ts = this.cols.t_s, xs = this.cols.x_m, ys = this.cols.y_m;
    const from = rowAt(ts, this.t - P.trackS);
    g.lineWidth = 4; g.strokeStyle = 'rgba(0, 0, 0, 0.55)';
    const path = new Path2D();
    for (let j = from; j <= this.i; j++) { if (j === from) path.moveTo(px(ys[j]), py(xs[j])); else path.lineTo(px(ys[j]), py(xs[j])); }
    path.lineTo(px(y0), py(x0));
    g.stroke(path); g.lineWidth = 2; g.strokeStyle = C.track; g.stroke(path);
    // The ship to scale: its waterline, turned to its heading (x forward of the CG).
    const toPic = (fwd, stbd) => [px(y0 + fwd * Math.sin(psi) + stbd * Math.cos(psi)), py(x0 + fwd * Math.cos(psi) - stbd * Math.sin(psi))];
    const outline = new Path2D();
    const wl = hull.x_m.map((x, j) => [x - hull.lcg_m, hull.waterline_half_breadth_m[j]]).filter(([, b], j) => b > 0 || j === 0 || j === hull.x_m.length - 1);
    wl.forEach(([f, b], j) => { const [a, c] = toPic(f, b); if (j) outline.lineTo(a, c); else outline.moveTo(a, c); });
    for (const [f, b] of [...wl].reverse()) { const [a, c] = toPic(f, -b); outline.lineTo(a, c); }
    outline.closePath();
    g.fillStyle = C.ship; g.fill(outline); g.strokeStyle = C.hullEdge; g.lineWidth = 1.5; g.stroke(outline);
    // Rudder at the stern, angle from the trace (positive turns to port: trailing edge to port),
    // drawn three times its length so it can be seen.
    const rud = (v('rudder_deg') * Math.PI) / 180, sternF = hull.x_m[0] - hull.lcg_m, len = 3 * 4;
    const [ra, rb] = toPic(sternF, 0), [rc, rd] = toPic(sternF - len * Math.cos(rud), -len * Math.sin(rud));
    g.strokeStyle = C.rudder; g.lineWidth = 3; g.beginPath(); g.moveTo(ra, rb); g.lineTo(rc, rd); g.stroke();
    // Course over ground: the heading turned by the drift angle (the trace's atan2(v, u)), a
    // dashed line ahead of the bow (its direction only).
    const course = psi + (v('drift_angle_deg') * Math.PI) / 180, bowF = hull.x_m[hull.x_m.length - 1] - hull.lcg_m;
    const [ba, bb] = toPic(bowF, 0), run = 0.35 * hull.lpp_m * s;
    const ea = ba + run * Math.sin(course), eb = bb - run * Math.cos(course);
    g.strokeStyle = C.hullEdge; g.fillStyle = C.hullEdge; g.lineWidth = 2; g.setLineDash([5, 4]);
    g.beginPath(); g.moveTo(ba, bb); g.lineTo(ea, eb); g.stroke(); g.setLineDash([]);
    g.beginPath(); g.arc(ea, eb, 3.5, 0, 2 * Math.PI); g.fill();
    // Corner marks: north, the waves' direction, scale, and the figures.
    const fs = Math.max(11, Math.min(this.big ? 20 : 15, Math.round(w / 40)));
    g.font = `${fs}px system-ui, sans-serif`;
    const label = (text, x, y, align = 'left') => {
      g.textAlign = align; g.textBaseline = 'top';
      const tw = g.measureText(text).width;
      g.fillStyle = 'rgba(255, 255, 255, 0.88)'; g.fillRect(align === 'left' ? x - 3 : x - tw - 3, y - 2, tw + 6, fs + 4);
      g.fillStyle = C.text; g.fillText(text, x, y);
    };
    label(`heading ${v('heading_deg').toFixed(0)}°, ${v('ship_speed_kn').toFixed(1)} kn`, 8, 6);
    label(`rudder ${Math.abs(v('rudder_deg')).toFixed(1)}°${v('rudder_deg') > 0.05 ? ' to port' : v('rudder_deg') < -0.05 ? ' to starboard' : ''} (drawn ×3)`, 8, 10 + fs);
    label(`drift ${v('drift_angle_deg').toFixed(1)}° (dashed: course over ground)`, 8, 14 + 2 * fs);
    label('N ↑', w - 8, 6, 'right');
    const from_deg = this.from;
    if (from_deg != null) {
      // The waves travel away from where they come from: an arrow the way they go.
      label(`waves from ${from_deg}°`, w - 8, 10 + fs, 'right');
      const d = ((from_deg + 180) * Math.PI) / 180, X = w - 34, Y = 30 + 3 * fs, L = 18;
      g.strokeStyle = C.waveArrow; g.fillStyle = C.waveArrow; g.lineWidth = 3;
      g.beginPath(); g.moveTo(X - L * Math.sin(d), Y + L * Math.cos(d)); g.lineTo(X + L * Math.sin(d), Y - L * Math.cos(d)); g.stroke();
      g.beginPath(); g.arc(X + L * Math.sin(d), Y - L * Math.cos(d), 5, 0, 2 * Math.PI); g.fill();
    }
    const bar = 100 * s;
    g.strokeStyle = '#ffffff'; g.lineWidth = 3; g.beginPath(); g.moveTo(10, h - 10); g.lineTo(10 + bar, h - 10); g.stroke();
    label('100 m', 10, h - 16 - fs);
    this.drawn.plan = { heading_deg: v('heading_deg'), rudder_deg: v('rudder_deg'), x_m: x0, y_m: y0, from_deg };
  }

  // For the tests: the median frame time [ms] and the playback rate [simulated s per wall s].
  stats() {
    const f = [...this.frameMs].sort((a, b) => a - b);
    const r = this.rate;
    return { frames: f.length, medianFrameMs: f.length ? f[f.length >> 1] : null, p95FrameMs: f.length ? f[Math.floor(f.length * 0.95)] : null,
      rate: r && r.wall > r.wall0 ? (r.t - r.t0) / ((r.wall - r.wall0) / 1000) : null, fps: r && r.wall > r.wall0 ? r.frames / ((r.wall - r.wall0) / 1000) : null };
  }
}
