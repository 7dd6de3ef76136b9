// Browser test of the standard maneuvers fold (issue 42) and the turbine schedule fold (issue 45): the booklet the page computes in its
// worker is the command line's bit for bit (`aes-sim maneuvers`, run here on the same preset), the
// table says its IMO verdicts, the full-astern stop (issue 56) is drawn from above with its traces
// on one time axis and its numbers in the table, a booklet of another study is hidden, and the fold fits and is axe
// clean at the three sizes (screenshots maneuvers-*.png). Also the stability tab's bus stability
// map (issue 44): the command line's map bit for bit, its cells said in words, its refusals at
// the box, and its fit at the three sizes in one page load (screenshots busmap-*.png).
// Usage: node tests/e2e/maneuvers.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync, writeFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, checker, foldAtSizes, foldFits, launch, openPage, pressAndWait, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const open = (url, c) => openPage(c, url, base, errors);
const link = `${base}#v=2&preset=turn-360`;

assert(existsSync(native), `no native ${native}`);
const cli = JSON.parse(execFileSync(native, ['maneuvers', 'preset:turn-360'], { maxBuffer: 64 << 20 }).toString());

async function compute(p) {
  await p.$eval('#maneuvers-box', (e) => { e.open = true; });
  await p.click('#maneuvers-compute');
  await p.waitForFunction(() => /^Done|could not|refused/.test(document.getElementById('maneuvers-status').textContent), null, { timeout: 60000 });
  const st = await p.textContent('#maneuvers-status');
  assert(st.startsWith('Done'), `status: ${st}`);
  return st;
}

await check('the fold sails the maneuvers in the worker: the command line\'s booklet, bit for bit, its verdicts in the table', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(link, c);
  const st = await compute(p);
  const page = await p.evaluate(() => window.__maneuvers);
  // The command line prints its keys sorted; the numbers must be the same bits.
  const canon = (v) => (Array.isArray(v) ? v.map(canon) : v && typeof v === 'object' ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canon(v[k])])) : v);
  assert(JSON.stringify(canon(page)) === JSON.stringify(canon(cli)), `page ${JSON.stringify(canon(page)).slice(0, 300)} against ${JSON.stringify(canon(cli)).slice(0, 300)}`);
  const table = await p.textContent('#maneuvers-table');
  for (const cr of cli.criteria) assert(table.includes(cr.name) && table.includes(Number(cr.value).toPrecision(3)), `the table lacks ${cr.name}: ${table}`);
  assert(st.includes(`all ${cli.criteria.length} IMO criteria met`), st);
  assert(await p.$$eval('#maneuvers-plots canvas', (cs) => cs.length) >= 3, 'the turning circle and the two zig-zags are not all drawn');
  // The full-astern stop (issue 56): its plan view and its three traces on one time axis, each
  // number shown the command line's to the digits shown.
  const stp = cli.stopping, p3 = (x) => Number(x).toPrecision(3);
  const stop = await p.evaluate(() => {
    const figs = [...document.querySelectorAll('#maneuvers-plots figure.plot')];
    const plan = figs.find((f) => /^Full-astern stop/.test(f.querySelector('h3').textContent));
    const traces = figs.filter((f) => /^Crash stop/.test(f.querySelector('h3').textContent));
    const cv = plan && plan.querySelector('canvas.track');
    return {
      aria: cv ? cv.getAttribute('aria-label') : '', axes: cv ? cv.drawnAxes : null,
      titles: traces.map((f) => f.querySelector('h3').textContent),
      data: traces.map((f) => f.querySelector('.chart').uplot.data.map((d) => Array.from(d))),
      keys: traces.map((f) => (f.querySelector('.key') || {}).textContent || ''),
    };
  });
  assert(stop.axes && stop.axes.tick_l > 0 && stop.axes.scale_px > 20, `the stop's plan view is not drawn: ${JSON.stringify(stop.axes)}`);
  assert(stop.aria.includes(`track reach ${p3(stp.track_reach_l)} ship lengths`) && stop.aria.includes(`dead in the water ${p3(stp.time_to_dead_s)} s`), stop.aria);
  assert(stop.titles.length === 3, `the stop's traces: ${stop.titles}`);
  assert(stop.titles[1].includes(`highest ${p3(stp.peak_bus_voltage_pu)} pu`) && stop.titles[2].includes(`${p3(stp.peak_regenerated_w / 1e6)} MW`), stop.titles.join(' | '));
  // One time axis: every trace's times are the booklet's from the order; the bus drawn is the booklet's.
  const n = stop.data[0][0].length, times = stp.track.slice(0, n).map((s) => s.t_s);
  assert(n > 2 * stp.time_to_dead_s && stop.data.every((d) => JSON.stringify(d[0]) === JSON.stringify(times)), 'the stop\'s traces are not on one time axis');
  assert(JSON.stringify(stop.data[1][1]) === JSON.stringify(stp.track.slice(0, n).map((s) => s.bus_voltage_pu)), 'the bus drawn is not the booklet\'s');
  assert(stop.keys.every((k) => k.includes(`dead in the water at ${p3(stp.time_to_dead_s)} s`)) && /shaded: the bus's band, 0.9 to 1.15 pu/.test(stop.keys[1]), stop.keys.join(' | '));
  for (const [what, v] of [['head reach', `${p3(stp.head_reach_l)} L`], ['time to dead in the water', `${p3(stp.time_to_dead_s)} s`], ['highest bus voltage', `${p3(stp.peak_bus_voltage_pu)} pu`],
    ['brake energy until dead in the water', `${p3(stp.brake_energy_j / 1e6)} MJ`], ['highest power the motors returned', `${p3(stp.peak_regenerated_w / 1e6)} MW`], ['lateral deviation', `${p3(stp.lateral_deviation_l)} L`]]) {
    assert(table.includes(what) && table.includes(v), `the table lacks the stop's ${what} ${v}`);
  }
  console.log(`     stop from ${stp.approach_kn} kn: track reach ${p3(stp.track_reach_l)} L, dead in the water after ${p3(stp.time_to_dead_s)} s, brake ${p3(stp.brake_energy_j / 1e6)} MJ`);
  console.log(`     tactical diameter ${(cli.turning.tactical_diameter_m / cli.length_m).toFixed(2)} L, advance ${(cli.turning.advance_m / cli.length_m).toFixed(2)} L`);
  // Another speed in the form: the booklet of the old one is no longer shown.
  await setField(p, 'initial.speed_kn', 20);
  await p.waitForFunction(() => document.getElementById('maneuvers-body').hidden, null, { timeout: 5000 });
  assert((await p.textContent('#maneuvers-status')).includes('compute it again'), await p.textContent('#maneuvers-status'));
  await c.close();
});

await foldAtSizes({ browser, check, open, link, compute, name: 'maneuvers', shots });

// The turbine schedule's fold (issue 45): the command line's schedule bit for bit, a hovered cell
// says its fuel saving, a click opens the simulator with that many sets online, and the run runs.
await check('the schedule fold: the command line\'s schedule, a hovered cell\'s fuel saving, a click opens the simulator with its sets and runs', async () => {
  const cliSchedule = JSON.parse(execFileSync(native, ['schedule', 'preset:startup', '--json'], { maxBuffer: 64 << 20 }).toString()).schedule;
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(`${base}#v=2&preset=startup`, c);
  await setField(p, 'sim.duration_s', 20);
  await p.$eval('#schedule-box', (e) => { e.open = true; });
  await p.click('#schedule-compute');
  await p.waitForFunction(() => /^Done|could not|refused/.test(document.getElementById('schedule-status').textContent), null, { timeout: 60000 });
  const st = await p.textContent('#schedule-status');
  assert(st.startsWith('Done'), `status: ${st}`);
  const page = await p.evaluate(() => window.__schedule);
  const canon = (v) => (Array.isArray(v) ? v.map(canon) : v && typeof v === 'object' ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canon(v[k])])) : v);
  assert(JSON.stringify(canon(page)) === JSON.stringify(canon(cliSchedule)), 'the page\'s schedule is not the command line\'s');
  const cell = cliSchedule.cells.find((x) => x.speed_kn === 15 && x.sea_state === 3);
  const sel = 'button.schedule-cell[data-speed="15"][data-ss="3"]';
  await p.hover(sel);
  const hover = await p.textContent('#schedule-hover');
  const saving = (100 * cell.saving).toPrecision(3);
  assert(hover.includes(`${cell.count} set`) && hover.includes(`fuel saving ${saving} %`), `hover: ${hover}`);
  console.log(`     15 kn SS3: ${hover}`);
  await p.click(sel);
  await p.waitForFunction(() => document.getElementById('about').textContent.includes('turbine schedule'), null, { timeout: 5000 });
  const run = await pressAndWait(p);
  assert(run.startsWith('Done'), `run: ${run}`);
  const warn = await p.textContent('#warnings');
  assert(!warn.includes('overloaded'), `warnings: ${warn}`);
  await c.close();
});

await foldAtSizes({
  browser, check, open, link: `${base}#v=2&preset=startup`, name: 'schedule', shots,
  compute: async (p) => {
    await p.$eval('#schedule-box', (e) => { e.open = true; });
    await p.click('#schedule-compute');
    await p.waitForFunction(() => /^Done/.test(document.getElementById('schedule-status').textContent), null, { timeout: 60000 });
  },
});

// The bus stability map (issue 44) on the stability tab: the start-up study's default map (ship
// service load and filter C) is `aes-sim stability-map` on the scenario the page sent, bit for
// bit, and so is its operating point; a cell says its value and verdict; bad boxes are refused
// at the box; it fits and is axe clean at the three sizes (the same page resized).
await check('the bus stability map: the command line\'s map bit for bit, its cells in words, its refusals at the box, fits at three sizes', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(`${base}#v=2&preset=startup`, c);
  await p.click('#tab-ips');
  const computed = async () => {
    await p.click('#busmap-compute');
    await p.waitForFunction(() => !document.getElementById('busmap-compute').disabled && /^Done|could not|refused|must/.test(document.getElementById('busmap-status').textContent), null, { timeout: 60000 });
    return p.textContent('#busmap-status');
  };
  const st = await computed();
  assert(st.startsWith('Done'), `status: ${st}`);
  const page = await p.evaluate(() => window.__busmap);
  const file = `${shots}/busmap-scenario.json`;
  writeFileSync(file, page.request.scenario);
  const axis = (a) => `${a.path}=${a.from}:${a.to}:${a.n}`;
  const cliMap = JSON.parse(execFileSync(native, ['stability-map', file, '--x', axis(page.request.x), '--y', axis(page.request.y)], { maxBuffer: 64 << 20 }).toString());
  const cliPoint = JSON.parse(execFileSync(native, ['stability-map', file]).toString());
  const canon = (v) => (Array.isArray(v) ? v.map(canon) : v && typeof v === 'object' ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, canon(v[k])])) : v);
  assert(page.request.x.path === 'plant.loads.ship_service_w' && page.request.y.path === 'plant.loads.filter_capacitance_f', `default pair ${page.request.x.path}, ${page.request.y.path}`);
  assert(JSON.stringify(canon(page.map)) === JSON.stringify(canon(cliMap)), `page ${JSON.stringify(canon(page.map)).slice(0, 300)} against ${JSON.stringify(canon(cliMap)).slice(0, 300)}`);
  assert(JSON.stringify(canon(page.point)) === JSON.stringify(canon(cliPoint)), 'the operating point is not the command line\'s');
  const crossed = cliMap.boundary_x.filter((b) => b != null);
  assert(crossed.length >= 5 && st.includes(`crosses ${crossed.length} of ${cliMap.y.values.length} rows`), `status ${st}`);
  const j10 = cliMap.y.values.findIndex((y) => Math.abs(y - 0.01) < 1e-12);
  console.log(`     ${cliMap.x.values.length} x ${cliMap.y.values.length} cells; boundary at C_f 10 mF: ${(cliMap.boundary_x[j10] / 1e6).toFixed(2)} MW`);
  // A cell on each side of the boundary, by keyboard: its value and verdict in words.
  await p.focus('#busmap-canvas');
  await p.keyboard.press('Home');
  for (const [key, want] of [['Home', 'stable: every mode decays'], ['End', 'unstable: a mode grows']]) {
    await p.keyboard.press(key);
    const said = await p.textContent('#busmap-readout');
    const [i, j] = await p.evaluate(() => window.__busmapCell);
    const a = cliMap.abscissa[j][i];
    assert(said.includes(want) && said.includes(`${Number(Number(a).toPrecision(3))} 1/s`), `${key}: ${said} (abscissa ${a})`);
    if (a >= 0) assert(said.includes(`rings at ${Number(Number(cliMap.least_damped_hz[j][i]).toPrecision(3))} Hz`), said);
  }
  // The pointer says a cell too.
  const box = await p.locator('#busmap-canvas').boundingBox();
  await p.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
  assert(/spectral abscissa .* 1\/s, (stable|unstable)/.test(await p.textContent('#busmap-readout')), 'hover says nothing');
  // The study's own point is on the map and said.
  assert((await p.textContent('#busmap-point')).includes(`${Number(cliPoint.spectral_abscissa.toPrecision(3))} 1/s, stable`), await p.textContent('#busmap-point'));
  for (const [w, h] of [[1366, 768], [1920, 1080], [390, 844]]) {
    await p.setViewportSize({ width: w, height: h });
    await foldFits(p, '#busmap', `${shots}/busmap-${w}x${h}.png`, ['heading-order', 'empty-table-header', 'scrollable-region-focusable']);
  }
  // Refusals at the box: too many values; a speed of 0 (no steady state under way).
  await p.fill('#busmap-x-n', '500');
  let bad = await computed();
  assert(bad.includes('x axis: 500 values of plant.loads.ship_service_w: a whole number from 2 to 200'), bad);
  assert(await p.getAttribute('#busmap-x-n', 'aria-invalid') === 'true', 'the values box is not marked');
  await p.fill('#busmap-x-n', '41');
  await p.fill('#busmap-speed', '0');
  bad = await computed();
  assert(bad.includes('initial.speed_kn = 0') && await p.getAttribute('#busmap-speed', 'aria-invalid') === 'true', bad);
  // Back to the map's values it is shown plainly; another load in the form dims it and says so.
  await p.fill('#busmap-speed', '25');
  await p.dispatchEvent('#busmap-speed', 'input');
  assert(!(await p.getAttribute('#busmap-body', 'class') || '').includes('stale'), 'the map of the boxes\' values is dimmed');
  await p.click('#tab-sim');
  await setField(p, 'plant.loads.ship_service_w', 5); // [MW] (the form shows power in MW)
  await p.click('#tab-ips');
  await p.waitForFunction(() => document.getElementById('busmap-body').classList.contains('stale'), null, { timeout: 5000 });
  assert((await p.textContent('#busmap-status')).includes('compute it again'), await p.textContent('#busmap-status'));
  await c.close();
});

await finish(browser, errors);
