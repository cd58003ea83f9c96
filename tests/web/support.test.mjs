// The harness's own checks, without a browser: the picture comparison the browser tests' thresholds
// rest on, and the static server's answers.

import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { PNG } from 'pngjs';

import { comparePngs, distinctColours, formatComparison, startServer, tempDir } from './support.mjs';

function png(width, height, colourAt) {
  const image = new PNG({ width, height });
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) image.data.set(colourAt(x, y), 4 * (y * width + x));
  }
  return PNG.sync.write(image);
}

test('comparePngs: max and mean absolute channel difference, the worst pixels first', () => {
  const grey = png(4, 3, () => [100, 100, 100, 255]);
  const changed = png(4, 3, (x, y) => (x === 2 && y === 1 ? [100, 160, 90, 255] : x === 0 && y === 2 ? [103, 100, 100, 255] : [100, 100, 100, 255]));
  const result = comparePngs(changed, grey);
  assert.equal(result.max, 60);
  assert.equal(result.mean, (60 + 10 + 3) / (4 * 3 * 4));
  assert.equal(result.differing, 2);
  assert.deepEqual(result.worst.map((w) => [w.x, w.y, w.delta]), [[2, 1, 60], [0, 2, 3]]);
  assert.deepEqual(result.worst[0].actual, [100, 160, 90, 255]);
  assert.deepEqual(result.worst[0].expected, [100, 100, 100, 255]);
  assert.equal(result.pixelsOver(5), 1);
  const report = formatComparison(result, { maxThreshold: 10, meanThreshold: 0.5, label: 'x' });
  assert.match(report, /max difference 60 \(allowed 10\)/);
  assert.match(report, /\[\s+2,\s+1\] #64a05aff vs #646464ff, 60/);

  assert.equal(comparePngs(grey, grey).max, 0);
  assert.equal(comparePngs(grey, grey).worst.length, 0);
  assert.throws(() => comparePngs(grey, png(3, 4, () => [0, 0, 0, 255])), /sizes differ: actual 4x3, expected 3x4/);
});

test('comparePngs lists at most ten pixels', () => {
  const a = png(8, 8, () => [0, 0, 0, 255]);
  const b = png(8, 8, (x, y) => [x * 8 + y, 0, 0, 255]);
  const result = comparePngs(a, b);
  assert.equal(result.worst.length, 10);
  assert.deepEqual(result.worst.slice(0, 2).map((w) => w.delta), [63, 62]);
  assert.equal(distinctColours(a), 1);
  assert.equal(distinctColours(b), 64);
});

test('startServer serves the directory with the MIME types the page needs, and nothing outside it', async () => {
  const work = tempDir('server-test');
  const dir = path.join(work.dir, 'site');
  mkdirSync(dir);
  writeFileSync(path.join(dir, 'index.html'), '<!doctype html>');
  writeFileSync(path.join(dir, 'vplab.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d]));
  writeFileSync(path.join(work.dir, 'secret.txt'), 'outside');
  const server = await startServer(dir);
  try {
    const index = await fetch(server.url);
    assert.equal(index.status, 200);
    assert.match(index.headers.get('content-type'), /^text\/html/);
    const wasm = await fetch(`${server.url}vplab.wasm`);
    assert.equal(wasm.headers.get('content-type'), 'application/wasm');
    assert.deepEqual([...new Uint8Array(await wasm.arrayBuffer())], [0, 0x61, 0x73, 0x6d]);
    assert.equal((await fetch(`${server.url}missing.js`)).status, 404);
    assert.equal((await fetch(`${server.url}..%2fsecret.txt`)).status, 404);
    assert.deepEqual(server.requests.map((r) => r.status), [200, 200, 404, 404]);
  } finally {
    await server.close();
    work.remove();
  }
});
