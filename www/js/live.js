// Live views (issue 14): the drive train of Fig. 2-1 with its power flowing, the stern in waves
// (Figs. 5-13 to 5-15 as a picture) and the ship in its seaway from above, drawn from the trace
// at the playback time; play/pause, speed and a scrubber whose time is the plots' cursor.
// Every number drawn is a trace value at the cursor (rows interpolated linearly while playing,
// the row itself after a seek); the hull comes from hullProfile and the sea surface from the
// run's own wave components summed in Rust (Sea). No physics here.
// This module holds the playback, the trace at the playback time and the text alternative; each
// view draws itself (live/drivetrain.js, live/stern.js, live/plan.js; shared parts in live/shared.js).
import init, { Sea, hullProfile } from '../pkg/aes_web.js';
import { LIVE } from './config.js';
import { el } from './dom.js';
import { TrainView, storageText } from './live/drivetrain.js';
import { PlanView } from './live/plan.js';
import { fixed, hubText, mw, pct, rowAt, rudderText, setsText, signed, steadySets } from './live/shared.js';
import { SternView } from './live/stern.js';

// The page's own copy of the wasm, for pictures only (the worker runs the simulations).
// Not behind the worker protocol: every frame asks the sea's elevations synchronously (Sea in
// live/stern.js and live/plan.js); a round trip to a worker busy with a run would stall playback.
let wasm = null;
const loadWasm = () => (wasm = wasm || init());
const reducedMotion = window.matchMedia('(prefers-reduced-motion: reduce)');

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
    this.train = new TrainView(redraw);
    this.stern = new SternView(redraw);
    this.plan = new PlanView(redraw);
    this.text = el('p', { id: 'live-text', className: 'live-text' });
    this.note = el('p', { className: 'hint' });
    root.replaceChildren(el('h2', { id: 'live-h', textContent: 'Watch it happen' }), bar,
      this.train.figure, el('div', { className: 'live-side' }, this.stern.figure, this.plan.figure), this.text, this.note);
    this.play.addEventListener('click', () => (this.playing ? this.pause() : this.start()));
    this.speedSel.addEventListener('change', () => { this.speed = Number(this.speedSel.value); this.rate = null; });
    this.scrub.addEventListener('input', () => this.seek(Number(this.scrub.value), { fromScrubber: true }));
    this.loop = (now) => this.frame(now);
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
    // The drive train's branches off the buses: the parts the scenario has (none by default).
    const st = scenario.plant.storage || {}, ld = scenario.plant.loads || {};
    this.parts = { storage: st.energy_j > 0, shipService: ld.ship_service_w > 0 || ld.ship_service_step_to_w > 0, pulsed: ld.pulse_power_w > 0 };
    this.online = steadySets(scenario);
    const w = constants.warnings;
    this.note.textContent = `Both plants draw the trace's figures (it records sums and means over machines; the shafts' speeds are each shaft's own). Block outlines turn red with a word when a limit is reached (the summary's health checks, which add how long): turbine stalled below ${w.turbine_min_running_pu} pu, overspeed above ${w.turbine_overspeed_pu} pu, bus voltage outside ${w.bus_voltage_low_pu} to ${+w.bus_voltage_high_pu.toPrecision(6)} pu, motor at its ${w.motor_power_limit_pu} pu rating, brake resistor on. What a block keeps is its stage's share in Table 5.7's chain (above 100 % it reads out/in: in a transient the stage is giving up energy its rotors or capacitors stored, which is not an efficiency): an inverter's is the whole power electronics (rectifier, stator resistance, notching, inverter); the ship's passes 100 % only while it slows, its momentum adding to the propellers' work. Arrow width follows the power; dashes move with it${reducedMotion.matches ? ' (held still: your system asks for reduced motion)' : ''}.`;
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
  // nearest that is. `scroll`: bring the views into sight (a link opened); a lesson's rerun leaves
  // the screen where the hand is.
  place({ at, speed }, { scroll = true } = {}) {
    return this.queued(() => {
      const near = LIVE.speeds.reduce((a, b) => (Math.abs(Math.log(b / speed)) < Math.abs(Math.log(a / speed)) ? b : a));
      this.speed = near; this.speedSel.value = String(near);
      this.seek(at);
      if (scroll) this.root.scrollIntoView({ block: 'start' });
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
    if (this.train.ready()) this.train.draw(this);
    if (this.inWaves && this.stern.ready()) this.stern.draw(this);
    if (this.plan.ready()) this.plan.draw(this);
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
    const sets = setsText(this.online), running = sets.words ? ` (${sets.words} running, the others offline)` : '';
    const parts = [`At ${this.t.toFixed(1)} s: turbines${running} ${mw(v('p_turbine_w') / sets.n)} each at ${v('turbine_speed_pu').toFixed(3)} pu speed${v('turbine_speed_pu') > w.turbine_overspeed_pu ? ' (OVERSPEED)' : v('turbine_speed_pu') < w.turbine_min_running_pu ? ' (STALLED)' : ''}`,
      `generators ${mw(v('p_generator_w') / sets.n)} each`, `buses at ${v('bus_voltage_pu').toFixed(3)} pu (${(v('bus_voltage_v') / 1e3).toFixed(2)} kV)`,
      `motors ${mw(v('p_motor_w') / 2)} each (${v('im_power_pu').toFixed(2)} pu)`, `propellers ${v('prop_rpm_1').toFixed(0)} and ${v('prop_rpm_2').toFixed(0)} rpm`,
      `ship ${v('ship_speed_kn').toFixed(1)} kn, heading ${fixed(v('heading_deg'), 0)}°, rudder ${rudderText(v('rudder_deg'))}`];
    if (v('brake_power_w') > 0) parts.push(`brake resistors ${mw(v('brake_power_w'))}`);
    // Each bus's share, as the picture draws it (the trace records the sums and the mean charge).
    if (this.parts.storage) parts.push(`storage on each bus ${pct(v('storage_soc'))} charged, ${storageText(v('storage_power_w') / 2)}`);
    if (this.parts.shipService) parts.push(`ship service load ${mw(v('ship_service_w') / 2)} on each bus`);
    if (this.parts.pulsed) parts.push(`pulsed load ${mw(v('pulsed_load_w') / 2)} on each bus`);
    if (this.inWaves) parts.push(`wave at the stern ${signed(v('wave_stern_m'))} m, ${hubText(v('hub_depth_m'))}, h/R ${v('h_over_r').toFixed(2)} (${this.discState().text}), thrust kept ${pct(v('beta_t'))}`);
    return parts.join('; ') + '.';
  }

  // The disc's state at the playback time (the stern view draws it, the text alternative says it).
  discState() {
    // The levels of eq. 2.14 on h/R (pageConstants): disc at the surface, disc out of the water.
    const hr = this.v('h_over_r'), bt = this.v('beta_t'), lv = this.k.h_over_r_levels.map((l) => l.value);
    if (hr <= Math.min(...lv)) return { text: 'disc out of the water', loud: true };
    if (hr < Math.max(...lv)) return { text: 'disc breaks the surface', loud: true };
    // Ventilation ends above the hysteresis band's top; the thrust then comes back over a few
    // turns of the shaft (a rate-limited recovery), so beta_T < 1 above the band is recovery.
    const ends = Math.max(...this.k.h_over_r_bands.map((b) => b.to));
    if (bt < 1) return hr > ends ? { text: `thrust recovering after ventilation (ended above h/R ${ends})`, loud: true } : { text: 'ventilating', loud: true };
    return { text: 'submerged', loud: false };
  }

  // For the tests: the median frame time [ms] and the playback rate [simulated s per wall s].
  stats() {
    const f = [...this.frameMs].sort((a, b) => a - b);
    const r = this.rate;
    return { frames: f.length, medianFrameMs: f.length ? f[f.length >> 1] : null, p95FrameMs: f.length ? f[Math.floor(f.length * 0.95)] : null,
      rate: r && r.wall > r.wall0 ? (r.t - r.t0) / ((r.wall - r.wall0) / 1000) : null, fps: r && r.wall > r.wall0 ? r.frames / ((r.wall - r.wall0) / 1000) : null };
  }
}