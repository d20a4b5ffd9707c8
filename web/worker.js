// The page's worker: reads an import's files in its own instance of the app's wasm, so the
// page keeps drawing while a large file is parsed (crates/app/src/offload.rs). It answers
// each {id, names, files} with {id, bytes} (the result, transferred) or {id, error} (the
// sentence of the refusal). A wasm that failed to load or trapped answers with the error too;
// the page replaces a worker that refused, so a trapped instance is never used again.

import init, { read_import } from "./sketchmesh_app.js";

const ready = init();

self.onmessage = async ({ data: { id, names, files } }) => {
  try {
    await ready;
    const bytes = read_import(names, files);
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (e) {
    self.postMessage({ id, error: String(e?.message ?? e) });
  }
};
