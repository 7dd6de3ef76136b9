// Browser end-to-end test of the page in headless Chromium (Debian's chromium + playwright-core).
// Usage: node tests/e2e/e2e.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';

const base = process.argv[2];
const shots = process.argv[3];
mkdirSync(shots, { recursive: true });
console.log(`screenshots in ${shots}`);
let passed = 0, failed = 0;
async function check(name, fn) {
  try { await fn(); passed++; console.log(`ok   ${name}`); } catch (e) { failed++; console.log(`FAIL ${name}: ${e.message}`); }
}
function assert(c, msg) { if (!c) throw new Error(msg); }

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const context = await browser.newContext({ viewport: { width: 1300, height: 1100 } });
const consoleErrors = [];
async function open(url) {
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(`${url}: ${m.text()}`); });
  page.on('pageerror', (e) => consoleErrors.push(`${url}: ${e}`));
  page.on('request', (r) => { if (!r.url().startsWith(base) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) consoleErrors.push(`request left the origin: ${r.url()}`); });
  await page.goto(url);
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  return page;
}
async function setField(page, path, value) {
  const sel = '#f-' + path.replace(/\./g, '-');
  if ((await page.$eval(sel, (e) => e.tagName)) === 'SELECT') await page.selectOption(sel, String(value));
  else await page.fill(sel, String(value));
  await page.dispatchEvent(sel, 'change');
}
async function runAndWait(page) {
  await page.click('#run');
  await page.waitForFunction(() => /^Done|^Cancel/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 60000 });
  return page.textContent('#status');
}
const summaryText = (page) => page.$eval('#summary tbody', (t) => t.textContent);

const page = await open(base);
let firstSummary;
await check('start-up runs and the plots are drawn with data', async () => {
  await setField(page, 'sim.duration_s', 120);
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  const n = await page.$$eval('#plots .uplot', (els) => els.length);
  assert(n >= 5, `only ${n} plots`);
  const rows = await page.$$eval('#summary tbody tr', (r) => r.length);
  assert(rows === 6, `${rows} summary rows`);
  firstSummary = await summaryText(page);
  assert(/\d/.test(firstSummary), 'no numbers in the summary');
  await page.screenshot({ path: `${shots}/startup.png` });
});
await check('a changed parameter changes the result', async () => {
  await setField(page, 'ship.drag_coeff', 0.004);
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  assert((await summaryText(page)) !== firstSummary, 'same summary after changing C_r');
});
await check('a copied link reproduces the identical run in a new page', async () => {
  const mine = await summaryText(page);
  await page.click('#share');
  const url = await page.inputValue('#share-url');
  assert(url.includes('#v=1&preset=startup&d='), url);
  const other = await open(url);
  await other.waitForFunction(() => document.getElementById('status').textContent.startsWith('Done'), null, { timeout: 60000 });
  const theirs = await summaryText(other);
  assert(theirs === mine, `summaries differ:\n${mine}\n${theirs}`);
  assert((await other.inputValue('#f-ship-drag_coeff')) === '0.004', 'form not restored');
  await other.close();
});
for (const [name, hash, want] of [
  ['a damaged link', '#v=1&preset=startup&d=@@@', 'damaged'],
  ['a link from a newer version', '#v=99&preset=startup', 'newer version'],
  ['a truncated link', '#v=1&preset=startup&d=eyJzaGlwIjp7Im1h', 'not valid JSON'],
  ['a hostile deeply nested link', '#v=1&preset=startup&d=' + Buffer.from('['.repeat(500)).toString('base64url'), 'nested too deeply'],
  ['a link with out-of-range values', '#v=1&preset=startup&d=' + Buffer.from(JSON.stringify({ ship: { mass_kg: 1e300 } })).toString('base64url'), 'ship.mass_kg'],
  ['a huge link', '#v=1&preset=startup&d=' + 'A'.repeat(20000), 'characters long'],
  ['a link with script text', '#v=1&preset=' + encodeURIComponent('<script>alert(1)</script>'), 'unknown study'],
]) {
  await check(`${name} shows a clear message and falls back to the preset`, async () => {
    const p = await open(base + hash);
    const text = await p.textContent('#notice');
    assert(!(await p.$eval('#notice', (n) => n.hidden)), 'no notice shown');
    assert(text.includes(want), `notice was: ${text}`);
    assert((await p.$eval('#preset', (s) => s.value)) === 'startup', 'did not fall back to start-up');
    assert(!(await p.textContent('#status')).startsWith('Running'), 'ran something');
    if (name === 'a damaged link') await p.screenshot({ path: `${shots}/broken-link.png` });
    await p.close();
  });
}
await check('a long run can be cancelled and the form survives', async () => {
  await setField(page, 'sim.duration_s', 50000);
  await page.click('#run');
  await page.waitForFunction(() => document.getElementById('progress').value > 0.002, null, { timeout: 30000 });
  await page.click('#cancel');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 5000 });
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-sim-duration_s')) === '50000', 'form lost its edit');
  assert((await page.$$eval('#plots .uplot', (els) => els.length)) >= 5, 'earlier plots were lost');
});
await check('edits survive a reload', async () => {
  await page.reload();
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-sim-duration_s')) === '50000', 'duration not restored');
  assert((await page.inputValue('#f-ship-drag_coeff')) === '0.004', 'C_r not restored');
});
await check('a bad value is named with its field and the earlier results stay', async () => {
  await setField(page, 'sim.duration_s', 60);
  await setField(page, 'ship.mass_kg', -5);
  const st = await runAndWait(page);
  assert(/ship\.mass_kg/.test(st), st);
  const err = await page.textContent('#f-ship-mass_kg-err');
  assert(err.includes('from'), `field error: ${err}`);
  await setField(page, 'ship.mass_kg', 7e6);
});
await check('maneuvering study draws the track', async () => {
  await page.selectOption('#preset', 'turn-90');
  const st = await runAndWait(page);
  assert(st.startsWith('Done'), st);
  await page.screenshot({ path: `${shots}/turn-90.png` });
});
await check('head seas: the sea plots appear (h/R with its bands, losses, wave, motions)', async () => {
  await page.selectOption('#preset', 'head-seas-ss6');
  await setField(page, 'seakeeping.stern_motion', 'thesis_eq_2_57');
  await setField(page, 'sim.duration_s', 30);
  await runAndWait(page);
  assert(/^Done/.test(await page.textContent('#status')), await page.textContent('#status'));
  const titles = await page.$$eval('#plots h3', (hs) => hs.map((h) => h.textContent));
  assert(titles.some((t) => t.startsWith('Hub depth over propeller radius')), titles.join(' | '));
  assert(titles.some((t) => t.startsWith('Propeller surface losses')), 'no loss plot');
  await page.screenshot({ path: `${shots}/head-seas.png` });
});
await check('Monte Carlo runs over workers and shows the Table 5.8 comparison and histograms', async () => {
  await page.selectOption('#preset', 'mc-arrival');
  await setField(page, 'monte_carlo.trials', 6);
  await page.click('#mc-run');
  await page.waitForFunction(() => /^Monte Carlo done|error/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 120000 });
  const st = await page.textContent('#status');
  assert(/^Monte Carlo done: 6 trials/.test(st), st);
  const text = await page.textContent('#plots');
  assert(/Table 5.8/.test(text) && /Rice/.test(text), 'no Table 5.8');
  assert((await page.$$eval('#plots .uplot', (els) => els.length)) >= 3, 'too few Monte Carlo plots');
  await page.screenshot({ path: `${shots}/monte-carlo.png` });
});
await check('a running Monte Carlo study can be cancelled and the form survives', async () => {
  await setField(page, 'monte_carlo.trials', 400);
  await page.click('#mc-run');
  await page.waitForFunction(() => document.getElementById('progress').value > 0, null, { timeout: 60000 });
  await page.click('#cancel');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 5000 });
  await page.waitForFunction(() => !document.getElementById('mc-run').disabled, null, { timeout: 30000 });
  assert((await page.inputValue('#f-monte_carlo-trials')) === '400', 'form lost its edit');
});
await check('100 Monte Carlo trials of head seas SS6 on 2 workers (speed report)', async () => {
  await page.selectOption('#preset', 'head-seas-ss6');
  await setField(page, 'monte_carlo.trials', 100);
  const t0 = Date.now();
  await page.click('#mc-run');
  await page.waitForFunction(() => /^Monte Carlo done/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 180000 });
  console.log(`     ${await page.textContent('#status')} (wall ${((Date.now() - t0) / 1000).toFixed(1)} s, ${await page.evaluate(() => navigator.hardwareConcurrency)} cores)`);
});
await check('fuel study draws the Fig. 5-12 curves and the RAOs', async () => {
  await page.selectOption('#preset', 'fuel-regular-seas');
  await setField(page, 'sim.duration_s', 10);
  await runAndWait(page);
  await page.waitForFunction(() => [...document.querySelectorAll('#plots h3')].filter((h) => /Fig. 5-12|RAOs/.test(h.textContent)).length >= 4, null, { timeout: 60000 });
  await page.screenshot({ path: `${shots}/fuel.png`, fullPage: true });
});
await check('stability tab shows poles and Bode plots, and follows the slider', async () => {
  await page.click('#tab-ips');
  await page.waitForFunction(() => document.getElementById('ips-status').textContent.startsWith('Stable'), null, { timeout: 10000 });
  const before = await page.textContent('#ips-steady');
  await page.fill('#ips-torque', '200');
  await page.dispatchEvent('#ips-torque', 'input');
  await page.waitForFunction((b) => document.getElementById('ips-steady').textContent !== b, before, { timeout: 10000 });
  assert((await page.$$eval('#ips-plots .uplot', (els) => els.length)) === 2, 'no Bode plots');
  assert((await page.$$eval('#ips-plots canvas.track', (els) => els.length)) === 1, 'no pole map');
  assert((await page.$$eval('#ips-poles tbody tr', (r) => r.length)) === 6, 'expected 6 poles above the torque threshold');
  await page.screenshot({ path: `${shots}/stability.png` });
});
await check('keyboard: the Run button is reachable and labelled inputs exist', async () => {
  const unlabelled = await page.$$eval('input, select, textarea', (els) => els.filter((e) => !e.labels?.length && !e.getAttribute('aria-label') && !e.hidden).map((e) => e.id));
  assert(unlabelled.length === 0, `unlabelled: ${unlabelled}`);
});
await check('no console errors and no request left the page', async () => {
  assert(consoleErrors.length === 0, consoleErrors.join('\n'));
});
await browser.close();
console.log(`e2e: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
