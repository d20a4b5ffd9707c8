// Starts Sketchmesh in the page: the wasm app, the documents it restores and keeps, the
// failure notice, and the service worker that makes the page open offline.

import init, { start } from "./sketchmesh_app.js";
import * as store from "./store.js";
import * as documents from "./documents.js";
import * as examples from "./examples.js";

const loading = document.getElementById("loading");

// Ctrl+S and Ctrl+O are Sketchmesh's export and import, not the browser's save and open.
addEventListener("keydown", (e) => {
  if ((e.ctrlKey || e.metaKey) && ["s", "o", "e"].includes(e.key.toLowerCase())) e.preventDefault();
});
// A file dropped beside the canvas must not make the browser navigate away from the work.
for (const type of ["dragover", "drop"]) addEventListener(type, (e) => e.preventDefault());

// Says `sentence` over the view, and in the console for bug reports.
const notify = (sentence) => {
  console.warn(sentence);
  window.sketchmesh?.notify(sentence);
};

// The app hands its autosave record here (see crates/app/src/autosave.rs), and the documents
// panel's buttons (crates/app/src/panels/toolbar.rs) here.
window.sketchmeshAutosave = {
  save: (pieces) => store.save(pieces).catch((e) => notify(`Could not autosave your work: ${e?.message ?? e}`)),
  keep: (pieces, name) => store.keep(pieces, name).catch((e) => notify(`Could not keep the previous document: ${e?.message ?? e}`)),
};
window.sketchmeshDocuments = {
  show: () => documents.show(),
  newDocument: () => documents.newDocument().catch((e) => notify(`Could not start a new document: ${e?.message ?? e}`)),
};

// A panic in the wasm stops the app (its hook calls this): say so, offer a bug report and a
// reload, and write no more autosaves, so the record of the last finished change stays.
let panicked = false;
window.sketchmeshPanicked = (sentence) => {
  panicked = true;
  document.getElementById("failure-message").textContent = sentence;
  document.getElementById("failure").hidden = false;
  document.getElementById("failure-reload").onclick = () => location.reload();
  document.getElementById("failure-copy").onclick = async (e) => {
    const session = await store.record(store.shownId()).catch(() => null);
    const report = { sentence, browser: navigator.userAgent, page: location.href, autosave: session };
    try {
      await navigator.clipboard.writeText(JSON.stringify(report, null, 2));
      e.target.textContent = "Copied";
    } catch {
      e.target.textContent = "Could not copy";
    }
  };
};
const flush = () => { if (!panicked) window.sketchmesh.flushAutosave(); };

// Restores the document shown last; a record that does not restore is set aside (the app has
// said so) and the page starts empty. Without IndexedDB the page starts empty too.
async function restore() {
  let record = null;
  try {
    record = await store.load();
  } catch (e) {
    // Without IndexedDB (no document is shown then) the page works but keeps nothing.
    if (store.shownId() == null) console.warn("No document store:", e);
    else notify(`Could not restore the last document (it stays under Documents): ${e?.message ?? e}`);
  }
  // At start: without a record, work done while the store was read stays.
  try {
    window.sketchmesh.restore(record, true);
  } catch (e) {
    console.warn(e);
    await store.setAside(record).catch((e) => console.warn(e));
    window.sketchmesh.restore(null, true);
  }
  // Closing or hiding the page writes the latest change at once.
  addEventListener("pagehide", flush);
  document.addEventListener("visibilitychange", () => {
    if (document.visibilityState === "hidden") flush();
  });
  // Asks the browser not to evict the documents under storage pressure.
  navigator.storage?.persist?.().catch(() => {});
}

// The page API's document calls (README, "Page API").
function extendPageApi() {
  Object.assign(window.sketchmesh, {
    newDocument: () => documents.newDocument(),
    documents: () => documents.documents(),
    openDocument: (id) => documents.openDocument(id),
    examples: () => examples.list().then((all) => all.map(({ name, title, description }) => ({ name, title, description }))),
    openExample: (name, options) => documents.openExample(name, options),
    examplePlayback: () => window.sketchmesh.making(),
  });
}

// The service worker keeps the app's files, so that the page opens offline after one visit.
// A new version is fetched in the background and taken on the next load; the page says so.
async function registerServiceWorker() {
  if (!("serviceWorker" in navigator)) return;
  // Without a worker at load this is the first visit: the one installing is not an update.
  const isUpdate = navigator.serviceWorker.controller != null;
  const registration = await navigator.serviceWorker.register("sw.js");
  registration.addEventListener("updatefound", () => {
    const worker = registration.installing;
    worker?.addEventListener("statechange", () => {
      if (worker.state === "activated" && isUpdate) {
        notify("A new version of Sketchmesh is ready: it opens the next time you load the page.");
      }
    });
  });
}

try {
  await init();
  await start("sketchmesh_canvas");
  loading.remove();
  extendPageApi();
  documents.install();
  await restore();
} catch (e) {
  loading.classList.add("error");
  loading.textContent = "Sketchmesh could not start: " + (e && e.message ? e.message : e);
  console.error(e);
}
registerServiceWorker().catch((e) => console.warn("No service worker:", e));
