// The monkey test of the page (issue 37: "the lecture never fails"): a seeded random user plays the
// page as Chromium's input gives it (the DevTools protocol's mouse, wheel and keyboard): clicks and
// double-clicks anywhere and on every widget the page recorded, drags, number fields typed into with
// invalid and extreme values, the clicker's and the shortcuts' keys, viewport changes from a phone's
// to a projector's, every bundled lesson at random steps and the bundled scenes by their links. It
// fails when the page stops (an uncaught exception, "vplab stopped"), when a frame ends in an error
// the viewer caught (state().caughtErrors), or when a frame takes over a second outside a scene's
// loading; every run prints its seed, a failure how to replay it:
//   VPLAB_MONKEY_SEED=N VPLAB_MONKEY_EVENTS=M node --test tests/web/monkey.test.mjs
// The desktop window's monkey (tests/app/window/monkey_test.cpp) gives 20 000 events under ASan +
// UBSan; SwiftShader draws the page's frames on the same two cores, so the page gets fewer.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { cssRect, openPage, servedPageAndBrowser, vplabState } from './support.mjs';

const seed = Number(process.env.VPLAB_MONKEY_SEED ?? 41);
const events = Number(process.env.VPLAB_MONKEY_EVENTS ?? 600);

/** mulberry32: a small seeded generator, so that a seed replays the same events. */
function generator(s) {
  let a = s >>> 0;
  return () => {
    a = (a + 0x6D2B79F5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const typed = ['0', '1', '-1', '8', '7.5', '0.5', '-3/5', '0,5', '1e308', '-1e308', '1e-320', 'nan', 'inf', 'abc', '',
  '-0', '99999999999', '12e', '--1', '1..2'];
const keys = ['ArrowRight', 'ArrowLeft', 'Space', 'PageDown', 'PageUp', 'Home', 'End', 'Enter', 'Escape', 'F1', 'KeyB',
  'KeyC', 'KeyP', 'KeyR', 'Digit1', 'Digit2', 'Digit3', 'Digit5', 'Digit9', 'Tab', 'Backspace', 'Delete'];
const lessons = ['01-synthetic-camera', '02-view-orientation', '03-view-mapping', '04-projections', '05-clipping',
  '06-device-mapping', '07-clip-planes'];
// Every bundled scene but the 1M-triangle one, whose arrival large.test.mjs measures on its own.
const scenes = ['default', 'perspective', 'parallel', 'oblique-cabinet', 'oblique-cavalier', 'behind-the-eye', 'clip-planes',
  'clipping-wc-vs-npc', 'depth-nonlinearity', 'mesh-obj', 'off-centre-window', 'seed-cube-tetrahedron', 'sphere-cylinder',
  'vanishing-1', 'vanishing-2', 'vanishing-3'];
const viewports = [[1280, 720], [1024, 768], [1920, 1080], [390, 844], [844, 390], [800, 600]];

const served = servedPageAndBrowser();

// Found by the monkey: a page exactly the screen's size (a phone's, here headless Chromium's 800 × 600
// screen) made Emscripten's GLFW ask for full screen without a gesture, an uncaught rejection.
test('a page the size of the screen does not ask for full screen', { timeout: 120_000 }, async () => {
  const { page, console: messages } = await openPage(served.browser, `${served.server.url}#scene=default`);
  const screen = await page.evaluate(() => [screen.width, screen.height]);
  const before = (await vplabState(page)).frames;
  await page.setViewport({ width: screen[0], height: screen[1], deviceScaleFactor: 1 });
  await page.waitForFunction((n) => window.vplab.state().frames > n + 2, { timeout: 30_000, polling: 50 }, before);
  const state = await vplabState(page);
  assert.deepEqual(state.canvas, screen, 'the canvas fills the page');
  assert.deepEqual(messages.filter((m) => m.type === 'pageerror'), [], 'the page threw');
  await page.close();
});

test(`the page survives a random user (seed ${seed}, ${events} events)`, { timeout: 1_200_000 }, async () => {
  const random = generator(seed);
  const pick = (list) => list[Math.floor(random() * list.length)];
  const { page, console: messages } = await openPage(served.browser, `${served.server.url}#scene=default`);
  // The frames' intervals (requestAnimationFrame): the longest outside a scene's loading is the test's.
  await page.evaluate(() => {
    window.__monkey = { last: performance.now(), longest: 0, paused: false };
    const tick = (now) => {
      const m = window.__monkey;
      if (!m.paused) m.longest = Math.max(m.longest, now - m.last);
      m.last = now;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  let done = 0;
  let last = 'none';
  let longest = 0;
  const replay = () => `after ${done} events, the last: ${last}; replay: VPLAB_MONKEY_SEED=${seed} VPLAB_MONKEY_EVENTS=${events} node --test tests/web/monkey.test.mjs`;
  console.log(`monkey (page): seed ${seed}, ${events} events`);
  while (done < events) {
    const state = await vplabState(page);
    const stopped = messages.find((m) => m.type === 'pageerror' || /vplab stopped|vplab wurde angehalten/.test(m.text));
    assert.equal(stopped, undefined, `the page stopped: ${stopped?.text} (${replay()})`);
    assert.equal(state.caughtErrors, 0, `a frame caught an error: ${state.lastCaughtError} (${replay()})`);
    // A frame over a second outside a scene's loading (the loader's worker and the run in steps take their time).
    const busy = state.loading || state.runProgress !== undefined;
    const frame = await page.evaluate((busy) => {
      const m = window.__monkey;
      const longestSoFar = m.longest;
      m.longest = 0;
      m.paused = busy;
      return longestSoFar;
    }, busy);
    longest = Math.max(longest, frame);
    assert.ok(frame <= 1000, `a frame took ${frame.toFixed(0)} ms (${replay()})`);

    const ids = Object.keys(state.rects ?? {}).filter((id) => id !== 'menu.quit');
    const [w, h] = [page.viewport().width, page.viewport().height];
    const somewhere = async (widget) => {
      if (widget && ids.length) {
        const r = await cssRect(page, state, pick(ids));
        return { x: r.x + r.w * (0.1 + 0.8 * random()), y: r.y + r.h * (0.2 + 0.6 * random()) };
      }
      return { x: random() * w, y: random() * h };
    };
    const choice = random() * 100;
    if (choice < 24) {
      const p = await somewhere(random() < 0.75);
      const count = random() < 0.12 ? 2 : 1;
      await page.mouse.click(p.x, p.y, { count, button: random() < 0.1 ? 'right' : 'left' });
      done += 1 + 2 * count;
      last = `click ×${count} at ${p.x.toFixed(0)}, ${p.y.toFixed(0)}`;
    } else if (choice < 40) {
      const p = await somewhere(true);
      await page.keyboard.down('Control');
      await page.mouse.click(p.x, p.y);
      await page.keyboard.up('Control');
      const text = pick(typed);
      await page.keyboard.type(text);
      await page.keyboard.press(pick(['Enter', 'Tab', 'Escape']));
      done += 5 + text.length;
      last = `typed "${text}" at ${p.x.toFixed(0)}, ${p.y.toFixed(0)}`;
    } else if (choice < 54) {
      const p = await somewhere(random() < 0.6);
      await page.mouse.move(p.x, p.y);
      await page.mouse.down();
      const steps = 2 + Math.floor(random() * 6);
      for (let i = 0; i < steps; ++i) {
        p.x += (random() - 0.5) * 120;
        p.y += (random() - 0.5) * 120;
        await page.mouse.move(p.x, p.y);
      }
      await page.mouse.up();
      done += 3 + steps;
      last = `drag to ${p.x.toFixed(0)}, ${p.y.toFixed(0)}`;
    } else if (choice < 62) {
      const p = await somewhere(false);
      await page.mouse.move(p.x, p.y);
      await page.mouse.wheel({ deltaY: (random() - 0.5) * 600 });
      done += 2;
      last = `wheel at ${p.x.toFixed(0)}, ${p.y.toFixed(0)}`;
    } else if (choice < 86) {
      const key = pick(keys);
      await page.keyboard.press(key);
      done += 2;
      last = `key ${key}`;
    } else if (choice < 90) {
      const [vw, vh] = pick(viewports);
      await page.setViewport({ width: vw, height: vh, deviceScaleFactor: 1 });
      done += 1;
      last = `viewport ${vw} × ${vh}`;
    } else if (choice < 96) {
      const lesson = `${pick(lessons)}${pick(['', '.de', '.en'])}`;
      const step = 1 + Math.floor(random() * 12);
      await page.evaluate((h) => window.vplab.setHash(h), `#lesson=${lesson}&step=${step}`);
      done += 1;
      last = `lesson ${lesson} step ${step}`;
    } else {
      const scene = pick(scenes);
      await page.evaluate((h) => window.vplab.setHash(h), `#scene=${scene}`);
      done += 1;
      last = `scene ${scene}`;
    }
    // Let the page take the events in (one button or key transition a frame) before the next action.
    await page.waitForFunction((n) => window.vplab.state().frames > n + 1, { timeout: 30_000, polling: 20 }, state.frames)
      .catch(() => {}); // input that changes nothing may draw no frame
  }
  const state = await vplabState(page);
  assert.equal(state.caughtErrors, 0, `a frame caught an error: ${state.lastCaughtError} (${replay()})`);
  console.log(`monkey (page): ${done} events in ${state.frames} frames, the longest frame outside loading ${longest.toFixed(0)} ms`);
});
