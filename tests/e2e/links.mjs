// Browser test: links and errors that help (issue 55). A lesson link's text that is no number is
// called that; a value between slider stops is said where the student sees it; one bad value in
// a simulator link loses only itself; the maneuvers' refusal names what would make them run, with
// a one-click fix; Cancel clears the progress; a study that prepares says so; values that change
// nothing add no history entry. Screenshots of the error states at 1366x768, 1920x1080 and 390x844.
// Usage: node tests/e2e/links.mjs http://127.0.0.1:PORT/ SCREENSHOT_DIR
import { mkdirSync } from 'node:fs';
import { assert, axeFindings, checker, launch, openPage } from './lib.mjs';

const base = process.argv[2];
const shots = process.argv[3];
mkdirSync(shots, { recursive: true });
const { check, finish } = checker();
const errors = [];
const browser = await launch();
const SIZES = [[1366, 768], [1920, 1080], [390, 844]];
const b64 = (x) => Buffer.from(JSON.stringify(x)).toString('base64url');
// bypassCSP: axe-core is injected as an inline script (the page's own policy forbids those).
const context = (w, h) => browser.newContext({ viewport: { width: w, height: h }, hasTouch: w < 600, bypassCSP: true });
// axe-core finds nothing serious in an error state.
const axeClean = async (p) => { const v = await axeFindings(p); assert(!v.length, v.join(' | ')); };
// An element's box inside the viewport (top and bottom both on screen).
const inView = (p, sel) => p.$eval(sel, (e) => { const r = e.getBoundingClientRect(); return r.top >= 0 && r.bottom <= innerHeight && r.height > 0; });

for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: a lesson link's "abc" is not a number (with the range) and 100 deg between the stops is said as 105 deg (screenshot)`, async () => {
    const c = await context(w, h);
    const p = await c.newPage();
    p.on('pageerror', (e) => errors.push(String(e)));
    await p.goto(`${base}#lesson=turn&commands.1.heading_deg=100&initial.speed_kn=abc`);
    await p.waitForSelector('#lesson-refused', { timeout: 30000 });
    const refused = await p.textContent('#lesson-refused');
    assert(/"abc" is not a number; this lesson's range is 17 to 30 kn/.test(refused), refused);
    assert(!/outside/.test(refused), `"abc" said to be out of range: ${refused}`);
    const snapped = await p.textContent('#lesson-snapped').catch(() => '(no line)');
    assert(/100 deg lies between this lesson's stops; the nearest, 105 deg, is used/.test(snapped), snapped);
    assert(await inView(p, '#lesson-snapped') && await inView(p, '#lesson-refused'), 'the words are not in view');
    assert((await p.textContent('#lesson-commands-1-heading_deg-out')).trim() === '105 deg', 'the slider does not show the stop used');
    assert(/commands\.1\.heading_deg=105/.test(await p.evaluate(() => location.hash)), 'the address does not carry the stop used');
    await p.screenshot({ path: `${shots}/links-lesson-${w}x${h}.png` });
    await axeClean(p);
    await c.close();
  });
}

for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: a simulator link with one bad value (initial speed 1e9) refuses it by name and keeps the rest of the study (screenshot)`, async () => {
    const c = await context(w, h);
    const p = await openPage(c, `${base}#v=2&preset=turn-90&d=${b64({ initial: { speed_kn: 1e9 }, sim: { seed: 7 } })}`, base, errors);
    await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
    const notice = await p.textContent('#notice');
    assert(/Initial speed \[kn\] \(initial\.speed_kn\) = 1000000000 was refused/.test(notice) && /0 to 35 kn/.test(notice) && /study's value, 25 kn, is used/.test(notice), notice);
    assert(/other values are kept/.test(notice), notice);
    assert((await p.$eval('#preset', (s) => s.value)) === 'turn-90', 'the study was dropped');
    assert((await p.inputValue('#f-sim-seed')) === '7', 'the link\'s other value was dropped');
    assert((await p.inputValue('#f-initial-speed_kn')) === '25', 'the refused value is not the study\'s');
    assert(/was refused/.test(await p.textContent('#f-initial-speed_kn-field .link-refused')), 'no word at the field');
    assert((await p.getAttribute('#f-initial-speed_kn', 'aria-invalid')) === null && !(await p.$eval('#run', (b) => b.disabled)), 'the study\'s value is marked invalid');
    await p.screenshot({ path: `${shots}/links-simulator-${w}x${h}.png` });
    await p.$eval('#f-initial-speed_kn-field', (e) => e.scrollIntoView({ block: 'center' }));
    await p.screenshot({ path: `${shots}/links-simulator-field-${w}x${h}.png` });
    await axeClean(p);
    // Typing a value of one's own there takes the link's word away.
    await p.fill('#f-initial-speed_kn', '20');
    await p.dispatchEvent('#f-initial-speed_kn', 'change');
    assert(!(await p.$('#f-initial-speed_kn-field .link-refused')), 'the link\'s word stays after an edit');
    await c.close();
  });
}

await check('a link\'s bad optional parts (the live views\' place, the tab) are said and lose only themselves', async () => {
  const c = await context(1366, 768);
  const p = await openPage(c, `${base}#v=2&preset=turn-90&d=${b64({ sim: { seed: 7 } })}&tab=nope&at=abc&speed=2`, base, errors);
  await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  const notice = await p.textContent('#notice');
  assert(/place in the live views \(at="abc", speed="2"\) is not used: at is a time from 0 to 1e7 s/.test(notice), notice);
  assert(/tab="nope" is not one of sim, design, ips, operability: sim is used/.test(notice), notice);
  assert((await p.$eval('#preset', (s) => s.value)) === 'turn-90' && (await p.inputValue('#f-sim-seed')) === '7', 'the study or its value was dropped');
  await c.close();
});

await check('a hand-edited address with one bad value keeps the rest, says it, and the address shows the values used', async () => {
  const c = await context(1366, 768);
  const p = await openPage(c, `${base}#v=2&preset=turn-90`, base, errors);
  await p.evaluate((h) => { location.hash = h; }, `v=2&preset=turn-45&d=${b64({ initial: { speed_kn: 'fast' }, sim: { seed: 9 } })}`);
  await p.waitForFunction(() => /was refused/.test(document.getElementById('notice').textContent), null, { timeout: 10000 });
  assert(/Initial speed \[kn\] \(initial\.speed_kn\) = "fast" was refused/.test(await p.textContent('#notice')), await p.textContent('#notice'));
  assert((await p.$eval('#preset', (s) => s.value)) === 'turn-45' && (await p.inputValue('#f-sim-seed')) === '9', 'the rest of the address was dropped');
  const d = new URLSearchParams(await p.evaluate(() => location.hash.slice(1))).get('d');
  assert(d && !/speed_kn/.test(Buffer.from(d, 'base64url').toString()), 'the address still carries the refused value');
  await c.close();
});

// The booklet of the default study (the surge hull) from a fresh page: the refusal and the button.
async function refusedBooklet(c) {
  const p = await openPage(c, base, base, errors);
  await p.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  await p.$eval('#maneuvers-box', (d) => { d.open = true; });
  await p.click('#maneuvers-compute');
  await p.waitForFunction(() => /could not/.test(document.getElementById('maneuvers-status').textContent), null, { timeout: 30000 });
  const st = await p.textContent('#maneuvers-status');
  assert(/hull\.model = "maneuvering"/.test(st) && /turn-360/.test(st), `the refusal names no way out: ${st}`);
  assert(await p.isVisible('#maneuvers-fix-model') && await p.isVisible('#maneuvers-fix-study'), 'no one-click fix');
  return p;
}
const bookletDone = (p) => p.waitForFunction(() => /^Done/.test(document.getElementById('maneuvers-status').textContent) && !document.getElementById('maneuvers-body').hidden, null, { timeout: 60000 });
for (const [w, h] of SIZES) {
  await check(`at ${w}x${h}: the maneuvers of the default study name the field and the study that would run, and one click sets the field and computes (screenshot)`, async () => {
    const c = await context(w, h);
    const p = await refusedBooklet(c);
    await p.$eval('#maneuvers-box', (e) => e.scrollIntoView({ block: 'start' }));
    await p.screenshot({ path: `${shots}/links-maneuvers-${w}x${h}.png` });
    await axeClean(p);
    await p.click('#maneuvers-fix-model');
    await bookletDone(p);
    assert((await p.inputValue('#f-hull-model')) === 'maneuvering', 'the field was not set');
    assert(await p.$eval('#maneuvers-fix', (e) => e.hidden), 'the fix stays offered after it worked');
    await c.close();
  });
}
await check('the maneuvers\' other fix opens the turning study the message names and computes', async () => {
  const c = await context(1366, 768);
  const p = await refusedBooklet(c);
  await p.click('#maneuvers-fix-study');
  await bookletDone(p);
  assert((await p.$eval('#preset', (s) => s.value)) === 'turn-360', 'the study was not opened');
  await c.close();
});

await check('Monte Carlo says it prepares (its bar without a share), and Cancel clears its progress (bar and words)', async () => {
  const c = await context(1366, 768);
  const p = await openPage(c, `${base}#v=2&preset=mc-arrival&d=${b64({ monte_carlo: { trials: 400 } })}`, base, errors);
  await p.waitForFunction(() => !document.getElementById('mc-run').disabled, null, { timeout: 60000 });
  // Every status line with the bar's state as it was said (the preparation may be short).
  await p.evaluate(() => {
    window.seenStatus = [];
    new MutationObserver(() => window.seenStatus.push({ text: document.getElementById('status').textContent, share: document.getElementById('progress').hasAttribute('value') }))
      .observe(document.getElementById('status'), { childList: true, characterData: true, subtree: true });
  });
  await p.click('#mc-run');
  await p.waitForFunction(() => document.getElementById('progress').value > 0.05 || document.querySelector('#long-study[open]'), null, { timeout: 60000 });
  if (await p.$('#long-study[open]')) {
    await p.click('#long-study-go');
    await p.waitForFunction(() => document.getElementById('progress').value > 0.05, null, { timeout: 60000 });
  }
  await p.click('#cancel');
  await p.waitForFunction(() => document.getElementById('status').textContent === 'Cancelled.', null, { timeout: 10000 });
  await p.waitForTimeout(300);
  const seen = await p.evaluate(() => window.seenStatus);
  assert(seen.some((x) => /^Monte Carlo: preparing/.test(x.text) && !x.share), `no preparing line with a bar without a share: ${JSON.stringify(seen.slice(0, 4))}`);
  const left = await p.evaluate(() => ({ value: document.getElementById('progress').value, eta: document.getElementById('eta').textContent }));
  assert(left.value === 0 && left.eta === '', `after Cancel the bar shows ${left.value} and "${left.eta}"`);
  await c.close();
});

await check('rare events say they are preparing (not "0 of n trials") until the first trial, then count', async () => {
  const c = await context(1366, 768);
  const p = await openPage(c, `${base}#v=2&preset=head-seas-ss6`, base, errors);
  await p.$eval('#rare-box', (d) => { d.open = true; });
  await p.waitForFunction(() => !document.getElementById('rare-compute').disabled, null, { timeout: 30000 });
  await p.fill('#rare-trials', '8');
  await p.dispatchEvent('#rare-trials', 'change');
  await p.click('#rare-compute');
  await p.waitForFunction(() => document.getElementById('rare-eta').textContent !== '', null, { timeout: 10000 });
  const early = await p.evaluate(() => ({ eta: document.getElementById('rare-eta').textContent, share: document.getElementById('rare-progress').hasAttribute('value') }));
  assert(/^Preparing the trials/.test(early.eta) && /first of 8/.test(early.eta), `while preparing: "${early.eta}"`);
  assert(!early.share, 'the bar shows a share while nothing is counted');
  await p.waitForFunction(() => /^Done|failed|Cancelled/.test(document.getElementById('rare-status').textContent), null, { timeout: 120000 });
  assert(/^8 of 8 trials/.test(await p.textContent('#rare-eta')), `after: ${await p.textContent('#rare-eta')}`);
  await c.close();
});

await check('a fold on the worker pool (fuel per mile) says it prepares, its bar without a share, then counts', async () => {
  const c = await context(1366, 768);
  const p = await openPage(c, `${base}#v=2&preset=head-seas-ss6`, base, errors);
  await p.$eval('#fuel-box', (e) => { e.open = true; });
  await p.fill('#fuel-speeds', '12, 24');
  await p.fill('#fuel-seeds', '2');
  await p.evaluate(() => {
    window.seenEta = [];
    new MutationObserver(() => window.seenEta.push({ text: document.getElementById('fuel-eta').textContent, share: document.getElementById('fuel-progress').hasAttribute('value') }))
      .observe(document.getElementById('fuel-eta'), { childList: true, characterData: true, subtree: true });
  });
  await p.click('#fuel-compute');
  await p.waitForFunction(() => /^Done|failed|refused|Cancelled/.test(document.getElementById('fuel-status').textContent), null, { timeout: 120000 });
  const seen = await p.evaluate(() => window.seenEta);
  assert(seen.length && /^Preparing the workers/.test(seen[0].text) && /first of 4 runs/.test(seen[0].text) && !seen[0].share, `first words: ${JSON.stringify(seen.slice(0, 3))}`);
  // "0 of 4" may follow once the runs have started (the pool's word that preparing ended), never before.
  assert(seen.findIndex((x) => /^0 of 4/.test(x.text)) !== 0, `"0 of 4" was said first: ${JSON.stringify(seen)}`);
  assert(/^4 of 4 runs/.test(await p.textContent('#fuel-eta')), `after: ${await p.textContent('#fuel-eta')}`);
  await c.close();
});

await check('a lesson value released where it was adds no history entry; a new value adds one', async () => {
  const c = await context(1366, 768);
  const p = await c.newPage();
  p.on('pageerror', (e) => errors.push(String(e)));
  await p.goto(`${base}#lesson=turn`);
  await p.waitForSelector('#lesson-skip:not([disabled])', { timeout: 30000 });
  await p.click('#lesson-skip');
  await p.waitForSelector('.lesson-explain', { timeout: 30000 });
  const before = await p.evaluate(() => history.length);
  await p.dispatchEvent('#lesson-commands-1-heading_deg', 'change');
  await p.waitForTimeout(1500);
  assert((await p.evaluate(() => history.length)) === before, 'the same value added a history entry');
  await p.focus('#lesson-commands-1-heading_deg');
  await p.keyboard.press('End');
  await p.waitForFunction((n) => history.length === n + 1, before, { timeout: 10000 });
  await c.close();
});

await finish(browser, errors);
