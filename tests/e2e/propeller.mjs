// Browser test of the propeller panel (issue 54): the panel beside the hull's draws the blades and
// the open-water curves from the worker; DTMB 4119 picked there goes into the scenario and the
// address, and its KT at J = 0.7 is the command line's (`aes-sim propeller` on the same table, the
// same diameter, shaft speed and water) to the digits shown; a bad blade table is refused with the
// core's words (row and column) and changes nothing; a good one runs; a link carries the pick and
// a run uses it. Prints the page's time to draw the curves beside the command line's for the same
// 25 advance ratios (a benchmark: printed, not asserted). Screenshots propeller-*.png at three sizes.
// Usage: node tests/e2e/propeller.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync, readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, checker, foldFits, launch, openPage, pressAndWait } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
assert(existsSync(native), `no native ${native}`);
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const open = (url, c) => openPage(c, url, base, errors);
const link = `${base}#v=2&preset=head-seas-ss6`;
const table4119 = 'core/data/dtmb4119_geometry.csv';
const csv4119 = readFileSync(table4119, 'utf8');
const b64url = (s) => Buffer.from(s).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

// The panel drawn with `name` (runs_it: the run uses it).
const drawn = (p, name, runsIt) => p.waitForFunction(([n, r]) => {
  const d = window.__propellerPanel && window.__propellerPanel.drawn;
  return d && d.name === n && d.runs_it === r && d.timing;
}, [name, runsIt], { timeout: 30000 });
const pick = async (p, value) => { await p.selectOption('#propeller-geometry', value); };
const upload = (p, name, text) => p.setInputFiles('#propeller-csv', { name, mimeType: 'text/csv', buffer: Buffer.from(text) });

await check('the panel beside the hull\'s: DTMB 4119 picked runs its blades, in the scenario and the address; KT at J = 0.7 is the command line\'s; timing beside it', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(link, c);
  await drawn(p, 'b_series', false);
  const opts = await p.$$eval('#propeller-geometry option', (os) => os.map((o) => [o.value, o.disabled]));
  assert(JSON.stringify(opts.map(([v]) => v)) === JSON.stringify(['model', 'b_series', 'dtmb4119', 'custom']) && opts[3][1], `options ${JSON.stringify(opts)}`);
  assert(await p.$eval('#propeller-geometry', (s) => s.value) === 'model', 'the study\'s own model is picked at first');
  // The panel follows the hull panel in the results.
  assert(await p.evaluate(() => document.getElementById('hull-box').nextElementSibling.id) === 'propeller-box', 'the propeller panel is not beside the hull panel');
  const samples = [];
  let sheet = null;
  for (let k = 0; k < 4; k++) {
    await pick(p, 'dtmb4119');
    await drawn(p, 'dtmb4119', true);
    samples.push(await p.evaluate(() => window.__propellerPanel.timing));
    sheet = await p.evaluate(() => window.__propellerPanel.sheet);
    if (k < 3) { await pick(p, 'b_series'); await drawn(p, 'b_series', true); }
  }
  const sc = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(sc.propeller.model === 'geometry' && sc.propeller.geometry.name === 'dtmb4119', `scenario ${JSON.stringify(sc.propeller).slice(0, 200)}`);
  const hash = await p.evaluate(() => location.hash);
  const d = JSON.parse(Buffer.from(new URLSearchParams(hash.slice(1)).get('d').replace(/-/g, '+').replace(/_/g, '/'), 'base64').toString());
  assert(d.propeller && d.propeller.model === 'geometry' && d.propeller.geometry.name === 'dtmb4119', `the address's scenario part ${JSON.stringify(d)}`);
  // Three plots (outline, pitch, curves), the curves with six lines over 25 J.
  const plots = await p.$$eval('#propeller-plots figure', (fs) => fs.map((f) => [f.querySelector('h3').textContent, f.querySelectorAll('.legend li').length, !!f.querySelector('canvas')]));
  assert(plots.length === 3 && plots[2][1] === 6 && plots.every((x) => x[2]), `plots ${JSON.stringify(plots)}`);
  const dr = await p.evaluate(() => window.__propellerPanel.drawn);
  assert(dr.points === 25 && dr.outline && dr.outline.rows === 10, `drawn ${JSON.stringify(dr)}`);
  // The command line on the same table at the panel's flow (diameter, shaft speed, sea water).
  const f = sheet.flow;
  const args = ['propeller', table4119, '--blades', '3', '--hub-ratio', '0.2', '--water', 'sea', '--diameter-m', String(f.diameter_m), '--rpm', String(f.rev_per_s * 60), '--j', '0:1.2:25'];
  const times = [];
  let cli = null;
  for (let k = 0; k < 5; k++) {
    const t0 = process.hrtime.bigint();
    cli = JSON.parse(execFileSync(native, args).toString());
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
  assert(sheet.flow.density_kg_m3 === cli.flow.density_kg_m3 && Math.abs(cli.flow.rev_per_s - f.rev_per_s) < 1e-12, `flows ${JSON.stringify(cli.flow)} ${JSON.stringify(f)}`);
  const at = cli.open_water.findIndex((r) => Math.abs(r.j - 0.7) < 1e-9);
  assert(at >= 0, 'the command line has no J = 0.7');
  const row = await p.$$eval('#propeller-table tbody tr', (rs) => rs.map((r) => [...r.children].map((x) => x.textContent)));
  const shown = row.find((r) => r[0] === '0.700');
  assert(shown, `no row J = 0.700 in ${JSON.stringify(row).slice(0, 200)}`);
  assert(shown[1] === cli.open_water[at].kt.toFixed(4) && shown[2] === (10 * cli.open_water[at].kq).toFixed(4),
    `J = 0.7: the page shows KT ${shown[1]}, 10KQ ${shown[2]}; the command line ${cli.open_water[at].kt}, ${10 * cli.open_water[at].kq}`);
  const page = median(samples.map((s) => s.request_to_drawn_ms)), worker = median(samples.map((s) => s.worker_ms)), nat = median(times);
  console.log(`     DTMB 4119 at D ${f.diameter_m} m, ${(f.rev_per_s * 60).toFixed(1)} rpm: KT(0.7) ${shown[1]}, 10KQ(0.7) ${shown[2]} on the page and the command line`);
  console.log(`     25 J: the page draws the curves in ${page.toFixed(1)} ms (request to drawn; the worker's vortex lattice ${worker.toFixed(1)} ms); aes-sim propeller ${nat.toFixed(1)} ms (process, median of 5); ratio ${(page / nat).toFixed(2)} (worker alone ${(worker / nat).toFixed(2)})`);
  await c.close();
});

await check('a bad blade table is refused with the core\'s words (row and column) beside the picker, the choice kept; a good one runs', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(link, c);
  await drawn(p, 'b_series', false);
  await pick(p, 'dtmb4119');
  await drawn(p, 'dtmb4119', true);
  const before = await p.evaluate(() => window.__scenarioText());
  const lines = csv4119.split('\n');
  const i = lines.findIndex((l) => l.startsWith('0.50,'));
  const bad = [...lines.slice(0, i), '0.50,0.0000,1.093,0.02182,0.09016,0,0', ...lines.slice(i + 1)].join('\n');
  await upload(p, 'bad4119.csv', bad);
  await p.waitForFunction(() => document.getElementById('propeller-csv-err').textContent !== '', null, { timeout: 10000 });
  const err = await p.textContent('#propeller-csv-err');
  assert(/^bad4119\.csv: row 4 \(r\/R 0\.5\), column c_D: a chord of 0/.test(err), `the refusal: ${err}`);
  assert(await p.$eval('#propeller-csv', (e) => e.getAttribute('aria-invalid')) === 'true', 'the file field is not marked invalid');
  assert(await p.$eval('#propeller-geometry', (s) => s.value) === 'dtmb4119', 'the choice was not kept');
  assert(await p.evaluate(() => window.__scenarioText()) === before, 'the scenario changed');
  // Blades out of range: the core's range, named.
  await p.fill('#propeller-blades', '9');
  await upload(p, 'p4119.csv', csv4119);
  await p.waitForFunction(() => /blades/.test(document.getElementById('propeller-csv-err').textContent), null, { timeout: 10000 });
  const err2 = await p.textContent('#propeller-csv-err');
  assert(err2.includes('blades: 9 is outside 2..=7'), err2);
  // The table with skew, three blades: read, picked, run by the scenario, in the address.
  await p.fill('#propeller-blades', '3');
  const skewed = csv4119.replace(/^(0\.\d+|1\.00),(.*),0,0$/gm, (_, r, rest) => `${r},${rest},${(Number(r) * 20).toFixed(1)},0`);
  await upload(p, 'skew4119.csv', skewed);
  await drawn(p, 'custom', true);
  assert(await p.textContent('#propeller-csv-err') === '', 'the refusal stayed');
  const sc = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(sc.propeller.geometry.name === 'custom' && sc.propeller.geometry.rows.length === 10 && sc.propeller.geometry.rows[9].skew_deg === 20, JSON.stringify(sc.propeller.geometry).slice(0, 300));
  assert((await p.$eval('#propeller-geometry', (s) => s.selectedOptions[0].textContent)).includes('skew4119.csv'), 'the picker does not name the file');
  // Four blades typed beside it: the table is read again with them and runs.
  await p.fill('#propeller-blades', '4');
  await p.dispatchEvent('#propeller-blades', 'change');
  await p.waitForFunction(() => window.__propellerPanel.sheet && window.__propellerPanel.sheet.blades === 4, null, { timeout: 30000 });
  assert(JSON.parse(await p.evaluate(() => window.__scenarioText())).propeller.geometry.blades === 4, 'the four blades are not in the scenario');
  const hash = await p.evaluate(() => location.hash);
  console.log(`     a 10-row blade table rides in the address: ${hash.length} characters`);
  await foldFits(p, '#propeller-box', `${shots}/propeller-skewed-1366x768.png`, ['heading-order', 'empty-table-header', 'scrollable-region-focusable']);
  // Back to the study's own model: the geometry leaves the scenario.
  await pick(p, 'model');
  await drawn(p, 'b_series', false);
  const back = JSON.parse(await p.evaluate(() => window.__scenarioText()));
  assert(back.propeller.model === 'b_series' && !back.propeller.geometry, JSON.stringify(back.propeller).slice(0, 200));
  await c.close();
});

await check('a link with DTMB 4119 opens with it picked, and a run uses its blades (the summary\'s propeller note under the panel)', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const d = b64url(JSON.stringify({ sim: { duration_s: 20 }, propeller: { model: 'geometry', geometry: { name: 'dtmb4119' } } }));
  const p = await open(`${base}#v=2&preset=startup&d=${d}`, c);
  await drawn(p, 'dtmb4119', true);
  assert(await p.$eval('#propeller-geometry', (s) => s.value) === 'dtmb4119', 'the link\'s pick is not shown');
  const st = await pressAndWait(p);
  assert(st.startsWith('Done'), st);
  await p.waitForFunction(() => !document.getElementById('propeller-run').hidden, null, { timeout: 10000 });
  const note = await p.textContent('#propeller-run');
  assert(note.includes('propeller.geometry "dtmb4119"'), note);
  await c.close();
});

for (const [w, h] of [[1366, 768], [1920, 1080], [390, 844]]) {
  await check(`at ${w}x${h}: the propeller panel fits, axe clean (screenshot propeller-${w}x${h}.png)`, async () => {
    const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
    const p = await open(link, c);
    await drawn(p, 'b_series', false);
    await pick(p, 'dtmb4119');
    await drawn(p, 'dtmb4119', true);
    await p.$eval('#propeller-points', (e) => { e.open = true; });
    await foldFits(p, '#propeller-box', `${shots}/propeller-${w}x${h}.png`, ['heading-order', 'empty-table-header', 'scrollable-region-focusable', 'label']);
    await c.close();
  });
}

await finish(browser, errors);
