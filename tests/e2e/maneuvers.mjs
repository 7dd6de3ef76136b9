// Browser test of the standard maneuvers fold (issue 42) and the turbine schedule fold (issue 45): the booklet the page computes in its
// worker is the command line's bit for bit (`aes-sim maneuvers`, run here on the same preset), the
// table says its IMO verdicts, a booklet of another study is hidden, and the fold fits and is axe
// clean at the three sizes (screenshots maneuvers-*.png).
// Usage: node tests/e2e/maneuvers.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, checker, foldAtSizes, launch, openPage, pressAndWait, setField } from './lib.mjs';

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

await finish(browser, errors);
