// The documents kept in this browser (IndexedDB), so that a reload, a closed tab or a
// discarded background tab loses nothing, and several pieces of work live side by side.
//
// - `records`: id → the app's autosave record (session and camera; see
//   crates/app/src/autosave.rs): a JSON text, or (since version 3) a list of its pieces in
//   order, each a string or `{ piece: key }`, a long piece kept in `pieces`.
// - `pieces`: "<id>/<index>" → a piece of document id's record at least `APART` long: an op
//   carrying an imported file (a scan's is tens of megabytes). The record's other pieces change
//   at every autosave; a long one is written once, not copied again at each change.
// - `documents`: id → { id, name, created, updated, thumbnail (a PNG Blob or null) }, small,
//   so that the documents panel lists them without reading the records.
// - `autosave`: "open" → the id of the document shown; "set-aside-<time>" → records that did
//   not restore, kept rather than deleted. (Version 1 kept the one record under "current".)
//
// IndexedDB is asynchronous, so a write never holds a frame. Writes run one after another, so
// that a slow one never lands after a newer one.

const DB = "sketchmesh";
const VERSION = 3;
const RECORDS = "records";
const PIECES = "pieces";
const DOCUMENTS = "documents";
const STATE = "autosave";
const OPEN = "open";
// A piece of a record this long or longer is stored apart (64 KiB: an import, not an edit).
const APART = 1 << 16;

let database = null;
let openId = null;
// The name the shown document gets when it is first written.
let pendingName = null;
let last = Promise.resolve();
// Key → the long piece as last written (or read): a piece still equal to it is not written
// again. The strings are the app's own (it keeps each op's text), so this costs no copy.
const written = new Map();

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

// Creates the stores a version lacks; version 1's single record becomes the open document.
function upgrade(request, oldVersion) {
  const db = request.result;
  if (oldVersion < 1) db.createObjectStore(STATE);
  if (oldVersion < 2) {
    db.createObjectStore(RECORDS);
    db.createObjectStore(DOCUMENTS, { keyPath: "id" });
  }
  if (oldVersion < 3) db.createObjectStore(PIECES);
  if (oldVersion !== 1) return;
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

// `name`, or with the lowest number after it that makes it none of `taken`: two documents
// made in the same minute get different names.
function distinctName(name, taken) {
  let distinct = name;
  for (let n = 2; taken.has(distinct); n++) distinct = `${name} (${n})`;
  return distinct;
}

// The id of the document shown.
export function shownId() {
  return openId;
}

// The shown document's record (JSON text), or null for an empty start. Call once, first.
// A record that cannot be read stays as it is, and a new document is shown.
export async function load() {
  openId = (await transact([STATE], "readonly", (s) => s[STATE].get(OPEN))) ?? newId();
  try {
    return await read(openId);
  } catch (error) {
    openId = newId();
    throw error;
  }
}

// Record `id`'s text, or null; its long pieces are remembered as written.
async function read(id) {
  const stored = await transact([RECORDS], "readonly", (s) => s[RECORDS].get(id));
  if (stored == null || typeof stored === "string") return stored ?? null;
  const keys = stored.filter((part) => typeof part !== "string").map((part) => part.piece);
  const pieces = await transact([PIECES], "readonly", (s) => Promise.all(keys.map((key) => asked(s[PIECES].get(key)))));
  if (pieces.some((piece) => typeof piece !== "string")) {
    throw new Error("a part of the document kept in this browser is missing from its storage");
  }
  const texts = new Map(keys.map((key, i) => [key, pieces[i]]));
  for (const [key, piece] of texts) written.set(key, piece);
  return stored.map((part) => (typeof part === "string" ? part : texts.get(part.piece))).join("");
}

// Resolves with a request's result.
function asked(request) {
  return new Promise((resolve, reject) => {
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error);
  });
}

// Writes `pieces` (strings whose concatenation is the record; see `autosave_pieces` in
// crates/app/src/web.rs) as the shown document's record.
export function save(pieces) {
  const id = openId;
  const now = Date.now();
  return write([RECORDS, PIECES, DOCUMENTS, STATE], (s) => {
    s[RECORDS].put(parted(id, pieces, s[PIECES]), id);
    s[DOCUMENTS].get(id).onsuccess = (event) => {
      if (event.target.result) {
        s[DOCUMENTS].put({ ...event.target.result, updated: now });
        return;
      }
      // A new document: its name, unless another has it already ("Sketch 7 Dec 06:12 (2)").
      s[DOCUMENTS].getAll().onsuccess = (all) => {
        const taken = new Set(all.target.result.map((doc) => doc.name));
        const name = distinctName(pendingName ?? defaultName(now), taken);
        s[DOCUMENTS].put({ id, name, created: now, updated: now, thumbnail: null });
      };
    };
    s[STATE].put(id, OPEN);
  });
}

// The record of document `id` made of `pieces`: runs of short pieces joined, each long one
// put into `store` under its own key unless it is there already, the long pieces no longer
// in the record deleted.
function parted(id, pieces, store) {
  const parts = [];
  const kept = new Set();
  let run = [];
  pieces.forEach((piece, index) => {
    if (piece.length < APART) {
      run.push(piece);
      return;
    }
    if (run.length > 0) parts.push(run.join(""));
    run = [];
    const key = `${id}/${index}`;
    if (written.get(key) !== piece) {
      const put = store.put(piece, key);
      written.set(key, piece);
      // A failed write is written again next time.
      put.onerror = () => written.delete(key);
    }
    kept.add(key);
    parts.push({ piece: key });
  });
  if (run.length > 0) parts.push(run.join(""));
  for (const key of writtenKeysOf(id)) {
    if (!kept.has(key)) {
      store.delete(key);
      written.delete(key);
    }
  }
  return parts;
}

// Deletes document `id`'s long pieces.
function deletePieces(id, store) {
  store.delete(IDBKeyRange.bound(`${id}/`, `${id}/\uffff`));
  for (const key of writtenKeysOf(id)) written.delete(key);
}

// The keys of document `id`'s long pieces written (or read) so far.
function writtenKeysOf(id) {
  return [...written.keys()].filter((key) => key.startsWith(`${id}/`));
}

// Shows the document `id` from now on (its record is written by later saves); a new id when
// none is given, named `name` once it is first written.
export function show(id = null, name = null) {
  openId = id ?? newId();
  pendingName = name;
  const shown = openId;
  return write([STATE], (s) => s[STATE].put(shown, OPEN));
}

// Keeps `pieces` (the record of the document shown, or null when it has nothing worth
// keeping) and shows a new, empty document named `name`.
export function keep(pieces, name = null) {
  if (pieces != null) save(pieces);
  return show(null, name);
}

// Keeps `text`, a record that did not restore, under a key of its own; the document it
// belonged to goes, and a new one is shown.
export function setAside(text) {
  const id = openId;
  write([RECORDS, PIECES, DOCUMENTS, STATE], (s) => {
    s[STATE].put(text, `set-aside-${new Date().toISOString()}`);
    s[RECORDS].delete(id);
    deletePieces(id, s[PIECES]);
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
  return write([RECORDS, PIECES, DOCUMENTS], (s) => {
    s[RECORDS].delete(id);
    deletePieces(id, s[PIECES]);
    s[DOCUMENTS].delete(id);
  });
}

// The record of document `id`, or null.
export async function record(id) {
  await last.catch(() => {});
  return read(id);
}

// The kept documents, the latest changed first, after the writes queued so far.
export async function list() {
  await last.catch(() => {});
  const all = await transact([DOCUMENTS], "readonly", (s) => s[DOCUMENTS].getAll());
  return all.sort((a, b) => b.updated - a.updated);
}
