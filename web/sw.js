// The service worker: keeps the app's files so that the page opens offline after one visit.
//
// `cargo xtask build-web` writes the version (a hash of the files) and the file list below.
// A new version is cached in the background while the page runs on the old one, takes over
// at once (the running page keeps the files it loaded), and so is what the next load opens;
// the page says so. Old versions' caches are deleted.

const VERSION = "__SKETCHMESH_VERSION__";
const FILES = __SKETCHMESH_FILES__;
const CACHE = `sketchmesh-${VERSION}`;

self.addEventListener("install", (event) => {
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(FILES)).then(() => self.skipWaiting()));
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((key) => key.startsWith("sketchmesh-") && key !== CACHE).map((key) => caches.delete(key))))
      .then(() => self.clients.claim()),
  );
});

// The app's files come from the cache; anything else (and a file the cache lacks) from the
// network. A page load is the cached index.html.
self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) return;
  const key = request.mode === "navigate" ? "./" : request;
  event.respondWith(
    caches.open(CACHE)
      .then((cache) => cache.match(key, { ignoreSearch: true }))
      .then((cached) => cached ?? fetch(request)),
  );
});
