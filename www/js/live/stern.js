// Live view: the stern in waves from the side (Figs. 5-13 to 5-15 as a picture): the hull, the
// propeller disc at the trace's hub depth and the wave surface along the centreline. The hub depth,
// the wave at the stern, h/R and the motions are trace values at the playback time; the hull comes
// from the wasm's hullProfile, the surface from the run's own wave components summed in Rust
// (Sea), the propeller's place and radius and the h/R levels from pageConstants. No physics here.
import { LIVE } from '../config.js';
import { C, View, hubText, signed, thrustKeptText } from './shared.js';

export class SternView extends View {
  constructor(onResize) {
    super('The stern in waves, from the side (Figs. 5-13 to 5-15)', 'The stern from the side: the hull, the propeller disc at its hub depth and the wave surface', '--live-side-h', onResize);
  }

  // Largest vertical excursion of the stern over the run [m]: |heave| + x_p |pitch| (and, in
  // `deepest`, the disc's lowest point below the calm waterline [m]).
  sternReach(L) {
    const c = L.cols;
    if (!c || !c.heave_m || !c.pitch_deg) { this.deepest = 0; return 0; }
    if (this.reachOf === c) return this.reach;
    const xp = (L.k && L.k.prop_x_aft_m) || 0;
    let r = 0, deep = 0;
    for (let i = 0; i < c.heave_m.length; i++) r = Math.max(r, Math.abs(c.heave_m[i]) + xp * Math.abs((c.pitch_deg[i] * Math.PI) / 180));
    // The disc's lowest point below the calm waterline: the hub drawn at its depth below the
    // wave at the stern (a deep hub in a trough goes further down than the stern's own motion).
    if (c.hub_depth_m && c.wave_stern_m) {
      for (let i = 0; i < c.hub_depth_m.length; i++) deep = Math.max(deep, c.hub_depth_m[i] - c.wave_stern_m[i]);
    }
    this.reachOf = c;
    this.reach = Number.isFinite(r) ? r : 0;
    this.deepest = Number.isFinite(deep) ? deep + ((L.k && L.k.propeller_radius_m) || 0) : 0;
    return this.reach;
  }

  // L: the live views (the trace at their playback time, the hull and the sea).
  draw(L) {
    const { g, w, h } = this;
    const v = (n) => L.v(n), hull = L.hull, W = LIVE.stern, k = L.k;
    g.clearRect(0, 0, w, h);
    // The frame grows to hold the run's largest heave and pitch at the stern (the thesis' Appendix
    // A as printed heaves the ship by 16-18 m), so nothing leaves the picture.
    const reach = this.sternReach(L);
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
    const eta = L.sea.elevations(L.t, north, east);
    const waveStern = v('wave_stern_m'), hub = v('hub_depth_m'), R = k.propeller_radius_m;
    // The port hub (the trace's wave_stern_m): x_p aft of G and y to port (port is heading - 90 deg).
    const yPort = (k.shaft_y_m || [0])[0];
    const kernelAtHub = L.sea.elevations(L.t, Float64Array.of(x0 - k.prop_x_aft_m * Math.cos(psi) + yPort * Math.sin(psi)), Float64Array.of(y0 - k.prop_x_aft_m * Math.sin(psi) - yPort * Math.cos(psi)))[0];
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
    const state = L.discState();
    g.strokeStyle = state.loud ? C.discOut : C.disc; g.lineWidth = state.loud ? 3 : 2; g.stroke(disc);
    g.fillStyle = C.disc; g.beginPath(); g.arc(dx, dz, 3, 0, 2 * Math.PI); g.fill();
    // The surface at the stern (trace value) marked with a tick.
    const surfPx = Z(waveStern);
    g.strokeStyle = C.discOut; g.lineWidth = 2; g.beginPath(); g.moveTo(dx - rpx - 8, surfPx); g.lineTo(dx - rpx - 2, surfPx); g.stroke();
    if (state.text === 'ventilating') {
      g.fillStyle = 'rgba(255, 255, 255, 0.85)';
      for (let b = 0; b < 7; b++) { const a = (b / 7) * 2 * Math.PI + 0.4; g.beginPath(); g.arc(dx + Math.cos(a) * rpx * 0.8, dz - Math.sin(a) * rpx * 0.8, 3 + (b % 3), 0, 2 * Math.PI); g.fill(); }
    }
    L.drawn.stern = { hub_depth_m: hub, wave_stern_m: waveStern, kernel_wave_stern_m: kernelAtHub, h_over_r: v('h_over_r'), disc_top_px: dz - rpx, surface_px: surfPx,
      disc_out_of_water: dz - rpx < surfPx, state: state.text, surface_at_hub_m: surf(hx), beta_t: v('beta_t'), thrust_text: thrustKeptText(v('beta_t')) };
    // Labels: a box in the top left corner (never over the disc).
    const lines = [[`h/R ${v('h_over_r').toFixed(2)}: ${state.text}`, state.loud], [L.drawn.stern.thrust_text, false],
      [hubText(hub), false], [`wave at the stern ${signed(waveStern)} m`, false],
      [`heave ${signed(heave)} m, pitch ${signed(v('pitch_deg'), 1)}° bow down`, false]];
    const fs = Math.max(11, Math.min(L.big ? 20 : 15, Math.round(w / 45)));
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
}
