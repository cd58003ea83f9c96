// Measures the page opening the bundled large-mesh scene (issue 24 item 3): the time from the link to
// the scene shown, every frame interval (requestAnimationFrame), and what the page's console says.
// Not a test: run by hand (node tests/web/measure-large.mjs) with VPLAB_WEB_DIR as for the tests.
import { launchBrowser, openPage, startServer, webDir } from './support.mjs';

const server = await startServer(webDir);
const browser = await launchBrowser();
try {
  const { page } = await openPage(browser, `${server.url}index.html`);
  const said = [];
  const t0 = performance.now();
  page.on('console', (m) => said.push(`${((performance.now() - t0) / 1000).toFixed(2)} s ${m.text()}`));
  await page.evaluate(() => {
    window.__frames = [];
    let last = performance.now();
    const tick = (t) => { window.__frames.push([last, t - last]); last = t; requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
    window.location.hash = '#scene=large-mesh';
  });
  await page.waitForFunction(() => window.vplab.state().scene.includes('large-mesh'), { timeout: 120_000, polling: 200 });
  const shown = performance.now() - t0;
  await new Promise((r) => setTimeout(r, 10000));
  const frames = await page.evaluate(() => window.__frames);
  const start = frames[0][0];
  const long = frames.filter(([, d]) => d > 100).map(([at, d]) => `${d.toFixed(0)} ms at ${(at - start).toFixed(0)}`);
  console.log(`shown after ${shown.toFixed(0)} ms; ${frames.length} frames; longer than 100 ms: ${long.join(', ')}`);
  console.log(said.join('\n'));
  said.length = 0;
  await page.evaluate(() => { window.__frames = []; });
  const t1 = performance.now();
  await page.keyboard.press('p');
  await new Promise((r) => setTimeout(r, 12000));
  const again = await page.evaluate(() => window.__frames);
  const long2 = again.filter(([, d]) => d > 100).map(([at, d]) => `${d.toFixed(0)} ms at ${(at - again[0][0]).toFixed(0)}`);
  console.log(`after P: ${again.length} frames; longer than 100 ms: ${long2.join(', ')}`);
  console.log(said.join('\n'));
} finally {
  await browser.close();
  await server.close();
}
