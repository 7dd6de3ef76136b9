// Browser test of the fuel-per-mile fold (a study on the shared pipeline, issue 41): computed on the
// worker pool, its numbers are the command line's bit for bit (`aes-sim fuel-per-mile`, run here
// with the page's settings), the table says them, a result of other inputs is hidden, and the fold
// fits and is axe clean at the three sizes (screenshots fuel-*.png).
// Usage: node tests/e2e/fuel.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR [path of aes-sim]
import { mkdirSync, existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { assert, checker, foldAtSizes, launch, openPage, setField } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
const native = process.argv[4] || 'target/release/aes-sim';
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const open = (url, c) => openPage(c, url, base, errors);
const link = `${base}#v=2&preset=head-seas-ss6`;

assert(existsSync(native), `no native ${native}`);
// The page's settings: 120 s runs measured from 60 s.
const cli = JSON.parse(execFileSync(native, ['fuel-per-mile', 'preset:head-seas-ss6', '--speeds', '12,24', '--seeds', '2',
  '--set', 'sim.duration_s=120', '--from', '60', '--quiet']).toString());

async function compute(p) {
  await p.$eval('#fuel-box', (e) => { e.open = true; });
  await p.fill('#fuel-speeds', '12, 24');
  await p.fill('#fuel-seeds', '2');
  await p.click('#fuel-compute');
  await p.waitForFunction(() => /^Done|failed|refused|Cancelled/.test(document.getElementById('fuel-status').textContent), null, { timeout: 120000 });
  const st = await p.textContent('#fuel-status');
  assert(st.startsWith('Done'), `status: ${st}`);
}

await check('the fold computes fuel per mile on the worker pool: the command line\'s numbers, bit for bit, said in its table', async () => {
  const c = await browser.newContext({ viewport: { width: 1366, height: 768 }, bypassCSP: true });
  const p = await open(link, c);
  await compute(p);
  const page = await p.evaluate(() => window.__fuel);
  assert(JSON.stringify(page) === JSON.stringify(cli), `page ${JSON.stringify(page).slice(0, 300)} against ${JSON.stringify(cli).slice(0, 300)}`);
  const table = await p.textContent('#fuel-table');
  for (const r of cli.rows) assert(table.includes(Number(r.kg_per_nmi_mean).toPrecision(4)), `the table lacks ${r.kg_per_nmi_mean}: ${table}`);
  assert(table.includes(`least at ${cli.most_economical_kn} kn`), table);
  console.log(`     ${cli.rows.map((r) => `${r.ordered_kn} kn: ${r.kg_per_nmi_mean.toFixed(1)} kg/nmi`).join(', ')}`);
  // Another sea state in the form: the result of the old one is no longer shown.
  await setField(p, 'sea.sea_state', 5);
  await p.waitForFunction(() => document.getElementById('fuel-body').hidden, null, { timeout: 5000 });
  assert((await p.textContent('#fuel-status')).includes('compute again'), await p.textContent('#fuel-status'));
  await c.close();
});

await foldAtSizes({ browser, check, open, link, compute, name: 'fuel', shots });

await finish(browser, errors);
