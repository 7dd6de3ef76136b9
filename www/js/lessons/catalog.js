// The lessons (issue 30): a few controls on one study, a question asked before the first run, an
// explanation in the run's own numbers and one thing to try next. Words only: every number shown
// comes from the run (its summary) and every control's label, unit and range from the registry
// (paramMeta); `span` narrows a slider inside the declared range, for the lesson's story.
// A control is a slider (`path`, `step`, optional `span`; `log`: in decades, `step` in decades) or a toggle (`path`, `values` [on, off]
// with `labels`, and `also`: settings that go with each value). `order` gives the index of a maneuver order (paths commands.N.*).
// explain({s, markers, values, before}) -> text: s is the run's summary, markers the surface-loss
// starts, values the controls' values, before the previous run's summary (or null).
// right({s}) -> index of the answer the run itself shows to be right (only where one run settles
// the question; a question about a change is answered by the student's next run beside the faint
// earlier one).

const f = (x, d = 2) => Number(x).toFixed(d);
const pct = (x) => `${(100 * x).toFixed(0)} %`;
const sig = (s, name) => s.signals[name];

export const LESSONS = [
  {
    name: 'power', title: 'Where the power goes', preset: 'startup', set: { 'sim.duration_s': 200 },
    plots: ['inventory'], view: 'train', at: 150,
    controls: [{ path: 'commands.N.speed_kn', order: 0, step: 1, span: [10, 30] }, { path: 'ship.drag_coeff', step: 0.0001 }],
    question: 'Once the ship holds its speed, how much of the gas turbines\' power ends up pushing the ship through the water?',
    answers: ['almost all of it (more than 90 %)', 'about two thirds', 'less than a third'],
    right: ({ s }) => { const r = s.power_inventory_w.ship / s.power_inventory_w.turbine; return r > 0.9 ? 0 : r > 0.4 ? 1 : 2; },
    explain: ({ s }) => {
      const p = s.power_inventory_w;
      return `At the end the turbines make ${f(p.turbine / 1e6, 1)} MW and ${f(p.ship / 1e6, 1)} MW pushes the ship (resistance times speed): ${pct(p.ship / p.turbine)}. `
        + `Each stage keeps back a little: the generators pass on ${pct(p.generator / p.turbine)}, the power electronics ${pct(p.inverter / p.generator)}, the motors ${pct(p.motor / p.inverter)}; `
        + `the largest loss is the propeller's, which passes on ${pct(p.ship / p.motor)} of the motors' power to the ship.`;
    },
    next: 'Order 30 knots: resistance grows about with the square of speed, so the power needed grows about with its cube.',
  },
  {
    name: 'waves', title: 'Waves unload the propeller', preset: 'head-seas-ss6', set: { 'sim.duration_s': 60 },
    plots: ['hr', 'motor'], view: 'stern', at: 3,
    controls: [{ path: 'sea.sea_state', step: 1 }, { path: 'ship.hull.hub_above_base_m', step: 0.25, span: [0, 3] }, { path: 'initial.speed_kn', step: 1, span: [10, 30] }],
    question: 'Raise the propeller hub (a lighter ship rides higher). Will the propeller draw air more often, less often, or as often?',
    answers: ['more often', 'less often', 'as often'],
    explain: ({ s, markers }) => {
      const hr = sig(s, 'h_over_r');
      return `h/R is the hub's depth below the wave surface over the propeller's radius: below 1 the disc breaks the surface. In this run it went down to ${f(hr.min)}, `
        + `and surface losses started ${markers.length} time(s). Each time the propeller loses thrust, its motor's power falls (here between ${f(sig(s, 'im_power_pu').min)} and ${f(sig(s, 'im_power_pu').max)} pu of the 38 MW rating), `
        + 'and the bus and the turbines feel the load come and go.';
    },
    next: 'Set the sea state to 3: the waves are much lower and the propeller stays deep.',
  },
  {
    name: 'turn', title: 'A turn costs power', preset: 'turn-90', set: { 'sim.duration_s': 240 },
    plots: ['motor', 'speed'], view: 'plan', at: 90,
    controls: [{ path: 'commands.N.heading_deg', order: 1, step: 15, span: [15, 180] }, { path: 'initial.speed_kn', step: 1, span: [10, 30] }],
    question: 'The speed order stays the same through the turn. What do the motors need while the ship turns?',
    answers: ['more power', 'the same power', 'less power'],
    right: ({ s }) => { const m = sig(s, 'im_power_pu'); return m.max > 1.02 * m.min ? 0 : 1; },
    explain: ({ s }) => {
      const m = sig(s, 'im_power_pu'), v = sig(s, 'ship_speed_kn');
      return `In the turn the hull moves a little sideways and the propellers meet the water at an angle: the motors' power rose from ${f(m.min)} to ${f(m.max)} pu (${pct(m.max / m.min - 1)} more), `
        + `and the ship still slowed from ${f(v.max, 1)} to ${f(v.min, 1)} knots before the speed controller caught up.`;
    },
    next: 'Try a 180° turn: the extra power lasts longer, and the speed loss grows.',
  },
  {
    name: 'braking', title: 'Braking: where the ship\'s energy goes', preset: 'ac-braking', set: { 'sim.duration_s': 90 },
    plots: ['bus', 'brake'], view: 'train', at: 15,
    // Without the resistor the rectifiers must pass power back to the generators (Fig. 5-8's plant):
    // a diode rectifier with nowhere for the energy to go drives the bus voltage away.
    controls: [{ path: 'plant.dc_link.brake_resistor_ohm', values: [1, 0], labels: ['with a brake resistor', 'no brake resistor'],
      also: [{ 'plant.dc_link.rectifier': 'diode' }, { 'plant.dc_link.rectifier': 'reversible' }] },
    { path: 'initial.speed_kn', step: 1, span: [10, 30] }],
    question: 'The ship stops from 25 knots. Without a brake resistor, where does its kinetic energy go?',
    answers: ['back into the gas turbines, which speed up', 'it simply disappears', 'into the bus, which holds its voltage'],
    right: () => 0,
    explain: ({ s }) => {
      const t = sig(s, 'turbine_speed_pu'), b = sig(s, 'bus_voltage_pu');
      return `From ${f(sig(s, 'ship_speed_kn').max, 1)} knots the water drives the propellers and the motors brake as generators. The brake resistor burnt ${f(s.energy_j.brake / 1e6, 1)} MJ; `
        + `the turbines reached ${f(t.max, 3)} pu of their speed and the bus ${f(b.max, 3)} pu of its voltage. Energy does not disappear: without the resistor it flows back and speeds up the turbines.`;
    },
    next: 'Switch the resistor off and watch the turbine speed and the bus voltage rise.',
  },
  {
    name: 'bus', title: 'How the bus voltage is held', preset: 'acceleration', set: {},
    plots: ['bus'], view: 'train', at: 12,
    // The study's gains are small (1e-4, 5e-4) and the stall comes at 5: sliders in decades.
    controls: [{ path: 'controllers.field.kp', log: true, step: 0.1, span: [1e-5, 10] }, { path: 'controllers.field.ki', log: true, step: 0.1, span: [1e-5, 10] }],
    question: 'The motors suddenly take full power. If the generators\' field controller reacts more strongly (a larger gain), the bus voltage will...',
    answers: ['dip less and recover sooner', 'dip more', 'not change'],
    explain: ({ s }) => {
      const b = sig(s, 'bus_voltage_pu'), t = sig(s, 'turbine_speed_pu');
      const health = (s.warnings || []).find((w) => /stall|bus|overspeed/i.test(w));
      const warn = health ? ` Warning: ${health}` : '';
      return `pu means "per unit": a fraction of the rated value. The bus dipped to ${f(b.min, 3)} pu and ended at ${f(b.final, 3)} pu; the turbines dipped to ${f(t.min, 3)} pu. `
        + `The field controller raises the generators' field current when the voltage falls; too strong a reaction can overshoot, or ask the turbines for more than they can give.${warn}`;
    },
    next: 'Set the proportional gain to 5 and look at the turbine speed: a controller can hold the voltage by stalling its prime mover.',
  },
  {
    name: 'sign', title: 'One sign in one equation', preset: 'head-seas-ss6', set: { 'sim.duration_s': 60 },
    plots: ['hr'], view: 'stern', at: 3,
    controls: [{ path: 'seakeeping.stern_motion', values: ['consistent', 'thesis_eq_2_57'], labels: ['the stern follows the waves (consistent)', 'eq. 2.57 as printed'] },
      { path: 'sea.sea_state', step: 1 }],
    question: 'The thesis prints the hub depth with the stern\'s motion added to the wave. If that sign is right, the propeller breaks the surface...',
    answers: ['more often than with the stern following the waves', 'less often', 'as often'],
    explain: ({ s, markers, values }) => `With ${values['seakeeping.stern_motion'] === 'thesis_eq_2_57' ? 'eq. 2.57 as printed' : 'the consistent sign'} h/R went down to ${f(sig(s, 'h_over_r').min)} and surface losses started ${markers.length} time(s). `
      + 'A stern that rises with the wave keeps its propeller at about the same depth below the surface; adding the motion instead doubles the swing.',
    next: 'Switch between the two and compare the faint earlier run with the new one.',
  },
];

// Short definitions of the symbols the lessons use.
export const GLOSSARY = [
  ['h/R', 'the propeller hub\'s depth below the water surface divided by the propeller\'s radius; below 1 the disc breaks the surface'],
  ['pu', '"per unit": a value as a fraction of its rating (1 pu is the rated voltage, speed or power)'],
  ['β_T', 'the share of its thrust a propeller keeps near the surface (1: all of it)'],
  ['sea state', 'a number for how rough the sea is (3: moderate, 6: very rough)'],
];
