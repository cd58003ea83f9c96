// The web bundle for course pages (scripts/web_bundle.py, written by scripts/web.sh): the archive
// holds the page's four files with their gzip and Brotli copies and a README, the copies decompress to
// the files, the same files give the same archive, and the page unpacked from it runs in Chromium.

import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { copyFileSync, existsSync, readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { brotliDecompressSync, gunzipSync } from 'node:zlib';

import { launchBrowser, openPage, startServer, tempDir, vplabState, webDir } from './support.mjs';

const execFileAsync = promisify(execFile);
const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const pageFiles = ['index.html', 'vplab.js', 'vplab.wasm', 'vplab.data', 'loader-worker.js', 'vplab-loader.js',
  'vplab-loader.wasm', 'vplab-loader.data'];

function projectVersion() {
  const cmake = readFileSync(path.join(repoRoot, 'CMakeLists.txt'), 'utf8');
  return cmake.match(/^project\(vplab VERSION ([0-9.]+)/m)[1];
}

test('the web bundle holds the page, its precompressed copies and a README, and the page runs from it', { timeout: 180_000 }, async () => {
  const version = projectVersion();
  const folder = `vplab-web-${version}`;
  const archive = path.join(webDir, `${folder}.zip`);
  assert.ok(existsSync(archive), `${archive} is missing: scripts/web.sh writes it`);
  const work = tempDir('bundle');
  let browser, server;
  try {
    await execFileAsync('python3', ['-m', 'zipfile', '-e', archive, work.dir]);
    const unpacked = path.join(work.dir, folder);
    const names = readdirSync(unpacked).sort();
    const withBrotli = names.some((n) => n.endsWith('.br'));
    const expected = ['README.md', ...pageFiles.flatMap((f) => [f, `${f}.gz`, ...(withBrotli ? [`${f}.br`] : [])])].sort();
    assert.deepEqual(names, expected, 'the bundle holds other files');
    for (const file of pageFiles) {
      const original = readFileSync(path.join(webDir, file));
      assert.ok(readFileSync(path.join(unpacked, file)).equals(original), `${file} in the bundle is not the built one`);
      assert.ok(gunzipSync(readFileSync(path.join(unpacked, `${file}.gz`))).equals(original), `${file}.gz does not decompress to ${file}`);
      if (withBrotli)
        assert.ok(brotliDecompressSync(readFileSync(path.join(unpacked, `${file}.br`))).equals(original), `${file}.br does not decompress to ${file}`);
    }
    const readme = readFileSync(path.join(unpacked, 'README.md'), 'utf8');
    assert.match(readme, new RegExp(`^# vplab ${version.replace(/\./g, '\\.')} for a course page`));
    assert.match(readme, /application\/wasm/, 'the README does not say which header the .wasm wants');
    assert.match(readme, /Content-Encoding: gzip/, 'the README does not say how to serve the precompressed copies');
    assert.match(readme, /#scene=perspective/, 'the README does not say how to link a state');

    // The same files give the same archive (no times, no names of the machine in it).
    const again = tempDir('bundle-again');
    try {
      for (const file of pageFiles) copyFileSync(path.join(webDir, file), path.join(again.dir, file));
      await execFileAsync('python3', [path.join(repoRoot, 'scripts', 'web_bundle.py'), again.dir, version]);
      assert.ok(readFileSync(path.join(again.dir, `${folder}.zip`)).equals(readFileSync(archive)),
        'the bundle made again from the same files differs');
    } finally {
      again.remove();
    }

    // The unpacked folder is the page.
    server = await startServer(unpacked);
    browser = await launchBrowser();
    const { page, console: messages } = await openPage(browser, server.url + '#scene=perspective');
    const state = await vplabState(page);
    assert.match(state.scene, /perspective\.json$/, 'the page from the bundle does not open a linked scene');
    assert.deepEqual(messages, [], 'the page from the bundle logged errors');
  } finally {
    await browser?.close();
    await server?.close();
    work.remove();
  }
});
