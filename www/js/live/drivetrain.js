// Live view: the drive train of Fig. 2-1 with its power flowing, from the four gas turbines through
// the generators, the two DC buses, inverters and motors to the propellers and the ship. Every
// number drawn is a trace value at the playback time; the warning levels and the motors' rating
// come from the wasm's pageConstants. No physics here.
import { LIVE } from '../config.js';
import { C, View, mw, pct, setsText } from './shared.js';

// What a stage keeps of the power through it: out/in flowing forward, in/out flowing back (a
// braking motor passes the shaft's power to the bus); none while the flow turns round.
// A stage passing on more than it takes is giving up stored energy (a transient): its ratio is
// shown as out/in, never as what it "keeps".
const ratioText = (r) => (r > 1 ? `out/in ${pct(r)}` : `keeps ${pct(r)}`);
export const keeps = (out, into) => (into > 0 && out >= 0 ? ratioText(out / into) : into < 0 && out < 0 ? ratioText(into / out) : 'flow turning');
// The ship's share: above 100 % only while the ship slows (resistance above thrust; no propeller
// turns as much as 90 % of its shaft power into thrust power), its momentum then paying the rest.
const shipShare = (out, into) => (into > 0 && out > into ? `slows: ${pct(out / into)}` : keeps(out, into));

// A block: rounded box with lines of text; warn: a word shown and the warning colours. gauge: a
// fraction 0 to 1 drawn as a level filling a bar at the block's left (a storage's charge); the
// text then centres in the rest.
function block(g, x, y, w, h, lines, warn, fsMax = 14, gauge = null) {
  g.fillStyle = warn ? C.warn : C.block;
  g.strokeStyle = warn ? C.warnEdge : C.blockEdge;
  g.lineWidth = warn ? 3 : 1.2;
  g.beginPath(); g.roundRect(x, y, w, h, 6); g.fill(); g.stroke();
  const gw = gauge === null ? 0 : Math.max(6, Math.min(12, w * 0.1));
  if (gauge !== null) {
    const gx = x + 4, gy = y + 5, gh = h - 10, f = Math.min(1, Math.max(0, gauge));
    g.fillStyle = C.gauge; g.fillRect(gx, gy + gh * (1 - f), gw, gh * f);
    g.strokeStyle = C.blockEdge; g.lineWidth = 1; g.strokeRect(gx, gy, gw, gh);
    x += gw + 4; w -= gw + 4;
  }
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

// What a storage does, in words: giving to its bus (positive) or charging from it.
// short: a narrow block's words (the arrow's direction says which way).
export const storageText = (w, short = false) => (w > 0 ? `${short ? 'out' : 'gives'} ${mw(w)}` : w < 0 ? `${short ? 'in' : 'charging'} ${mw(-w)}` : 'idle 0.0 MW');

// An arrow from (x0, y0) to (x1, y1) (along one axis) for power p [W] against a link rating
// [W]: width with the power, dashes moving with it; reversed (other colour) when power flows back.
// L: the live views (the dashes move with their playback speed).
function arrow(L, g, x0, y0, x1, y1, p, rating) {
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
  g.lineDashOffset = -L.dashPhase * LIVE.dashPxPerS * frac * L.speed;
  g.beginPath(); g.moveTo(ax, ay); g.lineTo(bx - ux * head, by - uy * head); g.stroke();
  g.setLineDash([]);
  const hw = width / 2 + 4;
  g.beginPath(); g.moveTo(bx, by); g.lineTo(bx - ux * head - uy * hw, by - uy * head + ux * hw); g.lineTo(bx - ux * head + uy * hw, by - uy * head - ux * hw); g.closePath(); g.fill();
  g.restore();
}

export class TrainView extends View {
  constructor(onResize) {
    super('Drive train (Fig. 2-1): power flows from the turbines to the ship', 'The drive train: four gas turbines, four generators, two DC buses, two inverters, two motors, two propellers and the ship, with the power each passes on', '--live-train-h', onResize);
  }

  // Fig. 2-1 left to right (top to bottom on a narrow screen): stages along one axis (turbines,
  // generators, buses, inverters, motors, propellers, ship), the four sets across the other. L: the live views (the trace at their playback time).
  draw(L) {
    const { g, w, h } = this;
    const v = (n) => L.v(n), k = L.k, lv = k.warnings;
    g.clearRect(0, 0, w, h);
    const down = w < LIVE.trainVerticalBelowPx; // stages from top to bottom
    const along = down ? h : w, across = down ? w : h;
    // A plant with storage or bus loads gets one more stage after the buses: their branches, one
    // above and one below each bus's line to its inverter. Without them the picture is as it was.
    const parts = L.parts || {}, o = parts.storage || parts.shipService || parts.pulsed ? 1 : 0;
    const stage = along / (7 + o), lane = across / 4;
    // Block extents along the flow and across it, and the picture position of (stage, lane).
    const big = (L.big = document.body.classList.contains('presenting')) ? 1.45 : 1; // presentation: larger blocks and type
    const bs = Math.min(stage * (down ? 0.7 : 0.8), 130 * big), bl = Math.min(lane * (down ? 0.92 : 0.86), (down ? 130 : 64) * big);
    const at = (st, ln) => (down ? [ln * lane, (st + 0.5) * stage] : [(st + 0.5) * stage, ln * lane]);
    const box = (st, ln, ext, lines, warn) => {
      const [cx, cy] = at(st, ln);
      const [bw, bh] = down ? [ext, bs] : [bs, ext];
      return block(g, cx - bw / 2, cy - bh / 2, bw, bh, lines, warn, fsMax);
    };
    const link = (st, ln, p, rating, to = st + 1) => {
      const [x0, y0] = at(st, ln), [x1, y1] = at(to, ln);
      if (down) arrow(L, g, x0, y0 + bs / 2, x1, y1 - bs / 2, p, rating);
      else arrow(L, g, x0 + bs / 2, y0, x1 - bs / 2, y1, p, rating);
    };
    const short = (down ? lane : bs) < 100; // narrow blocks: short names
    // One type size for every block: four lines in the smallest (a block with more shrinks alone).
    const fsMax = Math.max(10, Math.min(big > 1 ? 20 : 14, Math.floor(((down ? bs : bl) - 6) / 4) - 2));
    // The trace's sums shared by the sets running (an offline set: no power, no arrow).
    const on = L.online || [true, true, true, true], n = setsText(L.online).n;
    const pT = v('p_turbine_w') / n, pG = v('p_generator_w') / n, pI = v('p_inverter_w') / 2, pM = v('p_motor_w') / 2, pS = v('p_ship_w');
    const setRating = k.motor_rated_power_w / 2, plantRating = k.motor_rated_power_w;
    const speedPu = v('turbine_speed_pu'), busPu = v('bus_voltage_pu'), imPu = v('im_power_pu'), brake = v('brake_power_w');
    const warn = {
      turbine: speedPu > lv.turbine_overspeed_pu ? 'OVERSPEED' : speedPu < lv.turbine_min_running_pu ? 'STALLED' : null,
      bus: busPu < lv.bus_voltage_low_pu ? 'LOW' : busPu > lv.bus_voltage_high_pu ? 'HIGH' : null,
      motor: imPu >= lv.motor_power_limit_pu * 0.999 ? 'AT RATING' : null,
      brake: brake > 0 ? 'BRAKE ON' : null,
    };
    const d = L.drawn.train = { turbine_mw: pT / 1e6, generator_mw: pG / 1e6, inverter_mw: pI / 1e6, motor_mw: pM / 1e6, ship_mw: pS / 1e6, warn };
    // What the power electronics take: the generators' power, and with branches off the buses what
    // the storage gives less what the bus loads take (a storage giving would else read as out/in).
    const busIn = v('p_generator_w') + (o ? v('storage_power_w') - v('ship_service_w') - v('pulsed_load_w') : 0);
    const setLn = (s) => s + 0.5, plantLn = (p) => 2 * p + 1;
    // Arrows first, blocks over their ends.
    for (let s = 0; s < 4; s++) if (on[s]) { link(0, setLn(s), pT, setRating); link(1, setLn(s), pG, setRating); }
    for (let p = 0; p < 2; p++) {
      link(2, plantLn(p), pI, plantRating, 3 + o);
      link(3 + o, plantLn(p), pI, plantRating);
      link(4 + o, plantLn(p), pM, plantRating);
      // Useful power (resistance times speed), half per shaft, into the one ship; backwards
      // when the propellers brake the ship (negative thrust).
      link(5 + o, plantLn(p) + (p ? -0.3 : 0.3), v('thrust_kn') < 0 ? -pS / 2 : pS / 2, plantRating);
    }
    if (o) d.branches = this.branches(L, g, { at, down, bs, lane, fsMax, short, plantLn, plantRating });
    for (let s = 0; s < 4; s++) {
      if (!on[s]) {
        box(0, setLn(s), bl, [`${short ? 'GT' : 'Gas turbine'} ${s + 1}`, 'offline'], null);
        box(1, setLn(s), bl, [`${short ? 'Gen.' : 'Generator'} ${s + 1}`, 'offline'], null);
        continue;
      }
      d.turbineEdge = box(0, setLn(s), bl, [`${short ? 'GT' : 'Gas turbine'} ${s + 1}`, mw(pT), `${speedPu.toFixed(3)} pu`], warn.turbine);
      // A stalled set: the generator turns with its turbine, far below its frequency; what it
      // keeps of a stalled turbine's power says nothing.
      const stalled = warn.turbine === 'STALLED';
      box(1, setLn(s), bl, [`${short ? 'Gen.' : 'Generator'} ${s + 1}`, mw(pG), stalled ? 'set stalled' : keeps(v('p_generator_w'), v('p_turbine_w'))], stalled ? 'STALLED' : null);
    }
    const wide = Math.min(2 * lane * 0.9, bl * 1.6);
    for (let p = 0; p < 2; p++) {
      // With a set offline the two buses are tied (plant.online): every set running feeds both.
      box(2, plantLn(p), wide, [`DC bus ${p + 1}`, `${busPu.toFixed(3)} pu`, `${(v('bus_voltage_v') / 1e3).toFixed(2)} kV`, ...(n < 4 ? ['tied to the other'] : []), ...(warn.brake ? [`brake ${mw(brake / 2)}`] : [])], warn.bus || warn.brake);
      box(3 + o, plantLn(p), wide, [`${short ? 'Inv.' : 'Inverter'} ${p + 1}`, mw(pI), keeps(v('p_inverter_w'), busIn), ...(short ? [] : [`${v('motor_voltage_pu').toFixed(2)} pu V`])], null);
      box(4 + o, plantLn(p), wide, [`Motor ${p + 1}`, mw(pM), `${imPu.toFixed(2)} pu`, keeps(v('p_motor_w'), v('p_inverter_w'))], warn.motor);
      box(5 + o, plantLn(p), wide, [`${short ? 'Prop.' : 'Propeller'} ${p + 1}`, `${v(`prop_rpm_${p + 1}`).toFixed(0)} rpm`, `β_T ${v('beta_t').toFixed(2)}`], null);
    }
    box(6 + o, 2, Math.min(across * 0.5, 4 * bl), ['Ship', `${v('ship_speed_kn').toFixed(1)} kn`, `useful ${mw(pS)}`, ...(down ? [] : [`thrust ${(v('thrust_kn') / 1e3).toFixed(2)} MN`]), shipShare(v('p_ship_w'), v('p_motor_w'))], null);
  }

  // The branches off each bus (stage 3): its storage, with the charge as a level and a number and
  // an arrow for its power (into the storage while charging, out of it, orange, while giving), and
  // its ship service and pulsed loads with theirs. The trace records the two buses' sum (storage,
  // loads) and mean (charge): each bus shows half the sum and the mean, as the inverters and buses
  // do. Slots: above and below the bus's line to its inverter; two loads with a storage share the
  // lower slot.
  branches(L, g, { at, down, bs, lane, fsMax, short, plantLn, plantRating }) {
    const v = (n) => L.v(n), parts = L.parts;
    const soc = v('storage_soc'), pSt = v('storage_power_w') / 2, pSs = v('ship_service_w') / 2, pPl = v('pulsed_load_w') / 2;
    const items = [];
    if (parts.storage) items.push({ name: short ? 'Stor.' : 'Storage', lines: [short ? pct(soc) : `${pct(soc)} charged`, storageText(pSt, short)], p: -pSt, gauge: soc });
    if (parts.shipService) items.push({ name: short ? 'Ship svc' : 'Ship service', lines: [mw(pSs)], p: pSs });
    if (parts.pulsed) items.push({ name: short ? 'Pulsed' : 'Pulsed load', lines: [mw(pPl)], p: pPl });
    // Slots across, in lanes from the bus's centre line: above [-0.92, -gap], below [gap, 0.92].
    const gap = (LIVE.arrowMaxPx / 2 + 6) / lane;
    const slots = items.length === 3 ? [[items[0]], [items[1], items[2]]] : items.map((it) => [it]);
    for (let p = 0; p < 2; p++) {
      slots.forEach((group, k) => {
        const [a, b] = k === 0 ? [-0.92, -gap] : [gap, 0.92];
        group.forEach((it, j) => {
          const n = group.length, a1 = a + ((b - a) * j) / n, b1 = a + ((b - a) * (j + 1)) / n;
          const ln = plantLn(p) + (a1 + b1) / 2, ext = (b1 - a1) * lane - (n > 1 ? 4 : 0);
          // The arrow from the bus block's edge to the branch's, along the flow at the branch's lane.
          const [x0, y0] = at(2, ln), [x1, y1] = at(3, ln);
          if (down) arrow(L, g, x0, y0 + bs / 2, x1, y1 - bs / 2, it.p, plantRating);
          else arrow(L, g, x0 + bs / 2, y0, x1 - bs / 2, y1, it.p, plantRating);
          const [bw, bh] = down ? [ext, bs] : [bs, ext];
          block(g, x1 - bw / 2, y1 - bh / 2, bw, bh, [`${it.name} ${p + 1}`, ...it.lines], null, fsMax, it.gauge ?? null);
        });
      });
    }
    return {
      ...(parts.storage ? { storage_soc: soc, storage_soc_text: pct(soc), storage_mw: pSt / 1e6, storage_text: storageText(pSt, short) } : {}),
      ...(parts.shipService ? { ship_service_mw: pSs / 1e6 } : {}),
      ...(parts.pulsed ? { pulsed_mw: pPl / 1e6 } : {}),
    };
  }
}
