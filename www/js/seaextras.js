// The plots a run in waves asks the worker for once it is drawn: the hull's RAOs and, in a regular
// sea, Fig. 5-12's fuel study. They land in the run's plot box unless it was cleared meanwhile.
import { choiceLabel } from './registry.js';
import { RAO, FUEL_COLORS } from './config.js';
import { quantity, withPrefix } from './units.js';
import { REQUEST } from './protocol.js';

// After a run in waves: the hull's RAOs at the speed ordered at the end of the run, in head and
// bow seas, over wave length / Lpp (g and Lpp from pageConstants); after a run in a regular sea,
// also the fuel study of Fig. 5-12.
export function drawSeaExtras(box, client, scenario, cols, constants, onError) {
  const generation = box.generation;
  const hull = scenario.ship.hull || {};
  const hullTitle = hull.name === 'custom' ? 'Custom hull' : (choiceLabel('ship.hull.name', hull.name) || 'Hull').replace(/ \(.*\)$/, '');
  const g = constants.gravity_m_s2, lpp = constants.seakeeping_lpp_m;
  const kn = Number(cols.speed_cmd_kn[cols.speed_cmd_kn.length - 1].toPrecision(3));
  const lam = Array.from({ length: RAO.points }, (_, i) => RAO.lambdaFrom + i * RAO.lambdaStep);
  const omegas = lam.map((l) => Math.sqrt((2 * Math.PI * g) / (l * lpp)));
  for (const [heading, name] of RAO.headings) {
    client.request(REQUEST.rao, { scenario: JSON.stringify(scenario), speed_kn: kn, heading_deg: heading, omegas }).then(({ result: r }) => {
      const pk = r.pitch.amp.map((p, i) => p / ((omegas[i] * omegas[i]) / g));
      box.line(`${hullTitle} RAOs at ${kn} kn, ${name} seas (strip theory, ch. 2.5.2) [m/m; -; rad/m]`,
        { data: lam, label: `wave length / Lpp [-] (Lpp = ${quantity(lpp, 'm')})` },
        [{ data: r.heave.amp, label: 'heave per wave amplitude [m/m]', color: '#117a65' }, { data: pk, label: 'pitch / wave slope [-]', color: '#a04000', dash: [6, 3] }, { data: r.roll.amp, label: 'roll per wave amplitude [rad/m]', color: '#5b2c6f', dash: [2, 3] }],
        [{ scale: 'y', label: 'RAO [m/m; -; rad/m]' }], { generation, more: true });
    }, () => { /* a cancelled or failed RAO leaves the run's plots as they are */ });
  }
  if (scenario.sea.kind !== 'regular') return;
  // No frequencies given: the wasm takes Fig. 5-12's; the plot's axis is what the rows hold.
  client.request(REQUEST.fuel, { scenario: JSON.stringify(scenario), omegas: [] }).then(({ rows }) => {
    const { unit, factor } = withPrefix('W', 'M');
    const omegas = [...new Set(rows.map((r) => r.omega_rad_s))].sort((a, b) => a - b);
    const amplitudes = [...new Set(rows.map((r) => r.amplitude_ft))].sort((a, b) => a - b);
    for (const heading of [...new Set(rows.map((r) => r.heading))]) {
      const series = amplitudes.map((ft, j) => ({
        data: omegas.map((w) => { const r = rows.find((x) => x.heading === heading && x.amplitude_ft === ft && x.omega_rad_s === w); return r ? r.fuel_power_w * factor : null; }),
        label: `${ft} ft`, color: FUEL_COLORS[j % FUEL_COLORS.length],
      }));
      const range = amplitudes.length ? `${amplitudes[0]} to ${amplitudes[amplitudes.length - 1]} ft` : 'no amplitudes';
      box.line(`Fuel power of one prime mover [${unit}], ${heading} seas, ${range} (Fig. 5-12)`,
        { data: omegas, label: 'wave frequency [rad/s]' }, series, [{ scale: 'y', label: `fuel power [${unit}]` }], { generation });
    }
  }, (e) => { if (!e.cancelled) onError(e); });
}
