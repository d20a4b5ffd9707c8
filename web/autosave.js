// Autosave store: the app's record (a JSON text: session, camera, tool) in IndexedDB, so that
// a reload, a closed tab or a discarded background tab loses nothing. IndexedDB is
// asynchronous, so a write never holds a frame. A record that does not restore is kept
// under another key ("set-aside-<time>") rather than deleted.

const DB = "sketchmesh";
const STORE = "autosave";
const CURRENT = "current";

let database = null;

function open() {
  database ??= new Promise((resolve, reject) => {
    const request = indexedDB.open(DB, 1);
    request.onupgradeneeded = () => request.result.createObjectStore(STORE);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error);
  });
  return database;
}

// Runs `work` on the store in one transaction; resolves with its request's result once the
// transaction is committed.
async function transact(mode, work) {
  const db = await open();
  return new Promise((resolve, reject) => {
    const transaction = db.transaction(STORE, mode);
    const request = work(transaction.objectStore(STORE));
    transaction.oncomplete = () => resolve(request.result);
    transaction.onerror = () => reject(transaction.error);
    transaction.onabort = () => reject(transaction.error);
  });
}

// Writes `text` as the current record. Writes are chained, so that a slow one never lands
// after a newer one.
let last = Promise.resolve();
export function save(text) {
  last = last.catch(() => {}).then(() => transact("readwrite", (store) => store.put(text, CURRENT)));
  return last;
}

// The current record's text, or null.
export async function load() {
  return (await transact("readonly", (store) => store.get(CURRENT))) ?? null;
}

// Keeps `text` under a key of its own and clears the current record.
export function setAside(text) {
  return transact("readwrite", (store) => {
    store.put(text, `set-aside-${new Date().toISOString()}`);
    return store.delete(CURRENT);
  });
}
