// Measures the page opening the bundled large-mesh scene (issue 24 item 3): the time from the link to
// the scene shown, every frame interval (requestAnimationFrame), when the views' new images are
// complete (the page's count of views drawn), then the same after a change of the camera (P: the next
// projection). Not a test: run by hand (node tests/web/measure-large.mjs [more of the link]) with
// VPLAB_WEB_DIR as for the tests; it prints what the page's console said as well. More of the link,
// e.g. `camera-style=wire&world-style=wire&npc-style=wire`, measures the scene in other styles.
import { launchBrowser, openPage, startServer, webDir } from './support.mjs';

const server = await startServer(webDir);
const browser = await launchBrowser();

/** Frames and views drawn for `seconds` after `start` (performance.now() in the page). */
async function watch(page, seconds) {
  const drawn = [];
  const t0 = await page.evaluate(() => performance.now());
  let last = -1;
  while ((await page.evaluate(() => performance.now())) - t0 < seconds * 1000) {
    const { now, views } = await page.evaluate(() => ({ now: performance.now(), views: window.vplab.state().viewsDrawn }));
    if (views !== last) drawn.push(`${views} at ${((now - t0) / 1000).toFixed(1)} s`);
    last = views;
    await new Promise((r) => setTimeout(r, 250));
  }
  const frames = await page.evaluate(() => window.__frames.splice(0));
  const start = frames.length ? frames[0][0] : 0;
  const long = frames.filter(([, d]) => d > 100).map(([at, d]) => `${d.toFixed(0)} ms at ${((at - start) / 1000).toFixed(1)} s`);
  const longest = Math.max(...frames.map(([, d]) => d));
  return `${frames.length} frames, longest ${longest.toFixed(0)} ms; over 100 ms: ${long.join(', ') || 'none'}\n  views drawn: ${drawn.join(', ')}`;
}

try {
  const { page } = await openPage(browser, `${server.url}index.html`);
  const said = [];
  page.on('console', (m) => said.push(m.text()));
  await page.evaluate((more) => {
    window.__frames = [];
    let last = performance.now();
    const tick = (t) => { window.__frames.push([last, t - last]); last = t; requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
    window.location.hash = `#scene=large-mesh${more ? `&${more}` : ''}`;
  }, process.argv[2] ?? '');
  console.log(`opening #scene=large-mesh${process.argv[2] ? `&${process.argv[2]}` : ''}: ${await watch(page, 30)}`);
  await page.keyboard.press('p');
  console.log(`after P (the next projection): ${await watch(page, 30)}`);
  if (said.length) console.log(`the console said:\n${said.join('\n')}`);
} finally {
  await browser.close();
  await server.close();
}
