// The page's worker: runs the long, pure part of an edit in its own instance of the app's
// wasm, so the page keeps drawing meanwhile (crates/app/src/offload.rs). Its first message is
// the page's compiled module, {module}: sharing it shares its machine code, already optimized
// while the page ran. It answers an import's {id, names, files} or an op's
// {id, models, kept, op, preview?} (the preview of a gesture's op so far, `preview` its
// version) with {id, bytes} (the result, transferred) or {id, error, refused} (the sentence;
// `refused` when the wasm refused the work, as opposed to a wasm that failed to load or
// trapped, which the page replaces, so a trapped instance is never used again).

import init, { read_import, run_model_op, run_preview } from "./sketchmesh_app.js";

let ready;

self.onmessage = async ({ data }) => {
  if (data.module !== undefined) {
    // Should the module not take, the file is fetched and compiled as before.
    ready = init({ module_or_path: data.module }).catch(() => init());
    return;
  }
  const { id } = data;
  try {
    await (ready ??= init());
    const bytes = data.op === undefined
      ? read_import(data.names, data.files)
      : data.preview === undefined
        ? run_model_op(data.models, data.kept, data.op)
        : run_preview(data.models, data.kept, data.op, data.preview);
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (e) {
    self.postMessage({ id, error: String(e?.message ?? e), refused: typeof e === "string" });
  }
};
