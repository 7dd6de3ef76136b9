// What the browser tests share: the browser, a page opened and ready, fields set as a person
// sets them, a run waited for, named checks with a closing count, and axe-core's findings.
import { chromium } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const axeSource = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

export function assert(c, msg) { if (!c) throw new Error(msg); }

// Named checks; E2E_ONLY=regex runs only the matching ones (while working on one; CI runs all).
export function checker() {
  const counts = { passed: 0, failed: 0 };
  const check = async (name, fn) => {
    if (process.env.E2E_ONLY && !new RegExp(process.env.E2E_ONLY).test(name)) return;
    try { await fn(); counts.passed++; console.log(`ok   ${name}`); } catch (e) { counts.failed++; console.log(`FAIL ${name}: ${e.message}`); }
  };
  // The last check (no console errors, no request off the page), then the closing count line and
  // the exit code.
  const finish = async (browser, errors) => {
    await check('no console errors and no request left the page', async () => {
      assert(errors.length === 0, errors.join('\n'));
    });
    await browser.close();
    console.log(`e2e: ${counts.passed} passed, ${counts.failed} failed`);
    process.exit(counts.failed ? 1 : 0);
  };
  return { check, counts, finish };
}

// The browser; every page of its contexts loads the page's test hooks (www/js/testhooks.js: the
// window.__* names the tests read), asked for by a flag set before the page's scripts run.
// A browser that dies while starting (seen once: a crash before the first page, nothing of ours
// loaded) is started again, up to three times, and said so; a crash after it has started fails
// the test as before.
export async function launch() {
  let browser = null;
  for (let attempt = 1; !browser; attempt++) {
    try {
      browser = await chromium.launch({
        executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
        args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
      });
    } catch (e) {
      if (attempt >= 3) throw e;
      console.log(`     the browser did not start (attempt ${attempt} of 3: ${String(e.message).split('\n')[0]}); starting it again`);
    }
  }
  const newContext = browser.newContext.bind(browser);
  browser.newContext = async (options) => {
    const c = await newContext(options);
    await c.addInitScript(() => { globalThis.aesTestHooks = true; });
    return c;
  };
  return browser;
}

// A page of `ctx` at `url`, once the simulator is ready (Run enabled); console errors and
// requests that leave `base` go to `errors`.
export async function openPage(ctx, url, base, errors) {
  const page = await ctx.newPage();
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`${url}: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`${url}: ${e}`));
  page.on('request', (r) => { if (!r.url().startsWith(base) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) errors.push(`request left the origin: ${r.url()}`); });
  await page.goto(url);
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 30000 });
  return page;
}

export async function setField(page, path, value) {
  const sel = '#f-' + path.replace(/\./g, '-');
  // A field the study does not show on top: open the folds it is in.
  await page.$eval(sel, (e) => { for (let d = e.closest('details'); d; d = d.parentElement.closest('details')) d.open = true; });
  if ((await page.$eval(sel, (e) => e.tagName)) === 'SELECT') await page.selectOption(sel, String(value));
  else await page.fill(sel, String(value));
  await page.dispatchEvent(sel, 'change');
}

// Presses `button` (Run or Monte Carlo) and waits for the status to say it ended.
export async function pressAndWait(page, button = '#run') {
  await page.click(button);
  await page.waitForFunction(() => /^Done|^Monte Carlo done|^Cancel/.test(document.getElementById('status').textContent) || document.getElementById('status').className === 'error', null, { timeout: 120000 });
  return page.textContent('#status');
}

// axe-core's violations of the given impacts (or of the given rule ids), as short lines.
export async function axeFindings(page, { impacts = ['serious', 'critical'], rules = [] } = {}) {
  await page.addScriptTag({ content: axeSource });
  return page.evaluate(async ({ impacts, rules }) => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((x) => impacts.includes(x.impact) || rules.includes(x.id))
    .map((x) => `${x.id} (${x.impact}): ${x.nodes.slice(0, 2).map((n) => n.target.join(' ')).join('; ')}`), { impacts, rules });
}

// A fold of the results (`name`: its id is #NAME-box) at the three sizes, each a check: `link`
// opened in a fresh context of that size, `compute(p)` fills the fold, then [`foldFits`]
// (screenshots NAME-WxH.png in `shots`).
export async function foldAtSizes({ browser, check, open, link, compute, name, shots }) {
  const rules = ['heading-order', 'empty-table-header', 'scrollable-region-focusable'];
  for (const [w, h] of [[1366, 768], [1920, 1080], [390, 844]]) {
    await check(`at ${w}x${h}: the ${name} fold fits, axe clean (screenshots)`, async () => {
      const c = await browser.newContext({ viewport: { width: w, height: h }, bypassCSP: true, hasTouch: w < 600 });
      const p = await open(link, c);
      await compute(p);
      await foldFits(p, `#${name}-box`, `${shots}/${name}-${w}x${h}.png`, rules);
      await c.close();
    });
  }
}

// A fold of the results at one size: nothing in `box` (a selector) reaches past the page's width
// unless a scrolling ancestor clips it, a screenshot of it at `shot`, and axe-core clean on `rules`.
export async function foldFits(p, box, shot, rules) {
  await p.waitForTimeout(300);
  const l = await p.evaluate((sel) => {
    const W = document.documentElement.clientWidth;
    const clipped = (e) => { for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) if (getComputedStyle(a).overflowX !== 'visible') return true; return false; };
    const over = [...document.querySelectorAll(`${sel} *`)].filter((e) => e.getClientRects().length && e.getBoundingClientRect().right > W + 1 && !clipped(e)).map((e) => `${e.tagName}#${e.id}.${e.className}`).slice(0, 5);
    return { W, scroll: document.documentElement.scrollWidth, over };
  }, box);
  assert(l.scroll <= l.W && !l.over.length, `the page is ${l.scroll} px wide in ${l.W}; overflowing ${l.over.join(', ')}`);
  await p.locator(box).screenshot({ path: shot });
  const v = await axeFindings(p, { rules });
  assert(!v.length, v.join(' | '));
}
