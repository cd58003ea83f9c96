// The browser tests' and the web benchmark's harness (issue 13, section 3): a static file server on
// 127.0.0.1, Debian's Chromium driven headless through puppeteer-core (WebGL2 on SwiftShader), the
// page's console, `window.vplab` (the contract in the issue's "web contract"), mouse drags in canvas
// pixels, downloads caught into a directory, and an image comparison that prints the worst pixels as
// Magnum's DebugTools::CompareImage does.
//
// Index
//   1. Paths and processes        (webDir, vplabBin, runVplab)
//   2. The server                 (startServer)
//   3. The browser and the page   (launchBrowser, openPage, waitFrames, afterInput, vplabState)
//   4. The mouse and a finger     (cssRect, rectPoint, drag, click, fingerOn)
//   5. Downloads                  (catchDownloads)
//   6. Pictures                   (decodePng, comparePngs, formatComparison, isBlank)

import { execFile } from 'node:child_process';
import { createReadStream, existsSync, mkdtempSync, readdirSync, rmSync, statSync } from 'node:fs';
import { writeFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import { after, before } from 'node:test';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';

import { PNG } from 'pngjs';
import puppeteer from 'puppeteer-core';

// ---------------------------------------------------------------------------------------------------
// 1. Paths and processes
// ---------------------------------------------------------------------------------------------------

const here = path.dirname(fileURLToPath(import.meta.url));
const repoRoot = path.resolve(here, '..', '..');

/** The directory scripts/web.sh builds (index.html, vplab.js, vplab.wasm, vplab.data). */
export const webDir = path.resolve(process.env.VPLAB_WEB_DIR ?? path.join(repoRoot, 'build-web'));
/** The desktop build's `vplab`, the reference the page is compared with. */
export const vplabBin = path.resolve(process.env.VPLAB_BIN ?? path.join(repoRoot, 'build', 'vplab'));
/** Debian's Chromium (package `chromium`); CHROMIUM overrides it. */
export const chromiumBin = process.env.CHROMIUM ?? '/usr/bin/chromium';

const execFileAsync = promisify(execFile);

/** Runs the desktop `vplab` with `args`; resolves to {stdout, stderr}, rejects with both on failure. */
export async function runVplab(args, { timeout = 120_000 } = {}) {
  try {
    return await execFileAsync(vplabBin, args, { timeout, maxBuffer: 256 * 1024 * 1024 });
  } catch (error) {
    error.message = `${vplabBin} ${args.join(' ')} failed (exit ${error.code}): ${error.stderr ?? ''}`;
    throw error;
  }
}

/** A fresh temporary directory; `remove()` deletes it with its contents. */
export function tempDir(prefix) {
  const dir = mkdtempSync(path.join(tmpdir(), `vplab-${prefix}-`));
  return { dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}

// ---------------------------------------------------------------------------------------------------
// 2. The server: static files of one directory on 127.0.0.1, a free port, with the MIME types the page
//    needs (application/wasm lets the browser compile the module while it streams in).
// ---------------------------------------------------------------------------------------------------

const mimeTypes = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
  '.data': 'application/octet-stream',
  '.json': 'application/json',
  '.css': 'text/css; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.obj': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
};

/**
 * Serves `dir` on 127.0.0.1 at a port the system picks. Resolves to {url, port, requests, close()};
 * `requests` lists the paths asked for with their status (a 404 the page did not expect shows there).
 * Nothing is cached (`Cache-Control: no-store`): each page load fetches what a first visit fetches.
 * `hold(urlPath)` may return a promise: the answer waits for it (a slow network, made exact).
 */
export async function startServer(dir, { hold = () => null } = {}) {
  const root = path.resolve(dir);
  const requests = [];
  const server = createServer(async (request, response) => {
    const urlPath = decodeURIComponent(new URL(request.url, 'http://127.0.0.1').pathname);
    await hold(urlPath);
    let file = path.join(root, path.normalize(urlPath));
    const inside = file === root || file.startsWith(root + path.sep);
    if (inside && existsSync(file) && statSync(file).isDirectory()) file = path.join(file, 'index.html');
    const status = request.method !== 'GET' && request.method !== 'HEAD' ? 405
      : !inside || !existsSync(file) || !statSync(file).isFile() ? 404 : 200;
    requests.push({ path: urlPath, status });
    if (status !== 200) {
      response.writeHead(status, { 'Content-Type': 'text/plain' });
      response.end(status === 404 ? 'not found\n' : 'method not allowed\n');
      return;
    }
    response.writeHead(200, {
      'Content-Type': mimeTypes[path.extname(file).toLowerCase()] ?? 'application/octet-stream',
      'Content-Length': statSync(file).size,
      'Cache-Control': 'no-store',
    });
    if (request.method === 'HEAD') response.end();
    else createReadStream(file).pipe(response);
  });
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(0, '127.0.0.1', resolve);
  });
  const { port } = server.address();
  return {
    url: `http://127.0.0.1:${port}/`,
    port,
    requests,
    close: () => new Promise((resolve) => {
      server.closeAllConnections?.();
      server.close(() => resolve());
    }),
  };
}

// ---------------------------------------------------------------------------------------------------
// 3. The browser and the page
// ---------------------------------------------------------------------------------------------------

/** The flags of issue 13: WebGL2 through ANGLE on SwiftShader, and no traffic beyond 127.0.0.1. */
export const chromiumArgs = [
  '--headless=new',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
  '--disable-default-apps',
  '--disable-extensions',
  '--mute-audio',
];

/**
 * The page served and a browser launched for the tests of the current file or suite (node:test's
 * before and after hooks, registered here): returns {server, browser}, filled in before the first test.
 */
export function servedPageAndBrowser() {
  const held = { server: null, browser: null };
  before(async () => {
    if (!existsSync(path.join(webDir, 'index.html'))) throw new Error(`${webDir}/index.html is missing: build the page with scripts/web.sh`);
    held.server = await startServer(webDir);
    held.browser = await launchBrowser();
  });
  after(async () => {
    await held.browser?.close();
    await held.server?.close();
  });
  return held;
}

/**
 * Launches Chromium with a fresh temporary profile. Resolves to the puppeteer Browser; its `close()`
 * also removes the profile. The viewport is 1280 × 720 CSS pixels at devicePixelRatio 1 (the
 * projector size the desktop viewer is designed for) unless `viewport` says otherwise.
 */
export async function launchBrowser({ viewport = { width: 1280, height: 720, deviceScaleFactor: 1 } } = {}) {
  const profile = tempDir('chromium-profile');
  let browser;
  try {
    browser = await puppeteer.launch({
      executablePath: chromiumBin,
      headless: true, // '--headless=new' in args chooses the mode; puppeteer then adds no flag of its own
      args: [...chromiumArgs, `--user-data-dir=${profile.dir}`],
      defaultViewport: viewport,
      timeout: 60_000,
      protocolTimeout: 180_000,
    });
  } catch (error) {
    profile.remove();
    throw error;
  }
  const close = browser.close.bind(browser);
  browser.close = async () => {
    try { await close(); } finally { profile.remove(); }
  };
  return browser;
}

/**
 * Opens `url` in a new tab of `browser` (a puppeteer Browser, or a BrowserContext: a profile of its
 * own, as another visitor's) of `viewport`'s size and deviceScaleFactor, if given, and waits until
 * `window.vplab.ready` resolved (the first frame drawn).
 * Resolves to {page, console}: `console` collects the page's messages of level error and warning and
 * its uncaught exceptions ({type, text, location}) from before the navigation on. `languages` sets
 * the browser's languages (navigator.languages) before the page loads.
 */
export async function openPage(browser, url, { timeout = 60_000, viewport, languages } = {}) {
  const page = await browser.newPage(); // a Browser or a BrowserContext
  if (viewport) await page.setViewport(viewport);
  // `languages`: the browser's, as navigator reports them (['de-DE', 'de']: a German student's).
  if (languages) {
    await page.evaluateOnNewDocument((list) => {
      Object.defineProperty(Navigator.prototype, 'language', { get: () => list[0], configurable: true });
      Object.defineProperty(Navigator.prototype, 'languages', { get: () => list, configurable: true });
    }, languages);
  }
  const messages = [];
  page.on('console', (message) => {
    const type = message.type();
    if (type === 'error' || type === 'warn' || type === 'warning' || type === 'assert') {
      const where = message.location();
      messages.push({ type, text: message.text(), location: where?.url ? `${where.url}${where.lineNumber === undefined ? '' : `:${where.lineNumber + 1}`}` : '' });
    }
  });
  let failed;
  const pageFailed = new Promise((resolve) => { failed = resolve; });
  page.on('pageerror', (error) => {
    messages.push({ type: 'pageerror', text: String(error?.stack ?? error), location: '' });
    failed(); // an uncaught exception before the first frame: no use waiting for it
  });
  page.on('requestfailed', (request) => messages.push({
    type: 'requestfailed', text: `${request.url()}: ${request.failure()?.errorText}`, location: '',
  }));
  page.setDefaultTimeout(timeout);
  await page.goto(url, { waitUntil: 'load', timeout });
  await waitReady(page, messages, timeout, pageFailed);
  return { page, console: messages };
}

/**
 * Waits for `window.vplab.ready`; on a time-out, a rejection or an uncaught exception of the page
 * (`pageFailed` resolves) the error lists what the console said.
 */
export async function waitReady(page, messages = [], timeout = 60_000, pageFailed = new Promise(() => {})) {
  try {
    await page.waitForFunction(() => Boolean(window.vplab && window.vplab.ready), { timeout, polling: 100 });
    // A flag the polling below can see: the page's main thread may be busy or stuck, and a bare
    // evaluate of the promise would wait for the protocol's time-out instead of this one.
    await page.evaluate(() => {
      window.vplab.ready.then(() => { window.__vplabTestReady = 'resolved'; },
        (error) => { window.__vplabTestReady = `rejected: ${error}`; });
    });
    const outcome = await Promise.race([
      page.waitForFunction(() => window.__vplabTestReady, { timeout, polling: 100 }),
      pageFailed.then(() => { throw new Error('the page threw an uncaught exception'); }),
    ]);
    const value = await outcome.jsonValue();
    if (value !== 'resolved') throw new Error(`window.vplab.ready ${value}`);
  } catch (error) {
    const said = messages.map((m) => `  ${m.type}: ${m.text} ${m.location}`).join('\n') || '  (nothing)';
    error.message = `the page did not get ready (window.vplab.ready, waited up to ${timeout} ms): ${error.message}; the console said:\n${said}`;
    throw error;
  }
}

/**
 * Races `promise` against an uncaught exception of the page appearing in `messages` (openPage's
 * console list) from `since` on (default: now): a page that threw will not finish what the test waits for.
 */
export async function unlessPageFails(promise, messages, what, since = messages.length) {
  let timer;
  const failed = new Promise((resolve, reject) => {
    timer = setInterval(() => {
      const error = messages.slice(since).find((m) => m.type === 'pageerror');
      if (error) reject(new Error(`the page threw while waiting for ${what}: ${error.text}`));
    }, 100);
  });
  try {
    return await Promise.race([promise, failed]);
  } finally {
    clearInterval(timer);
  }
}

/** `vplab.state()` of the page (see the web contract). */
export function vplabState(page) {
  return page.evaluate(() => window.vplab.state());
}

/**
 * Waits until `predicate(state())` holds in the page (the predicate runs in the page: it may use
 * nothing but its argument); fails naming `what`, with the state (without its rects) and the console
 * (`messages`, openPage's list), when it does not within `timeout` ms or the page throws meanwhile.
 */
export async function waitForState(page, predicate, what, messages, timeout = 30_000) {
  try {
    await unlessPageFails(page.waitForFunction(`(${String(predicate)})(window.vplab.state())`, { timeout, polling: 100 }),
      messages, what);
  } catch (error) {
    const state = await vplabState(page).then((s) => JSON.stringify({ ...s, rects: undefined }), (e) => `unreadable (${e.message})`);
    throw new Error(`waited for ${what} in vain (${error.message}); state(): ${state}; the console said:\n` +
      (messages.map((m) => `  ${m.type}: ${m.text} ${m.location ?? ''}`).join('\n') || '  (nothing)'));
  }
}

/**
 * Lets the page settle: waits until it drew `count` more frames (state().frames), or until it went
 * idle (no frame for `quietMs`). The page draws only when something changed (input, a due wake-up) plus
 * a few frames for ImGui to settle, as the desktop window does, so an idle page draws nothing.
 * Resolves to the number of frames drawn meanwhile.
 */
export async function waitFrames(page, count = 3, { quietMs = 300, timeout = 30_000 } = {}) {
  return page.evaluate(async (count, quietMs, timeout) => {
    const frames = () => window.vplab.state().frames;
    const start = frames();
    let last = start;
    let lastChange = performance.now();
    const begin = lastChange;
    for (;;) {
      await new Promise((resolve) => setTimeout(resolve, 20));
      const now = performance.now();
      const drawn = frames();
      if (drawn >= start + count) return drawn - start;
      if (drawn !== last) { last = drawn; lastChange = now; } else if (now - lastChange >= quietMs) return drawn - start;
      if (now - begin > timeout) throw new Error(`the page kept drawing for ${timeout} ms without settling`);
    }
  }, count, quietMs, timeout);
}

/**
 * Does `action` (input), then waits for the page to draw a frame for it (up to `timeout` ms: input
 * that changes nothing may draw none) and to settle after it. Resolves to the frames drawn.
 */
export async function afterInput(page, action, { settleFrames = 3, timeout = 2000 } = {}) {
  const before = (await vplabState(page)).frames;
  await action();
  try {
    await page.waitForFunction((n) => window.vplab.state().frames > n, { timeout, polling: 20 }, before);
  } catch {
    // no frame: the input changed nothing the page draws (the caller's assertions say whether it should)
  }
  await waitFrames(page, settleFrames);
  return (await vplabState(page)).frames - before;
}

/** `vplab.exportPng(view, width, height)` as a Node Buffer holding the PNG file. */
export async function exportPng(page, view, width, height) {
  const bytes = await page.evaluate(async (v, w, h) => {
    const png = await window.vplab.exportPng(v, w, h);
    // Base64 keeps a large array cheap to carry over the protocol.
    let binary = '';
    for (let i = 0; i < png.length; i += 0x8000) binary += String.fromCharCode(...png.subarray(i, i + 0x8000));
    return btoa(binary);
  }, view, width, height);
  return Buffer.from(bytes, 'base64');
}

// ---------------------------------------------------------------------------------------------------
// 4. The mouse: the page reports ImGui rects in canvas pixels; puppeteer's mouse takes CSS pixels of
//    the viewport.
// ---------------------------------------------------------------------------------------------------

/**
 * The rect `id` of `state.rects` (canvas pixels [x, y, w, h]) in CSS pixels of the viewport:
 * divided by devicePixelRatio and moved by the canvas's own position on the page.
 */
export async function cssRect(page, state, id) {
  const rect = state.rects?.[id];
  if (!Array.isArray(rect) || rect.length !== 4) {
    throw new Error(`vplab.rects().rects has no rect "${id}" (it has: ${Object.keys(state.rects ?? {}).join(', ') || 'none'})`);
  }
  const canvas = await page.$eval('#canvas', (element) => {
    const box = element.getBoundingClientRect();
    return { left: box.left, top: box.top, width: box.width, height: box.height };
  });
  // Canvas pixels per CSS pixel: the page sizes its canvas at devicePixelRatio; measured, not assumed.
  const scaleX = state.canvas[0] / canvas.width;
  const scaleY = state.canvas[1] / canvas.height;
  const [x, y, w, h] = rect;
  return { x: canvas.left + x / scaleX, y: canvas.top + y / scaleY, w: w / scaleX, h: h / scaleY };
}

/** The point at fractions (fx, fy) of a CSS rect. */
export function rectPoint(rect, fx = 0.5, fy = 0.5) {
  return { x: rect.x + rect.w * fx, y: rect.y + rect.h * fy };
}

/**
 * Drags the left mouse button from `from` to `to` (CSS pixels) in `steps` moves, letting the page
 * draw and settle after the press, each move and the release: ImGui sees each event in a frame of its
 * own, as a hand on a real mouse gives it.
 */
export async function drag(page, from, to, { steps = 10, button = 'left' } = {}) {
  await afterInput(page, () => page.mouse.move(from.x, from.y));
  await afterInput(page, () => page.mouse.down({ button }));
  for (let i = 1; i <= steps; ++i) {
    const t = i / steps;
    await afterInput(page, () => page.mouse.move(from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t));
  }
  await afterInput(page, () => page.mouse.up({ button }));
}

/** Clicks at `point` (CSS pixels): move, press and release, each in frames of its own. */
export async function click(page, point) {
  await afterInput(page, () => page.mouse.move(point.x, point.y));
  await afterInput(page, () => page.mouse.down());
  await afterInput(page, () => page.mouse.up());
}

/** A finger on `page`: tap, swipe and hold through the protocol's touch events, each in frames of its own. */
export async function fingerOn(page) {
  const cdp = await page.createCDPSession();
  // `at`: the event's time (s since the epoch), as a finger's hardware stamps it; the protocol
  // answers only once the page handled an event, so a slow frame would otherwise space them out.
  const touch = (type, points, at = undefined) => cdp.send('Input.dispatchTouchEvent',
    { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })), ...(at === undefined ? {} : { timestamp: at }) });
  return {
    cdp,
    touch,
    async tap(point) {
      await afterInput(page, () => touch('touchStart', [[point.x, point.y]]));
      await afterInput(page, () => touch('touchEnd', []));
    },
    async swipe(from, to, steps = 8) {
      await afterInput(page, () => touch('touchStart', [[from.x, from.y]]));
      for (let i = 1; i <= steps; ++i)
        await afterInput(page, () => touch('touchMove', [[from.x + (to.x - from.x) * i / steps, from.y + (to.y - from.y) * i / steps]]));
      await afterInput(page, () => touch('touchEnd', []));
    },
    /** A flick: moves stamped 16 ms apart (a finger's pace, however slow the page's frames), lifted while moving. */
    async flick(from, to, steps = 6) {
      const start = Date.now() / 1000;
      await afterInput(page, () => touch('touchStart', [[from.x, from.y]], start));
      for (let i = 1; i <= steps; ++i)
        await touch('touchMove', [[from.x + (to.x - from.x) * i / steps, from.y + (to.y - from.y) * i / steps]], start + 0.016 * i);
      await touch('touchEnd', [], start + 0.016 * (steps + 1));
    },
  };
}

// ---------------------------------------------------------------------------------------------------
// 5. Downloads: the page downloads through an <a download> click; the browser's CDP session writes
//    them into a temporary directory.
// ---------------------------------------------------------------------------------------------------

/**
 * Sends the downloads of `browser` (of its BrowserContext `context`, if given) into a fresh temporary directory. Resolves to
 * {dir, next(timeout) -> Promise<{file, name}>, remove()}; `next` waits for the next completed download.
 */
export async function catchDownloads(browser, context = undefined) {
  const target = tempDir('downloads');
  const session = await browser.target().createCDPSession();
  const begun = new Map(); // guid -> suggested file name
  const finished = [];
  const waiting = [];
  const timers = new Set();
  session.on('Browser.downloadWillBegin', (event) => begun.set(event.guid, event.suggestedFilename));
  session.on('Browser.downloadProgress', (event) => {
    if (event.state !== 'completed' && event.state !== 'canceled') return;
    const done = { guid: event.guid, state: event.state, name: begun.get(event.guid) };
    const waiter = waiting.shift();
    if (waiter) waiter(done); else finished.push(done);
  });
  await session.send('Browser.setDownloadBehavior', {
    behavior: 'allowAndName', // saved as DIR/GUID: no clash with earlier files, the name reported apart
    downloadPath: target.dir,
    eventsEnabled: true,
    ...(context?.id ? { browserContextId: context.id } : {}),
  });
  return {
    dir: target.dir,
    async next(timeout = 30_000) {
      const done = finished.shift() ?? await new Promise((resolve, reject) => {
        const timer = setTimeout(() => {
          timers.delete(timer);
          let there = 'nothing';
          try { there = readdirSync(target.dir).join(', ') || there; } catch { /* removed meanwhile */ }
          reject(new Error(`no download completed within ${timeout} ms (in ${target.dir}: ${there})`));
        }, timeout);
        timers.add(timer);
        waiting.push((value) => { clearTimeout(timer); timers.delete(timer); resolve(value); });
      });
      if (done.state !== 'completed') throw new Error(`the download of ${done.name} was canceled`);
      return { file: path.join(target.dir, done.guid), name: done.name };
    },
    async remove() {
      for (const timer of timers) clearTimeout(timer); // a wait given up on (the page failed first)
      timers.clear();
      await session.detach().catch(() => {});
      target.remove();
    },
  };
}

// ---------------------------------------------------------------------------------------------------
// 6. Pictures
// ---------------------------------------------------------------------------------------------------

/** Decodes a PNG file's bytes into {width, height, data} (RGBA, 8 bits a channel). */
export function decodePng(bytes) {
  return PNG.sync.read(Buffer.from(bytes));
}

/**
 * Compares two PNGs channel by channel (R, G, B, A; 0..255). Resolves to
 * {width, height, max, mean, pixelsOver(threshold), worst: the `worstCount` pixels of the largest
 * difference (largest channel difference of the pixel, then the sum of its channels' differences),
 * each {x, y, delta, actual: [r,g,b,a], expected: [r,g,b,a]}}. Sizes that differ throw.
 * `max` is the largest absolute channel difference; `mean` the mean over every channel of every pixel.
 */
export function comparePngs(actualBytes, expectedBytes, { worstCount = 10 } = {}) {
  const actual = decodePng(actualBytes);
  const expected = decodePng(expectedBytes);
  if (actual.width !== expected.width || actual.height !== expected.height) {
    throw new Error(`image sizes differ: actual ${actual.width}x${actual.height}, expected ${expected.width}x${expected.height}`);
  }
  const { width, height } = actual;
  const pixelDelta = new Uint8Array(width * height);
  let max = 0;
  let sum = 0;
  for (let p = 0; p < width * height; ++p) {
    let pixelMax = 0;
    for (let c = 0; c < 4; ++c) {
      const d = Math.abs(actual.data[4 * p + c] - expected.data[4 * p + c]);
      sum += d;
      if (d > pixelMax) pixelMax = d;
    }
    pixelDelta[p] = pixelMax;
    if (pixelMax > max) max = pixelMax;
  }
  const pixelSum = (p) => [0, 1, 2, 3].reduce((s, c) => s + Math.abs(actual.data[4 * p + c] - expected.data[4 * p + c]), 0);
  const candidates = [];
  for (let p = 0; p < width * height; ++p) if (pixelDelta[p] > 0) candidates.push(p);
  candidates.sort((a, b) => pixelDelta[b] - pixelDelta[a] || pixelSum(b) - pixelSum(a) || a - b);
  const colour = (image, p) => Array.from(image.data.subarray(4 * p, 4 * p + 4));
  const worst = candidates.slice(0, worstCount).map((p) => ({
    x: p % width, y: Math.floor(p / width), delta: pixelDelta[p], actual: colour(actual, p), expected: colour(expected, p),
  }));
  return {
    width, height, max, mean: sum / (width * height * 4), differing: candidates.length, worst,
    pixelsOver: (threshold) => pixelDelta.reduce((n, d) => n + (d > threshold ? 1 : 0), 0),
    diffPng() {
      // Each pixel's largest channel difference, amplified ×4, white on black: where they differ.
      const out = new PNG({ width, height });
      for (let p = 0; p < width * height; ++p) {
        const v = Math.min(255, pixelDelta[p] * 4);
        out.data.set([v, v, v, 255], 4 * p);
      }
      return PNG.sync.write(out);
    },
  };
}

/** A report of a comparison: the thresholds, the measured max and mean, and the worst pixels. */
export function formatComparison(result, { maxThreshold, meanThreshold, label = 'images' } = {}) {
  const hex = (rgba) => `#${rgba.map((v) => v.toString(16).padStart(2, '0')).join('')}`;
  const lines = [
    `${label}: ${result.width}x${result.height}, max difference ${result.max}` +
      (maxThreshold === undefined ? '' : ` (allowed ${maxThreshold})`) +
      `, mean ${result.mean.toFixed(4)}` + (meanThreshold === undefined ? '' : ` (allowed ${meanThreshold})`) +
      `, ${result.differing} pixels differ`,
  ];
  if (result.worst.length) {
    lines.push(`  the ${result.worst.length} worst pixels (x, y: actual vs expected, largest channel difference):`);
    for (const w of result.worst) {
      lines.push(`    [${String(w.x).padStart(4)},${String(w.y).padStart(4)}] ${hex(w.actual)} vs ${hex(w.expected)}, ${w.delta}`);
    }
  }
  return lines.join('\n');
}

/** Whether a PNG is one colour only (a page that drew nothing). Resolves to {blank, colours}. */
export function distinctColours(bytes, limit = 64) {
  const { width, height, data } = decodePng(bytes);
  const seen = new Set();
  for (let p = 0; p < width * height && seen.size < limit; ++p) {
    seen.add((data[4 * p] << 16) | (data[4 * p + 1] << 8) | data[4 * p + 2]);
  }
  return seen.size;
}

/** Writes the actual, expected and difference pictures of a failed comparison for a person to look at. */
export async function keepArtifacts(name, { actual, expected, comparison }) {
  const dir = process.env.VPLAB_WEB_ARTIFACTS ?? path.join(tmpdir(), 'vplab-web-artifacts');
  const { mkdirSync } = await import('node:fs');
  mkdirSync(dir, { recursive: true });
  const written = [];
  const put = async (suffix, bytes) => {
    if (!bytes) return;
    const file = path.join(dir, `${name}.${suffix}.png`);
    await writeFile(file, bytes);
    written.push(file);
  };
  await put('actual', actual);
  await put('expected', expected);
  if (comparison) await put('diff', comparison.diffPng());
  return written;
}
