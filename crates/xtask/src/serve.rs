//! `cargo xtask serve`: a static file server for `dist/` on loopback (tiny_http).
//!
//! Serves `GET`/`HEAD` only, with the right MIME types (browsers refuse to stream-compile wasm
//! without `application/wasm`), `Cache-Control: no-cache`, and the precompressed `<file>.gz` when the
//! request accepts gzip. Paths are resolved segment by segment and checked to stay inside the root.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::thread::JoinHandle;

use anyhow::{Context as _, anyhow, bail};
use tiny_http::{Header, Method, Request, Response, Server};

use crate::Workspace;
use crate::build;

/// The port `cargo xtask serve` uses unless told otherwise.
pub const DEFAULT_PORT: u16 = 8080;
const WORKERS: usize = 4;

/// `serve [--port N]`: build the page, then serve `dist/` until interrupted.
pub fn serve_command(workspace: &Workspace, options: &[&str]) -> anyhow::Result<()> {
    let port = parse_options(options)?;
    build::build_web(workspace)?;
    let server = StaticServer::start(&workspace.dist(), port)?;
    println!("Serving Sketchmesh at {}", server.url());
    server.wait();
    Ok(())
}

/// The port of `serve [--port N]`.
fn parse_options(options: &[&str]) -> anyhow::Result<u16> {
    match options {
        [] => Ok(DEFAULT_PORT),
        ["--port", number] => number
            .parse()
            .with_context(|| format!("--port wants a number from 0 to 65535, got {number:?}")),
        [other, ..] => bail!("unknown serve option {other:?}; try --port N"),
    }
}

/// A static file server on `127.0.0.1`, answering on background threads; stops when dropped.
pub struct StaticServer {
    server: Arc<Server>,
    workers: Vec<JoinHandle<()>>,
    port: u16,
}

impl StaticServer {
    /// Serves `root` on `127.0.0.1:port`; port 0 picks a free one (see [`Self::url`]).
    pub fn start(root: &Path, port: u16) -> anyhow::Result<Self> {
        let root = root
            .canonicalize()
            .with_context(|| format!("{} does not exist; build the page first", root.display()))?;
        let server = Server::http(("127.0.0.1", port))
            .map_err(|err| anyhow!("cannot listen on 127.0.0.1:{port}: {err}"))?;
        let port = server
            .server_addr()
            .to_ip()
            .map(|addr| addr.port())
            .ok_or_else(|| anyhow!("the server has no IP address"))?;
        let server = Arc::new(server);
        let workers = (0..WORKERS)
            .map(|_| {
                let server = Arc::clone(&server);
                let root = root.clone();
                std::thread::spawn(move || {
                    // `recv` fails once `unblock` is called: that ends the worker.
                    while let Ok(request) = server.recv() {
                        respond(&root, request);
                    }
                })
            })
            .collect();
        Ok(Self {
            server,
            workers,
            port,
        })
    }

    /// `http://127.0.0.1:<port>/`.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }

    /// Blocks while the server runs (until the process is interrupted).
    pub fn wait(mut self) {
        for worker in std::mem::take(&mut self.workers) {
            // A worker only ends by panicking here; the others keep serving.
            let _ = worker.join();
        }
    }
}

impl Drop for StaticServer {
    fn drop(&mut self) {
        for _ in &self.workers {
            self.server.unblock();
        }
        for worker in self.workers.drain(..) {
            let _ = worker.join();
        }
    }
}

fn respond(root: &Path, request: Request) {
    let result = match answer(root, &request) {
        Answer::File {
            file,
            mime,
            gzipped,
        } => {
            let mut response = Response::from_file(file)
                .with_header(header("Content-Type", mime))
                .with_header(header("Cache-Control", "no-cache"))
                .with_header(header("Vary", "Accept-Encoding"));
            if gzipped {
                response.add_header(header("Content-Encoding", "gzip"));
            }
            request.respond(response)
        }
        Answer::Status(code) => {
            let response = Response::from_string(format!("{code}\n"))
                .with_status_code(code)
                .with_header(header("Content-Type", "text/plain; charset=utf-8"))
                .with_header(header("Cache-Control", "no-cache"));
            request.respond(response)
        }
    };
    // An error means the client went away; nothing to do about it.
    let _ = result;
}

enum Answer {
    File {
        file: File,
        mime: &'static str,
        gzipped: bool,
    },
    Status(u16),
}

fn answer(root: &Path, request: &Request) -> Answer {
    if !matches!(request.method(), Method::Get | Method::Head) {
        return Answer::Status(405);
    }
    let Some(path) = resolve(root, request.url()) else {
        return Answer::Status(404);
    };
    let mime = mime_type(&path);
    let accepts_gzip = request
        .headers()
        .iter()
        .filter(|h| h.field.equiv("Accept-Encoding"))
        .any(|h| accepts_gzip(h.value.as_str()));
    if accepts_gzip {
        let mut gz = path.clone().into_os_string();
        gz.push(".gz");
        if let Ok(file) = File::open(&gz) {
            return Answer::File {
                file,
                mime,
                gzipped: true,
            };
        }
    }
    match File::open(&path) {
        Ok(file) => Answer::File {
            file,
            mime,
            gzipped: false,
        },
        Err(_) => Answer::Status(404),
    }
}

/// The file under `root` that `url` names, or `None` if there is none or it would leave `root`.
fn resolve(root: &Path, url: &str) -> Option<PathBuf> {
    let path = url.split(['?', '#']).next().unwrap_or_default();
    let path = percent_decode(path)?;
    let mut file = root.to_path_buf();
    for segment in path.split('/').filter(|segment| !segment.is_empty()) {
        // Also refuses `.` and `..`, and hidden files such as build caches.
        if segment.starts_with('.') || segment.contains(['\\', '\0', ':']) {
            return None;
        }
        file.push(segment);
    }
    if path.ends_with('/') || file == root {
        file.push("index.html");
    }
    // Symlinks must not lead out of the root either.
    let file = file.canonicalize().ok()?;
    (file.starts_with(root) && file.is_file()).then_some(file)
}

fn percent_decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

/// Whether an `Accept-Encoding` value allows gzip (`gzip`, `gzip;q=0.5`, `*`; not `gzip;q=0`).
fn accepts_gzip(accept_encoding: &str) -> bool {
    accept_encoding.split(',').any(|coding| {
        let mut parts = coding.split(';').map(str::trim);
        let name = parts.next().unwrap_or_default();
        let refused = parts.any(|param| {
            param
                .strip_prefix("q=")
                .and_then(|q| q.parse::<f32>().ok())
                .is_some_and(|q| q <= 0.0)
        });
        (name.eq_ignore_ascii_case("gzip") || name == "*") && !refused
    })
}

fn mime_type(path: &Path) -> &'static str {
    let extension = path
        .extension()
        .and_then(|ext| ext.to_str())
        .unwrap_or_default()
        .to_ascii_lowercase();
    match extension.as_str() {
        "html" | "htm" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript",
        "wasm" => "application/wasm",
        "css" => "text/css; charset=utf-8",
        "json" | "map" => "application/json",
        "webmanifest" => "application/manifest+json",
        "png" => "image/png",
        "jpg" | "jpeg" => "image/jpeg",
        "svg" => "image/svg+xml",
        "ico" => "image/x-icon",
        "glb" => "model/gltf-binary",
        "gltf" => "model/gltf+json",
        "txt" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

fn header(field: &str, value: &str) -> Header {
    // Both are ASCII literals or MIME types from `mime_type`: always a valid header.
    Header::from_bytes(field.as_bytes(), value.as_bytes())
        .unwrap_or_else(|()| unreachable!("invalid header {field}: {value}"))
}

#[cfg(test)]
mod tests {
    use std::io::{Read as _, Write as _};
    use std::net::TcpStream;

    use super::*;

    fn fixture_root(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("xtask-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("dist").join("sub")).unwrap();
        std::fs::write(dir.join("secret.txt"), "outside").unwrap();
        let dist = dir.join("dist");
        std::fs::write(dist.join("index.html"), "<p>hi</p>").unwrap();
        std::fs::write(dist.join("app.wasm"), b"\0asm\x01\0\0\0").unwrap();
        std::fs::write(dist.join("app.js"), "plain js").unwrap();
        std::fs::write(dist.join("app.js.gz"), "pretend gzip").unwrap();
        std::fs::write(dist.join("sub").join("a b.json"), "{}").unwrap();
        dist.canonicalize().unwrap()
    }

    fn get(port: u16, path: &str, accept_encoding: Option<&str>) -> (String, Vec<u8>) {
        let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
        let encoding = accept_encoding
            .map(|value| format!("Accept-Encoding: {value}\r\n"))
            .unwrap_or_default();
        write!(
            stream,
            "GET {path} HTTP/1.1\r\nHost: localhost\r\n{encoding}Connection: close\r\n\r\n"
        )
        .unwrap();
        let mut raw = Vec::new();
        stream.read_to_end(&mut raw).unwrap();
        let split = raw.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
        let head = String::from_utf8(raw[..split].to_vec()).unwrap();
        (head, raw[split + 4..].to_vec())
    }

    #[test]
    fn resolve_stays_inside_the_root() {
        let root = fixture_root("resolve");
        assert_eq!(resolve(&root, "/"), Some(root.join("index.html")));
        assert_eq!(resolve(&root, "/app.js?v=2"), Some(root.join("app.js")));
        assert_eq!(
            resolve(&root, "/sub/a%20b.json"),
            Some(root.join("sub").join("a b.json"))
        );
        assert_eq!(resolve(&root, "/../secret.txt"), None);
        assert_eq!(resolve(&root, "/%2e%2e/secret.txt"), None);
        assert_eq!(resolve(&root, "/sub/..%2f..%2fsecret.txt"), None);
        assert_eq!(resolve(&root, "/..\\secret.txt"), None);
        assert_eq!(resolve(&root, "/missing.js"), None);
        assert_eq!(resolve(&root, "/sub"), None);
        assert_eq!(resolve(&root, "/%zz"), None);
        std::fs::remove_dir_all(root.parent().unwrap()).unwrap();
    }

    #[test]
    fn serve_options_parse() {
        assert_eq!(parse_options(&[]).unwrap(), 8080);
        assert_eq!(parse_options(&["--port", "9000"]).unwrap(), 9000);
        assert!(parse_options(&["--port", "9000", "--release"]).is_err());
        assert!(parse_options(&["--port", "x"]).is_err());
        assert!(parse_options(&["--port"]).is_err());
        assert!(parse_options(&["--fast"]).is_err());
    }

    #[test]
    fn gzip_acceptance_follows_q_values() {
        assert!(accepts_gzip("gzip, deflate, br, zstd"));
        assert!(accepts_gzip("br;q=1.0, GZIP;q=0.5"));
        assert!(accepts_gzip("*"));
        assert!(!accepts_gzip("gzip;q=0"));
        assert!(!accepts_gzip("br, deflate"));
        assert!(!accepts_gzip(""));
    }

    #[test]
    fn serves_files_with_types_gzip_and_404s() {
        let root = fixture_root("serve");
        let server = StaticServer::start(&root, 0).unwrap();
        let port = server.port;
        assert_ne!(port, 0);
        assert_eq!(server.url(), format!("http://127.0.0.1:{port}/"));

        let (head, body) = get(port, "/", None);
        assert!(head.starts_with("HTTP/1.1 200"), "{head}");
        assert!(
            head.contains("Content-Type: text/html; charset=utf-8"),
            "{head}"
        );
        assert!(head.contains("Cache-Control: no-cache"), "{head}");
        assert_eq!(body, b"<p>hi</p>");

        let (head, body) = get(port, "/app.wasm", Some("gzip"));
        assert!(head.contains("Content-Type: application/wasm"), "{head}");
        assert!(!head.contains("Content-Encoding"), "no .gz exists: {head}");
        assert_eq!(body, b"\0asm\x01\0\0\0");

        let (head, body) = get(port, "/app.js", Some("gzip, deflate"));
        assert!(head.contains("Content-Type: text/javascript"), "{head}");
        assert!(head.contains("Content-Encoding: gzip"), "{head}");
        assert_eq!(body, b"pretend gzip");

        let (head, body) = get(port, "/app.js", None);
        assert!(!head.contains("Content-Encoding"), "{head}");
        assert_eq!(body, b"plain js");

        let (head, _) = get(port, "/../secret.txt", None);
        assert!(head.starts_with("HTTP/1.1 404"), "{head}");
        let (head, _) = get(port, "/favicon.ico", None);
        assert!(head.starts_with("HTTP/1.1 404"), "{head}");
        drop(server);
        std::fs::remove_dir_all(root.parent().unwrap()).unwrap();
    }
}
