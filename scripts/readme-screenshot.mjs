// The README's screenshot (docs/screenshot.png): the head-seas study after its run, from the top of
// the page, in headless Chromium. Usage: serve www (e.g. ./build.sh), then
//   node scripts/readme-screenshot.mjs http://127.0.0.1:8080/ docs/screenshot.png
import { chromium } from 'playwright-core';

const [base = 'http://127.0.0.1:8080/', out = 'docs/screenshot.png'] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1600, height: 1000 } });
  await page.goto(base);
  await page.waitForFunction(() => !document.getElementById('run').disabled, null, { timeout: 60000 });
  await page.selectOption('#preset', 'head-seas-ss6');
  await page.click('#run');
  await page.waitForFunction(() => /^Done/.test(document.getElementById('status').textContent), null, { timeout: 60000 });
  // The live views at a moment of ventilation (h/R below 1.1: the disc near the surface).
  await page.evaluate((t) => {
    const s = document.getElementById('live-time');
    s.value = String(t); // seconds
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, Number(process.env.AT_S || 11.4));
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: out });
  console.log(`wrote ${out}`);
} finally {
  await browser.close();
}
