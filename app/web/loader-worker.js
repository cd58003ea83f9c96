// The page's loader worker (app/web/loader_worker.cpp, docs/measured.md "Large scenes in the page"): builds a
// scene's meshes off the page's thread. Messages from the page:
//   {put: PATH, bytes: Uint8Array}                      a file the page was given (/uploads/…)
//   {id, text: Uint8Array, source, baseDir}             a scene's text to read, its meshes to build
// Answers: {id, error, meshes: [[positions, indices, faceStart, normals, normalIndices], …]} (ArrayBuffers,
// transferred), one entry per object in order; {id, failure: {source, reason}, meshes: []} when the
// loader itself failed (the page words it).
"use strict";
importScripts("vplab-loader.js");
const ready = createVplabLoader();

function put(M, path, bytes) {
  const dir = path.substring(0, path.lastIndexOf("/"));
  if (dir) M.FS.mkdirTree(dir);
  M.FS.writeFile(path, bytes);
}

function build(M, m) {
  const text = M._malloc(m.text.length + 1);
  M.HEAPU8.set(m.text, text);
  const answer = M.ccall("vplab_loader_parse", "number", ["number", "number", "string", "string"],
                         [text, m.text.length, m.source, m.baseDir]);
  M._free(text);
  const error = M.UTF8ToString(M._vplab_loader_error(answer));
  const meshes = [];
  const transfer = [];
  const size = M._malloc(4);
  for (let i = 0, n = M._vplab_loader_objects(answer); i < n; ++i) {
    const arrays = [];
    for (let which = 0; which < 5; ++which) {  // vplab_loader_array: positions, indices, face starts, normals, normal indices
      const at = M._vplab_loader_array(answer, i, which, size);
      const copy = M.HEAPU8.slice(at, at + M.HEAPU32[size >> 2]);
      arrays.push(copy.buffer);
      transfer.push(copy.buffer);
    }
    meshes.push(arrays);
  }
  M._free(size);
  M._vplab_loader_free(answer);
  postMessage({ id: m.id, error, meshes }, transfer);
}

onmessage = (e) => {
  const m = e.data;
  ready.then((M) => {
    try {
      if (m.put) put(M, m.put, m.bytes);
      else build(M, m);
    } catch (err) {
      // The page says it in its language (index.html: "{1}: the page's loader failed ({2})").
      if (!m.put) postMessage({ id: m.id, error: "", failure: { source: m.source, reason: String(err) }, meshes: [] });
    }
  });
};
