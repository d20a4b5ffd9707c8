// The documents kept in this browser (IndexedDB), so that a reload, a closed tab or a
// discarded background tab loses nothing, and several pieces of work live side by side.
//
// - `records`: id → the app's autosave record, a JSON text (session, camera, tool; see
//   crates/app/src/autosave.rs).
// - `documents`: id → { id, name, created, updated, thumbnail (a PNG Blob or null) }, small,
//   so that the documents panel lists them without reading the records.
// - `autosave`: "open" → the id of the document shown; "set-aside-<time>" → records that did
//   not restore, kept rather than deleted. (Version 1 kept the one record under "current".)
//
// IndexedDB is asynchronous, so a write never holds a frame. Writes run one after another, so
// that a slow one never lands after a newer one.

const DB = "sketchmesh";
const VERSION = 2;
const RECORDS = "records";
const DOCUMENTS = "documents";
const STATE = "autosave";
const OPEN = "open";

let database = null;
let openId = null;
// The name the shown document gets when it is first written.
let pendingName = null;
let last = Promise.resolve();

function open() {
  database ??= new Promise((resolve, reject) => {
    const request = indexedDB.open(DB, VERSION);
    request.onupgradeneeded = (event) => upgrade(request, event.oldVersion);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error);
    request.onblocked = () => reject(new Error("another tab holds an older version of the store"));
  });
  return database;
}

// Creates the stores; version 1's single record becomes the open document.
function upgrade(request, oldVersion) {
  const db = request.result;
  if (oldVersion < 1) db.createObjectStore(STATE);
  db.createObjectStore(RECORDS);
  db.createObjectStore(DOCUMENTS, { keyPath: "id" });
  if (oldVersion < 1) return;
  const state = request.transaction.objectStore(STATE);
  state.get("current").onsuccess = (event) => {
    const text = event.target.result;
    if (text == null) return;
    const id = newId();
    const now = Date.now();
    request.transaction.objectStore(RECORDS).put(text, id);
    request.transaction.objectStore(DOCUMENTS).put({ id, name: defaultName(now), created: now, updated: now, thumbnail: null });
    state.put(id, OPEN);
    state.delete("current");
  };
}

// Runs `work(stores)` in one transaction over `names`; resolves with what `work` returned (a
// request's result once the transaction is committed, or a plain value).
async function transact(names, mode, work) {
  const db = await open();
  return new Promise((resolve, reject) => {
    const transaction = db.transaction(names, mode);
    const stores = Object.fromEntries(names.map((name) => [name, transaction.objectStore(name)]));
    let result;
    try {
      result = work(stores);
    } catch (error) {
      // A request refused at once (a full store can refuse the put itself).
      transaction.abort();
      reject(storageError(error));
      return;
    }
    transaction.oncomplete = () => resolve(result instanceof IDBRequest ? result.result : result);
    transaction.onerror = () => reject(storageError(transaction.error));
    transaction.onabort = () => reject(storageError(transaction.error));
  });
}

// Queues a write after the earlier ones.
function write(names, work) {
  last = last.catch(() => {}).then(() => transact(names, "readwrite", work));
  return last;
}

// A full store gets a sentence that says what to do.
function storageError(error) {
  if (error?.name === "QuotaExceededError") {
    return new Error("this browser's storage for Sketchmesh is full: delete documents you no longer need under Documents, or save the session to a file");
  }
  return error ?? new Error("the browser's storage failed");
}

function newId() {
  return crypto.randomUUID?.() ?? `${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`;
}

function defaultName(time) {
  const date = new Date(time);
  const day = date.toLocaleDateString(undefined, { day: "numeric", month: "short" });
  const clock = date.toLocaleTimeString(undefined, { hour: "2-digit", minute: "2-digit" });
  return `Sketch ${day} ${clock}`;
}

// The id of the document shown.
export function shownId() {
  return openId;
}

// The shown document's record (JSON text), or null for an empty start. Call once, first.
export async function load() {
  openId = (await transact([STATE], "readonly", (s) => s[STATE].get(OPEN))) ?? newId();
  return (await transact([RECORDS], "readonly", (s) => s[RECORDS].get(openId))) ?? null;
}

// Writes `text` as the shown document's record.
export function save(text) {
  const id = openId;
  const now = Date.now();
  return write([RECORDS, DOCUMENTS, STATE], (s) => {
    s[RECORDS].put(text, id);
    s[DOCUMENTS].get(id).onsuccess = (event) => {
      const known = event.target.result ?? { id, name: pendingName ?? defaultName(now), created: now, thumbnail: null };
      s[DOCUMENTS].put({ ...known, updated: now });
    };
    s[STATE].put(id, OPEN);
  });
}

// Shows the document `id` from now on (its record is written by later saves); a new id when
// none is given, named `name` once it is first written.
export function show(id = null, name = null) {
  openId = id ?? newId();
  pendingName = name;
  const shown = openId;
  return write([STATE], (s) => s[STATE].put(shown, OPEN));
}

// Keeps `text` (the document shown, or null when it has nothing worth keeping) and shows a
// new, empty document named `name`.
export function keep(text, name = null) {
  if (text != null) save(text);
  return show(null, name);
}

// Keeps `text`, a record that did not restore, under a key of its own; the document it
// belonged to goes, and a new one is shown.
export function setAside(text) {
  const id = openId;
  write([RECORDS, DOCUMENTS, STATE], (s) => {
    s[STATE].put(text, `set-aside-${new Date().toISOString()}`);
    s[RECORDS].delete(id);
    s[DOCUMENTS].delete(id);
  });
  return show();
}

// Sets the thumbnail (a PNG Blob) of document `id`, if it is kept.
export function setThumbnail(id, blob) {
  return write([DOCUMENTS], (s) => {
    s[DOCUMENTS].get(id).onsuccess = (event) => {
      if (event.target.result) s[DOCUMENTS].put({ ...event.target.result, thumbnail: blob });
    };
  });
}

export function rename(id, name) {
  return write([DOCUMENTS], (s) => {
    s[DOCUMENTS].get(id).onsuccess = (event) => {
      if (event.target.result) s[DOCUMENTS].put({ ...event.target.result, name });
    };
  });
}

export function remove(id) {
  return write([RECORDS, DOCUMENTS], (s) => {
    s[RECORDS].delete(id);
    s[DOCUMENTS].delete(id);
  });
}

// The record of document `id`, or null.
export async function record(id) {
  await last.catch(() => {});
  return (await transact([RECORDS], "readonly", (s) => s[RECORDS].get(id))) ?? null;
}

// The kept documents, the latest changed first, after the writes queued so far.
export async function list() {
  await last.catch(() => {});
  const all = await transact([DOCUMENTS], "readonly", (s) => s[DOCUMENTS].getAll());
  return all.sort((a, b) => b.updated - a.updated);
}
