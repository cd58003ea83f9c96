// A large scene in a student's page (issue 24 item 3; docs/measured.md "Large scenes in the page"). The
// bundled large-mesh scene (a sphere of 524 288 polygons, about a million triangles) is read and tessellated
// in the page's loader worker (loader-worker.js): the page goes on drawing frames meanwhile, shows the
// desktop's Loading window with its progress bar, and Cancel keeps the open scene. The test holds the
// worker's module at the server until the test lets it go, so the load is under way for as long as
// the test needs, on any machine. Then the scene is opened for real, and the longest frame until its
// views are complete is measured and reported (the frames' intervals, requestAnimationFrame), beside
// the longest frame of the default scene's views drawn whole in the same browser.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import {
  click, cssRect, launchBrowser, openPage, rectPoint, startServer, unlessPageFails, vplabState, waitFrames, webDir,
} from './support.mjs';

/** Polls the page's state until `predicate` holds (every 50 ms, up to `timeout` ms). */
async function waitForState(page, predicate, what, timeout = 30_000) {
  const begin = Date.now();
  for (;;) {
    const state = await vplabState(page);
    if (predicate(state)) return state;
    if (Date.now() - begin > timeout) throw new Error(`${what}: not within ${timeout} ms (status "${state.status}")`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}

/** What the frame of `frame` ({start, duration}) spent its time on: its parts, longest first. */
function partsOf(frame, parts) {
  const within = parts.filter((p) => p.start >= frame.start - 0.5 && p.start + p.duration <= frame.start + frame.duration + 0.5);
  const sums = new Map();
  for (const p of within) sums.set(p.part, (sums.get(p.part) ?? 0) + p.duration);
  return [...sums].sort((a, b) => b[1] - a[1]).map(([part, ms]) => `${part} ${ms.toFixed(0)}`).join(', ');
}

/**
 * Runs `action` and returns the page's frame intervals meanwhile (requestAnimationFrame, ms) and each
 * frame's own work (the page's "vplab frame" performance measures, ms; index.html frameWorked), with
 * each frame's start (`frames`), and the frames' parts ("vplab part: <name>" measures; partWorked).
 */
async function framesWhile(page, action) {
  await page.evaluate(() => {
    window.__frames = [];
    window.__work = [];
    window.__stopFrames = false;
    window.__parts = [];
    window.__take = (entries) => {
      for (const e of entries) {
        if (e.name === 'vplab frame') window.__work.push({ start: e.startTime, duration: e.duration });
        else if (e.name.startsWith('vplab part: ')) window.__parts.push({ part: e.name.slice(12), start: e.startTime, duration: e.duration });
      }
    };
    window.__observer = new PerformanceObserver((list) => window.__take(list.getEntries()));
    window.__observer.observe({ entryTypes: ['measure'] });
    let last = performance.now();
    const tick = (now) => {
      window.__frames.push(now - last);
      last = now;
      if (!window.__stopFrames) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const begin = Date.now();
  await action();
  const { intervals, work, parts } = await page.evaluate(() => {
    window.__stopFrames = true;
    window.__take(window.__observer.takeRecords());
    window.__observer.disconnect();
    return { intervals: window.__frames, work: window.__work, parts: window.__parts };
  });
  return { intervals, work: work.map((w) => w.duration), frames: work, parts, seconds: (Date.now() - begin) / 1000 };
}

test('a large scene loads in the worker while the page answers; Cancel keeps the open scene', { timeout: 300_000 }, async (t) => {
  let release;
  const held = new Promise((resolve) => { release = resolve; });
  const server = await startServer(webDir, { hold: (p) => (p.endsWith('/vplab-loader.wasm') ? held : null) });
  const browser = await launchBrowser();
  try {
    const { page, console: messages } = await openPage(browser, `${server.url}index.html`);
    await waitFrames(page);
    const before = await vplabState(page);
    assert.match(before.scene, /default\.json$|^$/, 'the page did not open the default scene');

    // The link asks for the large scene: the worker cannot answer while its module is held.
    await page.evaluate(() => window.vplab.setHash('#scene=large-mesh'));
    const loading = await unlessPageFails(waitForState(page, (s) => s.loading, 'the page never said it was loading'), messages,
                                          'opening the large scene');
    const framesThen = loading.frames;
    await new Promise((resolve) => setTimeout(resolve, 1000));
    const later = await vplabState(page);
    assert.ok(later.loading, 'the load ended while the worker could not answer');
    assert.ok(later.frames >= framesThen + 5, `the page drew ${later.frames - framesThen} frames in a second of loading: it does not answer`);
    assert.ok(later.rects['load.cancel'], 'no Loading window with Cancel');

    // Cancel: the open scene stays, and the worker's answer, when it comes, is dropped.
    await click(page, rectPoint(await cssRect(page, later, 'load.cancel')));
    const cancelled = await waitForState(page, (s) => !s.loading, 'Cancel did not end the load');
    assert.equal(cancelled.scene, before.scene, 'Cancel did not keep the open scene');
    assert.match(cancelled.status, /cancelled/);
    release();
    await new Promise((resolve) => setTimeout(resolve, 3000));
    assert.equal((await vplabState(page)).scene, before.scene, 'the cancelled load landed after all');

    // For comparison, in the same browser: the frames of the default scene while P switches its
    // projection ten times (each frame draws the three views whole). On SwiftShader (the CPU draws
    // what a GPU would) these pass 100 ms as well.
    // (A page of its own: P changes the scene, and the test's page would then ask about it.)
    const { page: other } = await openPage(browser, `${server.url}index.html`);
    await waitFrames(other);
    const baseline = await framesWhile(other, async () => {
      for (let i = 0; i < 10; ++i) {
        await other.keyboard.press('p');
        await new Promise((resolve) => setTimeout(resolve, 200));
      }
    });
    await other.close();
    // Now for real, every frame's interval recorded from the link until the run and the three
    // views of the sphere are complete.
    let opened;
    const frames = await framesWhile(page, async () => {
      await page.evaluate(() => window.vplab.setHash('#scene=large-mesh'));
      opened = await unlessPageFails(
        waitForState(page, (s) => /large-mesh\.json$/.test(s.scene) && !s.loading, 'the large scene never opened', 120_000),
        messages, 'opening the large scene');
      await unlessPageFails(waitForState(page, (s) => s.run.polygons === 524288 && s.viewsBusy === 0,
                                         'the views of the sphere were never complete', 180_000), messages, 'drawing the large scene');
    });
    assert.ok(!opened.statusIsError, `the page said: ${opened.status}`);
    // How long the frames are depends on the machine; that the page answers while it loads was
    // asserted above, with the worker held. Here it is measured and reported, and a frame that held
    // the page for half a second (the whole scene read or drawn at once: 1.75 s before the slices)
    // fails, or on a machine so busy that the default scene's frames pass 250 ms, one over twice
    // their longest. And the page's own work in a frame (the wasm's and the WebGL calls it makes,
    // not SwiftShader's drawing after them) stays within 50 ms (issue 42): the scene's arrival, the
    // run's steps, a view's new list and its slices each in frames of their own, no GL call that
    // waits for the GPU (38-42 ms on the 2 cores this was written on, the scene's arrival and a
    // view's first list; 164-170 ms before). The report names each long frame's parts.
    const longest = Math.max(...frames.intervals);
    const sorted = [...frames.work].sort((a, b) => a - b);
    const longestWork = sorted[sorted.length - 1];
    const report = `opening large-mesh until its views are complete: ${frames.intervals.length} frames in ` +
                   `${(frames.seconds).toFixed(1)} s, the longest ${longest.toFixed(0)} ms, ` +
                   `${frames.intervals.filter((d) => d > 100).length} over 100 ms; the page's own work in a frame ` +
                   `(${frames.work.length} measured): median ${sorted[sorted.length >> 1].toFixed(1)} ms, the longest ` +
                   `${longestWork.toFixed(1)} ms, the five longest ${sorted.slice(-5).map((d) => d.toFixed(0)).join(', ')} ms; ` +
                   `pressing P in the default scene: the longest ${Math.max(...baseline.intervals).toFixed(0)} ms`;
    const worst = [...frames.frames].sort((a, b) => b.duration - a.duration).slice(0, 5);
    const where = worst.map((f) => `${f.duration.toFixed(0)} ms: ${partsOf(f, frames.parts) || 'no part measured'}`).join('; ');
    t.diagnostic(`the five longest frames' parts (ms): ${where}`);
    console.log(`the five longest frames' parts (ms): ${where}`);
    t.diagnostic(report);
    console.log(report);
    assert.ok(longest < Math.max(500, 2 * Math.max(...baseline.intervals)), report);
    assert.ok(longestWork <= 50, `a frame of the page's own work took ${longestWork.toFixed(1)} ms (over 50): ${where}`);
    // The mesh the worker built is the sphere with n = 1024: the pipeline's run of it.
    assert.equal((await vplabState(page)).run.vertices, 523266);
  } finally {
    release();
    await browser.close();
    await server.close();
  }
});
