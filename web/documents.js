// Several documents: "New" keeps the document shown and starts an empty one; the documents
// panel lists the kept ones (thumbnail, name, date) to open, rename or delete. The panel is
// page markup over the canvas (index.html's #documents), so that names are edited in a real
// text field and read by screen readers.

import * as store from "./store.js";
import * as examples from "./examples.js";

const THUMBNAIL_WAIT_MS = 3000;

const panel = () => document.getElementById("documents");
const app = () => window.sketchmesh;

// Says `sentence` over the view.
function tell(sentence) {
  app()?.notify(sentence);
}

// Writes the shown document's latest change and its thumbnail: before another one is shown.
async function keepShown() {
  app().flushAutosave();
  const shot = await Promise.race([
    app().thumbnail(),
    new Promise((resolve) => setTimeout(() => resolve(null), THUMBNAIL_WAIT_MS)),
  ]);
  if (shot) await store.setThumbnail(store.shownId(), await png(shot));
}

// The thumbnail `{width, height, pixels}` as a PNG Blob.
function png({ width, height, pixels }) {
  const canvas = document.createElement("canvas");
  canvas.width = width;
  canvas.height = height;
  canvas.getContext("2d").putImageData(new ImageData(pixels, width, height), 0, 0);
  return new Promise((resolve) => canvas.toBlob(resolve, "image/png"));
}

// Keeps the document shown and starts an empty one, named `name` once it is written.
export async function newDocument(name = null) {
  await keepShown();
  await store.show(null, name);
  app().restore(null);
  tell("New document: the previous one is kept under Documents.");
  if (!panel().hidden) await render();
}

// Opens example `name` as a new document (the one shown is kept): replayed at once, or with
// `play` its making played step by step. Resolves once it is shown, or playing.
export async function openExample(name, { play = false } = {}) {
  const example = await examples.load(name);
  await newDocument(example.title);
  if (play) await app().playMaking(example.text, example.captions ?? []);
  else await app().replay(example.text);
}

// Shows the kept document `id` (the one shown is kept first). A record that does not restore
// is set aside with a sentence, and an empty document is shown.
export async function openDocument(id) {
  if (id === store.shownId()) return;
  await keepShown();
  const text = await store.record(id);
  await store.show(id);
  try {
    app().restore(text);
  } catch (e) {
    console.warn(e);
    await store.setAside(text);
    app().restore(null);
  }
}

// Deletes document `id`; deleting the one shown shows an empty one.
export async function removeDocument(id) {
  await store.remove(id);
  if (id === store.shownId()) {
    await store.show();
    app().restore(null);
  }
}

// The kept documents for the page API: `{id, name, created, updated, shown, thumbnail}`, the
// latest changed first.
export async function documents() {
  return (await store.list()).map(({ id, name, created, updated, thumbnail }) => ({
    id, name, created, updated, shown: id === store.shownId(), thumbnail: thumbnail != null,
  }));
}

// Opens the panel, with a fresh thumbnail of the document shown.
export async function show() {
  panel().hidden = false;
  await render();
  await keepShown().catch((e) => tell(`Could not keep the document: ${e.message ?? e}`));
  await render();
}

export function hide() {
  panel().hidden = true;
  for (const url of urls.splice(0)) URL.revokeObjectURL(url);
}

const urls = [];

// Fills the list from the store.
async function render() {
  const list = document.getElementById("documents-list");
  const kept = await store.list().catch((e) => {
    tell(`Could not read the documents: ${e.message ?? e}`);
    return [];
  });
  for (const url of urls.splice(0)) URL.revokeObjectURL(url);
  list.replaceChildren(...kept.map(row));
  if (kept.length === 0) {
    const empty = document.createElement("li");
    empty.className = "empty";
    empty.textContent = "Nothing kept yet: documents appear here once something is drawn.";
    list.append(empty);
  }
  await renderExamples();
  await showUsage();
}

// The examples: thumbnail, title, one line on what it shows, Open and Play how it was made.
async function renderExamples() {
  const list = document.getElementById("documents-examples");
  if (list.childElementCount > 0) return;
  const shown = await examples.list().catch((e) => {
    tell(`Could not list the examples: ${e.message ?? e}`);
    return [];
  });
  list.replaceChildren(...shown.map((example) => {
    const item = document.createElement("li");
    item.dataset.example = example.name;
    const image = document.createElement("img");
    image.className = "thumbnail";
    image.src = `examples/${example.thumbnail}`;
    image.alt = "";
    const text = document.createElement("div");
    text.className = "text";
    const title = document.createElement("span");
    title.className = "title";
    title.textContent = example.title;
    const line = document.createElement("span");
    line.className = "line";
    line.textContent = example.description;
    text.append(title, line);
    const opened = (play) => async () => {
      hide();
      await openExample(example.name, { play }).catch((e) => tell(`Could not open the example: ${e.message ?? e}`));
    };
    const actions = document.createElement("div");
    actions.className = "actions";
    actions.append(button("Open", "open", opened(false)), button("Play how it was made", "play", opened(true)));
    item.append(image, text, actions);
    return item;
  }));
}

// One document: thumbnail, name (editable), date, Open and Delete.
function row(doc) {
  const item = document.createElement("li");
  item.dataset.id = doc.id;
  const shown = doc.id === store.shownId();
  item.classList.toggle("shown", shown);
  const image = document.createElement(doc.thumbnail ? "img" : "div");
  image.className = "thumbnail";
  if (doc.thumbnail) {
    const url = URL.createObjectURL(doc.thumbnail);
    urls.push(url);
    image.src = url;
    image.alt = "";
  }
  const name = document.createElement("input");
  name.className = "name";
  name.value = doc.name;
  name.setAttribute("aria-label", "Name");
  name.addEventListener("change", () => {
    const renamed = name.value.trim() || doc.name;
    name.value = renamed;
    store.rename(doc.id, renamed).catch((e) => tell(`Could not rename: ${e.message ?? e}`));
  });
  const date = document.createElement("span");
  date.className = "date";
  date.textContent = new Date(doc.updated).toLocaleString(undefined, { dateStyle: "medium", timeStyle: "short" });
  const open = button(shown ? "Shown" : "Open", "open", async () => {
    hide();
    await openDocument(doc.id).catch((e) => tell(`Could not open ${doc.name}: ${e.message ?? e}`));
  });
  open.disabled = shown;
  // Deleting takes a second tap, so that a stray one loses nothing.
  const remove = button("Delete", "delete", async () => {
    if (!remove.classList.contains("armed")) {
      remove.classList.add("armed");
      remove.textContent = "Tap to delete";
      setTimeout(() => {
        remove.classList.remove("armed");
        remove.textContent = "Delete";
      }, 3000);
      return;
    }
    await removeDocument(doc.id).catch((e) => tell(`Could not delete ${doc.name}: ${e.message ?? e}`));
    await render();
  });
  const text = document.createElement("div");
  text.className = "text";
  text.append(name, date);
  const actions = document.createElement("div");
  actions.className = "actions";
  actions.append(open, remove);
  item.append(image, text, actions);
  return item;
}

function button(label, className, onClick) {
  const element = document.createElement("button");
  element.textContent = label;
  element.className = className;
  element.addEventListener("click", onClick);
  return element;
}

// How much of the browser's storage the documents use.
async function showUsage() {
  const note = document.getElementById("documents-note");
  const estimate = await navigator.storage?.estimate?.().catch(() => null);
  if (!estimate?.quota) {
    note.textContent = "";
    return;
  }
  const mb = (bytes) => (bytes / 1e6).toFixed(bytes < 1e7 ? 1 : 0);
  note.textContent = `Kept in this browser: ${mb(estimate.usage)} MB of ${mb(estimate.quota)} MB. Save a session to keep a copy elsewhere.`;
}

// Wires the panel's buttons; keys typed in it stay out of the app's shortcuts.
export function install() {
  document.getElementById("documents-new").addEventListener("click", () =>
    newDocument().catch((e) => tell(`Could not start a new document: ${e.message ?? e}`)));
  document.getElementById("documents-close").addEventListener("click", hide);
  panel().addEventListener("click", (e) => {
    if (e.target === panel()) hide();
  });
  // Keys typed in the panel (a rename) are not the app's shortcuts, so they stop here; Escape
  // still closes it, from a button or a name being edited.
  panel().addEventListener("keydown", (e) => {
    e.stopPropagation();
    if (e.key === "Escape") hide();
  });
  // Escape closes the panel wherever else the focus is (a deleted row's button takes it along).
  addEventListener("keydown", (e) => {
    if (e.key === "Escape" && !panel().hidden) hide();
  });
}
