// Lessons in the page (docs/lecturers.md "Lessons"): a link opens a bundled lesson at a step, the keys a
// clicker sends advance it and the address follows the step; the embed form shows only the named
// views and the caption, as a figure beside a course page's own text. A link explains itself (issue 41):
// every part left out is named at once over the view, the valid lesson kept, the address as given.
import assert from 'node:assert/strict';
import { existsSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, test } from 'node:test';

import {
  afterInput, cssRect, decodePng, distinctColours, launchBrowser, openPage, rectPoint, startServer, tempDir, vplabState,
  waitForState, waitFrames, webDir,
} from './support.mjs';

const errorsOf = (messages) => messages.filter((m) => m.type === 'error' || m.type === 'warning');

describe('lessons in the browser', { concurrency: 1 }, () => {
  let server;
  let browser;
  let work;

  before(async () => {
    assert.ok(existsSync(path.join(webDir, 'index.html')), `${webDir}/index.html is missing: build the page with scripts/web.sh`);
    work = tempDir('web-lesson');
    server = await startServer(webDir);
    browser = await launchBrowser();
  });

  after(async () => {
    await browser?.close();
    await server?.close();
    work?.remove();
  });

  test('(p) a lesson link opens its step, the clicker\'s keys advance it, and the address follows', { timeout: 180_000 }, async () => {
    const context = await browser.createBrowserContext();
    const { page, console: messages } = await openPage(context, `${server.url}#lesson=02-view-orientation&step=3`);
    await waitForState(page, (s) => s.lesson && s.lesson.step === 3 && s.lesson.settled, 'the lesson at step 3', messages);
    let state = await vplabState(page);
    assert.equal(state.lesson.file, '02-view-orientation.en.json', 'a name without a language is the page\'s (English)');
    assert.match(state.hash, /lesson=02-view-orientation\.en&step=3/, 'the address names the lesson and the step');
    assert.ok(state.rects['lesson.caption'], 'the caption box is drawn');
    const cameraAt3 = state.camera;

    // → and Page Down (what clickers send) advance; the camera moves to the step's.
    await afterInput(page, () => page.keyboard.press('ArrowRight'));
    await waitForState(page, (s) => s.lesson.step === 4 && s.lesson.settled && /step=4/.test(s.hash), 'step 4 in the address', messages);
    await afterInput(page, () => page.keyboard.press('PageDown'));
    await waitForState(page, (s) => s.lesson.step === 5 && s.lesson.settled, 'step 5', messages);
    // ← goes back; the step's state is restored exactly.
    await afterInput(page, () => page.keyboard.press('ArrowLeft'));
    await afterInput(page, () => page.keyboard.press('ArrowLeft'));
    await waitForState(page, (s) => s.lesson.step === 3 && s.lesson.settled && /step=3/.test(s.hash), 'step 3 again', messages);
    state = await vplabState(page);
    assert.deepEqual(state.camera, cameraAt3, 'going back restores the step\'s camera as written');
    assert.equal(state.dirty, false, 'a lesson\'s step leaves nothing unsaved');

    // The address given while the page is open (a link in the course page) moves there.
    await afterInput(page, () => page.evaluate(() => window.vplab.setHash('#lesson=02-view-orientation.en&step=7')));
    await waitForState(page, (s) => s.lesson.step === 7 && s.lesson.settled, 'step 7 from the address', messages);

    // A German lesson by its name.
    await afterInput(page, () => page.evaluate(() => window.vplab.setHash('#lesson=05-clipping.de&step=1')));
    await waitForState(page, (s) => s.lesson && s.lesson.file === '05-clipping.de.json', 'the German clipping lesson', messages);
    state = await vplabState(page);
    assert.equal(state.lesson.title, 'Clipping in homogenen Koordinaten');
    writeFileSync(path.join(work.dir, 'lesson.png'), await page.screenshot({ type: 'png' }));
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });

  test('(q) the embed form shows only the named views and the caption', { timeout: 120_000 }, async () => {
    const context = await browser.createBrowserContext();
    const { page, console: messages } = await openPage(context, `${server.url}#embed=camera,world&lesson=01-synthetic-camera&step=2`,
      { viewport: { width: 900, height: 420, deviceScaleFactor: 1 } });
    await waitForState(page, (s) => s.lesson && s.lesson.step === 2 && s.lesson.settled, 'the embedded lesson at step 2', messages);
    await waitFrames(page, 3);
    const state = await vplabState(page);
    assert.deepEqual(state.embed, ['camera', 'world']);
    assert.match(state.hash, /^embed=camera,world&lesson=01-synthetic-camera\.en&step=2$/, 'the address keeps the embed form');
    for (const id of ['view.world', 'view.camera', 'lesson.caption']) assert.ok(state.rects[id], `"${id}" is drawn`);
    for (const id of ['menu.file', 'camera.vrp', 'tab.controls.Camera'])
      assert.ok(!state.rects[id], `the embed form draws no "${id}" (no menu, no panels)`);
    // The views sit side by side in their order, above the caption.
    const camera = state.rects['view.camera'];
    const world = state.rects['view.world'];
    const caption = state.rects['lesson.caption'];
    assert.ok(camera[0] < world[0], 'camera left of world, as the link orders them');
    assert.ok(camera[1] + camera[3] <= caption[1] + 1 && world[1] + world[3] <= caption[1] + 1, 'the views above the caption');
    const shot = await page.screenshot({ type: 'png' });
    writeFileSync(path.join(work.dir, 'embed.png'), shot);
    assert.ok(distinctColours(shot) >= 32, 'the embedded figure is drawn');
    // The keys still advance it.
    await afterInput(page, () => page.keyboard.press('Space'));
    await waitForState(page, (s) => s.lesson.step === 3 && /^embed=camera,world&lesson=/.test(s.hash), 'step 3, still embedded', messages);
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });

  // Issue 37's page reproduction: in lesson 02's free step the class types PRP = (0, 8, 0) (VUP ∥ N,
  // an invalid camera), then ←: the page stopped ("vplab stopped: invalid camera …") with the caption
  // frozen. Now ← cuts into step 8, and a reload's recovery gives back what was typed, in its step.
  test('(r) an invalid camera typed in a free step, then ←, then a reload: nothing stops, recovery is what was typed', { timeout: 180_000 }, async () => {
    const context = await browser.createBrowserContext();
    const url = `${server.url}#lesson=02-view-orientation.de&step=9`;
    let { page, console: messages } = await openPage(context, url);
    await waitForState(page, (s) => s.lesson && s.lesson.step === 9 && s.lesson.settled, 'the lesson at step 9', messages);
    let state = await vplabState(page);
    // Ctrl+click makes a drag field a text field (Dear ImGui); each of PRP's three typed, then Enter.
    const typeInto = async (fx, text) => {
      const at = rectPoint(await cssRect(page, state, 'camera.prp'), fx, 0.5);
      await page.keyboard.down('Control');
      await page.mouse.click(at.x, at.y);
      await page.keyboard.up('Control');
      await waitFrames(page, 2);
      await page.keyboard.press('End');
      for (let i = 0; i < 12; ++i) await page.keyboard.press('Backspace');
      await page.keyboard.type(text);
      await afterInput(page, () => page.keyboard.press('Enter'));
      state = await vplabState(page);
    };
    await typeInto(1 / 6, '0');
    await typeInto(3 / 6, '8');
    await typeInto(5 / 6, '0');
    await waitForState(page, (s) => s.camera.prp[0] === 0 && s.camera.prp[1] === 8 && s.camera.prp[2] === 0, 'PRP typed as (0, 8, 0)', messages);
    const typed = await vplabState(page);
    // The autosave (3 s after the last change) reaches localStorage.
    await page.waitForFunction(() => Object.keys(localStorage).some((k) => k.startsWith('vplab.recovery') && /edited_camera/.test(localStorage.getItem(k))),
      { timeout: 20_000, polling: 250 }).catch(() => assert.fail('no autosave with the typed camera within 20 s'));
    // ← moves into step 8: a cut, nothing caught, the page alive.
    await afterInput(page, () => page.keyboard.press('ArrowLeft'));
    await waitForState(page, (s) => s.lesson.step === 8 && s.lesson.settled && /step=8/.test(s.hash), 'step 8 after ←', messages);
    state = await vplabState(page);
    assert.equal(state.caughtErrors, 0, `an error was caught: ${state.lastCaughtError}`);
    assert.ok(!messages.some((m) => m.type === 'pageerror' || /vplab stopped|vplab wurde angehalten/.test(m.text)), 'the page stopped');
    // Back to the free step, type it again, and leave without saving: the next visit recovers it.
    await afterInput(page, () => page.keyboard.press('ArrowRight'));
    await waitForState(page, (s) => s.lesson.step === 9 && s.lesson.settled, 'step 9 again', messages);
    state = await vplabState(page);
    await typeInto(1 / 6, '0');
    await typeInto(3 / 6, '8');
    await typeInto(5 / 6, '0');
    const before = await page.evaluate(() => Object.keys(localStorage).map((k) => localStorage.getItem(k)).join(''));
    await page.waitForFunction((text) => Object.keys(localStorage).map((k) => localStorage.getItem(k)).join('') !== text,
      { timeout: 20_000, polling: 250 }, before).catch(() => assert.fail('no autosave of the typed camera within 20 s'));
    await page.close();
    ({ page, console: messages } = await openPage(context, url));
    await waitFrames(page, 5);
    state = await vplabState(page);
    assert.equal(state.recoveryOffered, true, 'the next visit does not offer the typed camera back');
    await afterInput(page, async () => page.mouse.click(...Object.values(rectPoint(await cssRect(page, state, 'recovery.recover')))));
    await waitForState(page, (s) => !s.recoveryOffered, 'the recovery dialog to close', messages);
    await waitFrames(page, 3);
    state = await vplabState(page);
    assert.deepEqual(state.camera.prp, typed.camera.prp, 'the recovered PRP is not the one typed');
    assert.equal(state.lesson?.step, 9, 'the recovered lesson is not at its step');
    assert.equal(state.caughtErrors, 0, `an error was caught: ${state.lastCaughtError}`);
    await context.close();
  });
  test('(y) lecture mode takes the browser\'s full screen (F11 is the browser\'s), and the browser\'s leaving it ends lecture mode', { timeout: 120_000 }, async () => {
    const context = await browser.createBrowserContext();
    const { page, console: messages } = await openPage(context, `${server.url}#lesson=01-synthetic-camera&step=2`);
    await waitForState(page, (s) => s.lesson && s.lesson.settled, 'the lesson', messages);
    const clickId = async (id) => {
      const p = rectPoint(await cssRect(page, await vplabState(page), id));
      await afterInput(page, () => page.mouse.click(p.x, p.y));
    };
    await clickId('tab.controls.Lecture');
    await waitForState(page, (s) => Boolean(s.rects['lecture.mode']), 'the Lecture tab', messages);
    await clickId('lecture.mode');
    await waitForState(page, (s) => s.lectureMode, 'lecture mode', messages);
    await page.waitForFunction(() => document.fullscreenElement === document.documentElement, { timeout: 10_000 });
    // The browser leaves full screen (its Esc, which the page never sees): lecture mode ends with it.
    await page.evaluate(() => document.exitFullscreen());
    await waitForState(page, (s) => !s.lectureMode, 'lecture mode to end with the full screen', messages);
    assert.equal((await vplabState(page)).lesson.step, 2, 'the lesson moved');
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });

  test('(s) a link with three bad parts on a phone names all three over the view, keeps its lesson and its address', { timeout: 180_000 }, async () => {
    const context = await browser.createBrowserContext();
    const given = 'lesson=05-clipping&step=abc&zoom=2&vrp=1,2';
    const { page, console: messages } = await openPage(context, `${server.url}#${given}`,
      { viewport: { width: 390, height: 844, deviceScaleFactor: 2, isMobile: true, hasTouch: true } });
    await waitForState(page, (s) => s.lesson && s.lesson.settled && s.linkProblems.length === 3, 'the lesson and three parts left out', messages);
    let state = await vplabState(page);
    assert.equal(state.lesson.file, '05-clipping.en.json', 'the valid lesson is opened');
    assert.equal(state.lesson.step, 1, 'the bad step is ignored: the lesson opens at its first');
    assert.deepEqual(state.linkProblems.map((p) => p.key), ['step', 'zoom', 'vrp'], 'every bad part, all at once');
    for (const part of ['step="abc"', 'zoom="2"', 'vrp="1,2"']) assert.ok(state.status.includes(part), `${part} in: ${state.status}`);
    assert.equal(await page.evaluate(() => location.hash), `#${given}`, 'the address stays as given');
    // Seen on the phone without opening a panel: the note's amber text over the one view shown.
    const view = ['view.world', 'view.camera', 'view.npc'].find((id) => state.rects[id]);
    assert.ok(view, 'a view is shown');
    const [x, y, w] = state.rects[view].map(Math.round);
    const shot = decodePng(await page.screenshot({ type: 'png' }));
    const scale = shot.width / state.canvas[0];
    let amber = 0;
    for (let py = Math.round(y * scale); py < Math.round((y + 120) * scale); ++py)
      for (let px = Math.round(x * scale); px < Math.round((x + w) * scale); ++px) {
        const i = (py * shot.width + px) * 4;
        amber += shot.data[i] > 200 && shot.data[i + 1] > 150 && shot.data[i + 1] < 220 && shot.data[i + 2] < 120;
      }
    assert.ok(amber > 300, `the note is drawn over the view (${amber} amber pixels)`);

    // The student moves on: the address follows again and the note goes.
    await afterInput(page, () => page.keyboard.press('ArrowRight'));
    await waitForState(page, (s) => s.lesson.step === 2 && /step=2/.test(s.hash) && s.linkProblems.length === 0, 'step 2, the note gone', messages);
    assert.match(await page.evaluate(() => location.hash), /^#lesson=05-clipping\.en&step=2$/);
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });
});
