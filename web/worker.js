// The page's worker: runs the long, pure part of an edit in its own instance of the app's
// wasm, so the page keeps drawing meanwhile (crates/app/src/offload.rs). It answers an
// import's {id, names, files} or an op's {id, models, op} with {id, bytes} (the result,
// transferred) or {id, error} (the sentence of the refusal). A wasm that failed to load or
// trapped answers with the error too; the page replaces a worker that refused, so a trapped
// instance is never used again.

import init, { read_import, run_model_op } from "./sketchmesh_app.js";

const ready = init();

self.onmessage = async ({ data }) => {
  const { id } = data;
  try {
    await ready;
    const bytes = data.op === undefined ? read_import(data.names, data.files) : run_model_op(data.models, data.op);
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (e) {
    self.postMessage({ id, error: String(e?.message ?? e) });
  }
};
