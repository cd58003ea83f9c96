// The page in German and English (docs/lecturers.md "German and English"): a browser whose language is German
// opens the page in German, its own texts (index.html's, shown before the lab has loaded) as well as
// the lab's; View ▸ Language's choice wins over the browser's and is kept in localStorage for the
// next visit.
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, test } from 'node:test';

import {
  afterInput, click, cssRect, launchBrowser, rectPoint, startServer, vplabState, waitForState, waitFrames,
  waitReady, webDir,
} from './support.mjs';

const errorsOf = (messages) => messages.filter((m) => m.type === 'error' || m.type === 'pageerror');

/** The page's own message over the canvas (index.html's #vplab-message), or null while it is hidden. */
const messageShown = (page) => page.evaluate(() => {
  const m = document.getElementById('vplab-message');
  return m.hidden ? null : m.textContent;
});

describe('the page in German and English', { concurrency: 1 }, () => {
  let server;
  let browser;
  // While `gate` is set, the server holds vplab.js until gate.release(): the page shows its own
  // loading text, before any WebAssembly, for as long as the test reads it.
  let gate = null;

  before(async () => {
    assert.ok(existsSync(path.join(webDir, 'index.html')), `${webDir}/index.html is missing: build the page with scripts/web.sh`);
    server = await startServer(webDir, {
      hold: (urlPath) => {
        if (urlPath !== '/vplab.js' || !gate) return null;
        gate.held = true;
        return gate.promise;
      },
    });
    browser = await launchBrowser();
  });

  after(async () => {
    gate?.release();
    await browser?.close();
    await server?.close();
  });

  function holdLab() {
    let release;
    const promise = new Promise((resolve) => { release = resolve; });
    gate = { promise, held: false, release: () => { gate = null; release(); } };
    return gate;
  }

  /**
   * Loads the page by `navigate` (a goto or a reload) with vplab.js held: resolves to the page's own
   * loading text and its <html lang>, read before the lab's WebAssembly is there, once the lab is ready.
   */
  async function loadHeld(page, messages, navigate) {
    const held = holdLab();
    await navigate();
    await page.waitForFunction(() => document.getElementById('vplab-message')?.textContent, { timeout: 20_000 });
    for (let i = 0; i < 200 && !held.held; ++i) await new Promise((resolve) => setTimeout(resolve, 50));
    assert.ok(held.held, 'the page did not ask for vplab.js');
    const shown = await page.evaluate(() => ({
      text: document.getElementById('vplab-message').textContent,
      lang: document.documentElement.lang,
      started: Boolean(window.vplab && window.vplab.firstFrameMs !== null),
    }));
    held.release();
    await waitReady(page, messages);
    await waitFrames(page, 3);
    return shown;
  }

  /**
   * Opens View ▸ Language (the View menu's recorded rect, then its Language item, which opens its
   * submenu). Resolves to the state with the submenu's items. `state.rects` keeps a rect once drawn:
   * meant for a page that has not drawn the submenu yet.
   */
  async function openLanguageMenu(page, messages) {
    const state = await vplabState(page);
    assert.ok(!state.rects['menu.language'], 'the View menu was drawn before (its rect would not tell that it opened now)');
    await click(page, rectPoint(await cssRect(page, state, 'menu.view')));
    await waitForState(page, (s) => Boolean(s.rects['menu.language']), 'the View menu', messages, 5000);
    await click(page, rectPoint(await cssRect(page, await vplabState(page), 'menu.language')));
    await waitForState(page, (s) => Boolean(s.rects['menu.language.en'] && s.rects['menu.language.de']),
      'View ▸ Language\'s items', messages, 5000);
    return vplabState(page);
  }

  test('(a) a German browser gets the page in German, (b) View ▸ Language ▸ English switches and is kept over a reload, (c) the page\'s own texts follow', { timeout: 240_000 }, async () => {
    const context = await browser.createBrowserContext(); // a profile of its own: nothing chosen yet
    const page = await context.newPage();
    const messages = [];
    page.on('console', (m) => { if (m.type() === 'error') messages.push({ type: 'error', text: m.text() }); });
    page.on('pageerror', (e) => messages.push({ type: 'pageerror', text: String(e?.stack ?? e) }));
    page.setDefaultTimeout(60_000);
    // The browser's language is German (as a German Chromium's navigator reports it).
    await page.evaluateOnNewDocument(() => {
      Object.defineProperty(Navigator.prototype, 'language', { get: () => 'de-DE', configurable: true });
      Object.defineProperty(Navigator.prototype, 'languages', { get: () => ['de-DE', 'de', 'en-US', 'en'], configurable: true });
    });

    // (a), (c): German before the lab has loaded (index.html's own text) and in the lab.
    const loadingDe = await loadHeld(page, messages, () => page.goto(server.url, { waitUntil: 'domcontentloaded' }));
    assert.equal(loadingDe.started, false, 'the lab started although vplab.js was held');
    assert.equal(loadingDe.text, 'vplab wird geladen …', 'the page\'s loading text is not German in a German browser');
    assert.equal(loadingDe.lang, 'de', '<html lang> does not say German');
    let state = await vplabState(page);
    assert.equal(state.language, 'de', 'the lab is not German in a German browser');
    assert.equal(state.labels['menu.file'], 'Datei', 'the File menu is not "Datei"');
    const germanFileWidth = state.rects['menu.file'][2];
    assert.equal(await page.evaluate(() => localStorage.getItem('vplab.language')), null,
      'the browser\'s language was stored as if chosen');

    // (b) View ▸ Language ▸ English.
    state = await openLanguageMenu(page, messages);
    await click(page, rectPoint(await cssRect(page, state, 'menu.language.en')));
    await waitForState(page, (s) => s.language === 'en', 'English after View ▸ Language ▸ English', messages);
    await waitFrames(page, 3);
    state = await vplabState(page);
    assert.equal(state.labels['menu.file'], 'File');
    assert.ok(state.rects['menu.file'][2] < germanFileWidth,
      `the menu bar still draws the German title: "File" is ${state.rects['menu.file'][2]} px wide, "Datei" was ${germanFileWidth}`);
    assert.equal(state.statusIsError, false, `choosing the language failed: ${state.status}`);
    assert.equal(await page.evaluate(() => localStorage.getItem('vplab.language')), 'en', 'the choice is not kept in localStorage');
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'en', '<html lang> did not follow the choice');

    // (c) The page's own texts follow the choice at once: a lost graphics context is said in English.
    await page.evaluate(() => {
      const x = document.querySelector('canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
      x.loseContext();
      setTimeout(() => x.restoreContext(), 1000);
    });
    await waitForState(page, (s) => s.graphicsLost, 'the page to notice the lost context', messages);
    assert.match(await messageShown(page) ?? '', /^The graphics context was lost \(CONTEXT_LOST_WEBGL: the browser took WebGL away\); restoring…$/,
      'the lost context is not said in the chosen English');
    await waitForState(page, (s) => !s.graphicsLost, 'the context to be restored', messages);
    await waitFrames(page, 3);

    // (b) After a reload the page stays English, though the browser is still German.
    const loadingEn = await loadHeld(page, messages, () => page.reload({ waitUntil: 'domcontentloaded' }));
    assert.equal(await page.evaluate(() => navigator.language), 'de-DE', 'the browser is no longer German');
    assert.equal(loadingEn.text, 'Loading vplab…', 'the page\'s loading text does not follow the kept choice');
    assert.equal(loadingEn.lang, 'en');
    state = await vplabState(page);
    assert.equal(state.language, 'en', 'the reload forgot View ▸ Language\'s choice');
    assert.equal(state.labels['menu.file'], 'File');

    assert.deepEqual(errorsOf(messages), [], 'the page logged errors');
    await context.close();
  });
});
