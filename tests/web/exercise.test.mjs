// An exercise practised in the page (issue 40): a link opens it with its Tasks beside the views; a
// student fills every field from the keyboard (a click into the first field, then text and Tab),
// presses Ctrl+Enter and gets full points; a divide-first answer is named and its polygon drawn where
// the desktop `vplab render --answer` draws it; Hand in downloads the answer.json that `vplab grade
// numbers` and `vplab grade batch` grade to the same points, and that opens again on its own in a
// fresh browser (File ▸ Open exercise…); what was typed survives a reload; a phone reaches the Tasks.
//
// Oracles: the desktop `vplab exercise`'s solution.json (the key), and the divide-first answer worked
// out here, in a few lines of Sutherland–Hodgman on the divided polygon (Hill 7.4), never by the page.
import assert from 'node:assert/strict';
import { copyFileSync, existsSync, mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, test } from 'node:test';

import {
  afterInput, catchDownloads, cssRect, decodePng, fingerOn, launchBrowser, openPage, rectPoint, runVplab, startServer, tempDir,
  vplabState, waitForState, waitFrames, webDir,
} from './support.mjs';

const errorsOf = (messages) => messages.filter((m) => m.type === 'error' || m.type === 'warning' || m.type === 'pageerror');

// ---------------------------------------------------------------- the answers, worked out here

/** A number as a student writes it: 6 decimals, the German decimal comma in every other one. */
const onPaper = (x, i) => {
  const t = (Math.abs(x) < 5e-7 ? 0 : x).toFixed(6);
  return i % 2 ? t.replace('.', ',') : t;
};

/** The value of `answer` at a JSON pointer. */
const at = (answer, pointer) => pointer.split('/').slice(1).reduce((v, key) => v[key], answer);

/** What is typed, field after field (the fields in the sheet's order, from the page's state). */
function keystrokes(fields, answer) {
  const out = [];
  for (const f of fields) {
    const v = at(answer, f.path);
    if (f.kind === 'number') out.push(onPaper(v, out.length));
    else if (f.kind === 'outcode') out.push(v.toString(2).padStart(6, '0'));
    else if (f.kind === 'vector') v.forEach((x) => out.push(onPaper(x, out.length)));
    else {
      if (f.kind === 'polygon') out.push(String(v.length));
      v.forEach((row) => row.forEach((x) => out.push(onPaper(x, out.length))));
    }
  }
  return out;
}

/**
 * The divide-first answer of a clipping sheet: the polygon in homogeneous NPC divided by w first, then
 * clipped plane by plane (left x ≥ 0, right x ≤ w, bottom, top, back z ≥ 0, front z ≤ w; w = 1 now),
 * each new vertex at t = BC(in) / (BC(in) − BC(out)) from the inside end; DC = (W x, H (1 − y), z).
 */
function divideFirstAnswer(npcH, dcFromNpc) {
  const boundary = (p, k) => [p[0], p[3] - p[0], p[1], p[3] - p[1], p[2], p[3] - p[2]][k];
  let polygon = npcH.map(([x, y, z, w]) => [x / w, y / w, z / w, 1]);
  const passes = [];
  for (let k = 0; k < 6; ++k) {
    const out = [];
    for (let i = 0; i < polygon.length; ++i) {
      const s = polygon[(i + polygon.length - 1) % polygon.length], e = polygon[i];
      const bs = boundary(s, k), be = boundary(e, k);
      const cut = (a, b, ba, bb) => { const t = ba / (ba - bb); return a.map((v, j) => v + t * (b[j] - v)); };
      if (be >= 0) {
        if (bs < 0) out.push(cut(e, s, be, bs));
        out.push(e);
      } else if (bs >= 0) {
        out.push(cut(s, e, bs, be));
      }
    }
    polygon = out;
    passes.push({ polygon });
  }
  const [W, , , ] = dcFromNpc[0];
  const H = dcFromNpc[1][3];
  return {
    objects: [{ polygons: [{ clip_steps: passes, clipped_dc: polygon.map(([x, y, z]) => [W * x, H * (1 - y), z]) }] }],
    matrices: { dc_from_npc: dcFromNpc },
  };
}

// ---------------------------------------------------------------- driving the page

/** Scrolls the Tasks (wheel over the inspector) until `id` is on the canvas, then clicks it (at `fx`). */
async function clickField(page, id, fx = 0.5) {
  for (let i = 0; i < 40; ++i) {
    const state = await vplabState(page);
    const r = state.rects[id];
    if (r && r[1] >= 40 && r[1] + r[3] <= state.canvas[1] - 10) {
      const at = rectPoint(await cssRect(page, state, id), fx, 0.5);
      await afterInput(page, () => page.mouse.click(at.x, at.y));
      return;
    }
    const panel = await cssRect(page, state, 'tab.inspect.Tasks');
    await page.mouse.move(panel.x + panel.w / 2, panel.y + panel.h * 4);
    await afterInput(page, () => page.mouse.wheel({ deltaY: r && r[1] < 40 ? -120 : 120 }));
  }
  assert.fail(`the field ${id} never came into sight`);
}

/** The rect id of an item's first field (a polygon's: its vertex count, whose rect holds − and + too). */
function firstCellId(f) {
  const suffix = { number: '', outcode: '', vector: '/0', matrix: '/0/0', polygon: '/count' }[f.kind];
  return `task${f.path}${suffix}`;
}

/** Clicks into the sheet's first field, types `texts` with Tab after each, then Ctrl+Enter. */
async function typeAndCheck(page, texts, messages) {
  const first = (await vplabState(page)).exercise.fields[0];
  await clickField(page, firstCellId(first), first.kind === 'polygon' ? 0.2 : 0.5);
  for (let i = 0; i < texts.length; ++i) {
    await page.keyboard.type(texts[i]);
    if (i + 1 < texts.length) await page.keyboard.press('Tab');
  }
  await page.keyboard.down('Control');
  await page.keyboard.press('Enter');
  await page.keyboard.up('Control');
  await waitForState(page, (s) => s.exercise && s.exercise.check && s.exercise.check.edits === s.exercise.edits,
    'Check of the fields as typed', messages, 60_000);
  return vplabState(page);
}

/** The student's colour in the dark theme (255 89 217) and its antialiased edges; not VUP's violet. */
const studentColoured = (r, g, b) => r > 150 && b > 0.6 * r && b < 0.95 * r && g < 0.42 * r;

function studentMask(png, x0, y0, w, h) {
  const mask = new Uint8Array(w * h);
  for (let y = 0; y < h; ++y)
    for (let x = 0; x < w; ++x) {
      const i = ((y0 + y) * png.width + (x0 + x)) * 4;
      mask[y * w + x] = studentColoured(png.data[i], png.data[i + 1], png.data[i + 2]) ? 1 : 0;
    }
  return mask;
}

describe('an exercise in the browser', { concurrency: 1 }, () => {
  let server;
  let browser;
  let work;

  before(async () => {
    assert.ok(existsSync(path.join(webDir, 'index.html')), `${webDir}/index.html is missing: build the page with scripts/web.sh`);
    work = tempDir('web-exercise');
    server = await startServer(webDir);
    browser = await launchBrowser();
  });

  after(async () => {
    await browser?.close();
    await server?.close();
    work?.remove();
  });

  test('(a) every field of #exercise=pipeline&seed=4&id=100 typed from the key, Ctrl+Enter: full points', { timeout: 300_000 }, async () => {
    const dir = path.join(work.dir, 'pipeline');
    await runVplab(['exercise', '--seed', '4', '--topic', 'pipeline', '--student-id', '100', '--out', dir]);
    const key = JSON.parse(readFileSync(path.join(dir, 'solution.json'), 'utf8'));
    const context = await browser.createBrowserContext();
    const { page, console: messages } = await openPage(context, `${server.url}#exercise=pipeline&seed=4&id=100`);
    await waitForState(page, (s) => s.exercise && s.rects['tab.inspect.Tasks'], 'the exercise and its Tasks', messages);
    let state = await vplabState(page);
    assert.equal(state.exercise.key, 'pipeline-4-perspective-100');
    assert.match(state.hash, /exercise=pipeline&seed=4&id=100/, 'the address names the exercise');
    const texts = keystrokes(state.exercise.fields, key);
    assert.ok(texts.length > 60, 'the pipeline sheet has its matrices, vectors and outcode');
    const started = Date.now();
    state = await typeAndCheck(page, texts, messages);
    const typed = state.exercise.fields.flatMap((f) => f.texts);
    assert.deepEqual(typed, texts, 'every field holds what was typed into it, in the sheet\'s order');
    const check = state.exercise.check;
    assert.equal(check.points, check.maxPoints, `full points: ${JSON.stringify(check.diagnosis)} ${JSON.stringify(check.items.filter((i) => !i.passed))}`);
    assert.ok(check.passed);
    console.log(`# the pipeline sheet: ${texts.length} fields typed and checked in ${Date.now() - started} ms; Check took ${(check.seconds * 1000).toFixed(1)} ms in the page`);
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });

  test('(b) a divide-first answer to #exercise=clipping&seed=3 is named, drawn where the desktop draws it, and handed in', { timeout: 300_000 }, async () => {
    const dir = path.join(work.dir, 'clipping');
    await runVplab(['exercise', '--seed', '3', '--topic', 'clipping', '--out', dir]);
    const dump = JSON.parse((await runVplab(['dump', '--scene', path.join(dir, 'scene.json')])).stdout);
    const key = JSON.parse(readFileSync(path.join(dir, 'solution.json'), 'utf8'));
    const answer = divideFirstAnswer(dump.objects[0].polygons[0].npc_h, key.matrices.dc_from_npc);
    const context = await browser.createBrowserContext();
    const downloads = await catchDownloads(browser, context);
    const { page, console: messages } = await openPage(context, `${server.url}#exercise=clipping&seed=3`);
    await waitForState(page, (s) => s.exercise, 'the exercise', messages);
    let state = await vplabState(page);
    state = await typeAndCheck(page, keystrokes(state.exercise.fields, answer), messages);
    assert.equal(state.exercise.check.mistake, 'divide-first', JSON.stringify(state.exercise.check.diagnosis));
    assert.ok(state.exercise.check.points < state.exercise.check.maxPoints);

    // The NPC view shows their last pass dashed: compared with the desktop's render of the handed-in answer.
    // Hand in from the File menu (the Tasks' own button is below the fields).
    let rect = await cssRect(page, state, 'menu.file');
    await afterInput(page, () => page.mouse.click(rect.x + rect.w / 2, rect.y + rect.h / 2));
    state = await vplabState(page);
    rect = await cssRect(page, state, 'menu.handIn');
    await afterInput(page, () => page.mouse.click(rect.x + rect.w / 2, rect.y + rect.h / 2));
    const { file } = await downloads.next(30_000);
    const handedIn = JSON.parse(readFileSync(file, 'utf8'));
    assert.ok(handedIn.objects[0].polygons[0].clip_steps[5].polygon.length >= 3, 'the answer file holds the passes');
    const graded = JSON.parse((await runVplab(['grade', 'numbers', '--student', file, '--assignment', path.join(dir, 'assignment.json'), '--json'])
      .catch((e) => ({ stdout: e.stdout }))).stdout);
    assert.equal(graded.points, state.exercise.check.points, 'vplab grade numbers gives the handed-in answer the same points');
    // A class's handed-in answers, one per student, as `vplab grade batch` reads them.
    const answers = path.join(work.dir, 'answers');
    mkdirSync(answers, { recursive: true });
    copyFileSync(file, path.join(answers, 's1.json'));
    await runVplab(['grade', 'batch', '--assignment', path.join(dir, 'assignment.json'), '--answers', answers,
      '--out', path.join(work.dir, 'grades')]);
    const batch = JSON.parse(readFileSync(path.join(work.dir, 'grades', 'results.json'), 'utf8'));
    assert.equal(batch.students.length, 1);
    assert.equal(batch.students[0].score, state.exercise.check.points, 'vplab grade batch gives the handed-in answer the same points');

    await waitFrames(page, 5);
    state = await vplabState(page);
    const [x, y, w, h] = state.rects['view.npc'].map(Math.round);
    const shot = decodePng(await page.screenshot({ type: 'png' }));
    const expectedFile = path.join(work.dir, 'npc-divide-first.png');
    await runVplab(['render', '--view', 'npc', '--style', 'shaded', '--exercise', dir, '--answer', file, '--size', `${w}x${h}`,
      '--out', expectedFile]);
    const expected = decodePng(readFileSync(expectedFile));
    const shown = studentMask(shot, x, y, w, h), rendered = studentMask(expected, 0, 0, w, h);
    let both = 0, inShown = 0, inRendered = 0;
    for (let i = 0; i < shown.length; ++i) { both += shown[i] & rendered[i]; inShown += shown[i]; inRendered += rendered[i]; }
    // Every pixel of their colour the page shows is one the render has (5 %: antialiasing and the
    // labels), and most of the render's are shown: the page draws the lab's step-through over parts.
    assert.ok(inRendered > 150, `the rendered outline is visible (${inRendered} px)`);
    assert.ok(both >= 0.95 * inShown, `shown ${inShown}, rendered ${inRendered}, both ${both}`);
    assert.ok(both > 0.5 * inRendered, `shown ${inShown}, rendered ${inRendered}, both ${both}`);
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    const typed = state.exercise.fields.flatMap((f) => f.texts);
    const { points, mistake } = state.exercise.check;
    await context.close();

    // The handed-in file opens on its own in a fresh browser (no answer kept there): File ▸ Open exercise….
    const fresh = await browser.createBrowserContext();
    const opened = await openPage(fresh, server.url);
    await waitForState(opened.page, (s) => s.rects['menu.file'], 'the page', opened.console);
    state = await vplabState(opened.page);
    rect = await cssRect(opened.page, state, 'menu.file');
    await afterInput(opened.page, () => opened.page.mouse.click(rect.x + rect.w / 2, rect.y + rect.h / 2));
    state = await vplabState(opened.page);
    rect = await cssRect(opened.page, state, 'menu.openExercise');
    await afterInput(opened.page, () => opened.page.mouse.click(rect.x + rect.w / 2, rect.y + rect.h / 2));
    await (await opened.page.$('#vplab-file')).uploadFile(file);
    await waitForState(opened.page, (s) => s.exercise && s.exercise.key === 'clipping-3-perspective', 'the exercise the file names',
      opened.console);
    state = await vplabState(opened.page);
    assert.deepEqual(state.exercise.fields.flatMap((f) => f.texts), typed, 'the fields hold the handed-in values');
    await opened.page.keyboard.down('Control');
    await opened.page.keyboard.press('Enter');
    await opened.page.keyboard.up('Control');
    await waitForState(opened.page, (s) => s.exercise.check, 'Check of the opened answer', opened.console, 60_000);
    state = await vplabState(opened.page);
    assert.equal(state.exercise.check.points, points);
    assert.equal(state.exercise.check.mistake, mistake);
    assert.deepEqual(errorsOf(opened.console), [], 'the page logged errors or warnings');
    downloads.remove();
    await fresh.close();
  });

  test('(c) what was typed survives a reload; on a phone the switcher reaches the Tasks and checks', { timeout: 300_000 }, async () => {
    const context = await browser.createBrowserContext();
    let { page, console: messages } = await openPage(context, `${server.url}#exercise=mapping&seed=2`,
      { viewport: { width: 390, height: 844, deviceScaleFactor: 2, isMobile: true, hasTouch: true } });
    await waitForState(page, (s) => s.exercise && s.compact, 'the exercise in the compact layout', messages);
    await waitFrames(page, 5);  // laid out for a finger (a phone starts so)
    let state = await vplabState(page);
    assert.equal(state.touch, true, 'a phone starts with a finger\'s targets');
    assert.ok(state.rects['switch.tasks'], 'the switcher has the Tasks');
    // A phone is touched, not clicked (a mouse would give it the mouse's smaller targets).
    const finger = await fingerOn(page);
    await finger.tap(rectPoint(await cssRect(page, state, 'switch.tasks')));
    state = await vplabState(page);
    assert.equal(state.compactPanel, 'inspect');
    const first = state.exercise.fields[0];
    await waitFrames(page, 5);  // the Tasks laid out
    // Swiped into sight: the sheet's givens come first (a swipe on their text scrolls the panel).
    for (let i = 0; i < 8; ++i) {
      state = await vplabState(page);
      const cell = await cssRect(page, state, firstCellId(first));
      const switcher = await cssRect(page, state, 'switch.tasks');
      if (cell.y + cell.h <= switcher.y - 4) break;
      const at = { x: 195, y: switcher.y - 60 };
      await finger.swipe(at, { x: at.x, y: at.y - 150 });
      await waitFrames(page, 3);
    }
    await finger.tap(rectPoint(await cssRect(page, await vplabState(page), firstCellId(first))));
    await waitForState(page, (s) => s.keysWanted, 'the first cell to take the keys', messages);
    await page.keyboard.type('5/2');
    await page.keyboard.press('Tab');
    await page.keyboard.down('Control');
    await page.keyboard.press('Enter');
    await page.keyboard.up('Control');
    await waitForState(page, (s) => s.exercise.check, 'Check on the phone', messages);
    state = await vplabState(page);
    assert.equal(state.exercise.fields[0].texts[0], '5/2');
    // The answer is kept as it is typed: a reload brings it back.
    await page.reload({ waitUntil: 'load' });
    await page.waitForFunction(() => window.vplab && window.vplab.state && (() => { try { return window.vplab.state().exercise; } catch (e) { return false; } })(),
      { timeout: 60_000, polling: 200 });
    state = await vplabState(page);
    assert.equal(state.exercise.fields[0].texts[0], '5/2', 'the kept answer came back');
    assert.deepEqual(errorsOf(messages), [], 'the page logged errors or warnings');
    await context.close();
  });
});
