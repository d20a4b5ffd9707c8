//! `cargo xtask docs`: every path and item that `ARCHITECTURE.md` and `docs/guide.md` name in
//! backticks exists, so the docs cannot drift from the code unnoticed; and the landing page and
//! the architecture stay short enough to be read to the end ([`LENGTH_LIMITS`]).
//!
//! The rule, code span by code span (text between matching runs of backticks; fenced code blocks
//! and HTML comments are not read, so an `<!-- INTEGRATOR: ... -->` note may name what is still
//! to come). A span of the form `a::{b, c}` is read as `a::b` and `a::c`. Then each is:
//!
//! 1. **Skipped** when it is plainly not a name of this repository: it holds a space (a command
//!    such as `cargo xtask test`, a phrase, a formula), `://` (a URL), `<`, `>` or `*` (a
//!    placeholder or a generic type), or it starts with `.` (a file kind such as `.glb`), `-` (a
//!    flag) or `std::`.
//! 2. **A path** when it contains `/` or ends in one of [`PATH_EXTENSIONS`]: it must exist
//!    relative to the repository root, or, for a path relative to a crate's sources such as
//!    `document/edit.rs`, under some `crates/*/src/`. A trailing `/` and a `#anchor` are
//!    ignored.
//! 3. **An item** when it is a Rust path (`ident` or `ident::ident…`, optionally followed by a
//!    call's parentheses such as `Editor::begin(op)` or `finish()`): each segment must be
//!    defined somewhere in `crates/*/src` (see [`Definitions`]), after a leading crate name
//!    (`core`, `app`, `cli`, `xtask`, `sketchmesh_core`, `crate`) is dropped. A bare word
//!    without parentheses is checked only when it looks like a type or a constant: it starts
//!    with a capital and has a lower-case letter (`ToolSet`, `SpdSystem`) and is not a key name
//!    ([`KEY_NAMES`]), or it is upper case with an underscore (`FRAME_BUDGET_MS`). Other bare
//!    words (an op's name in a session such as `cut`, a module in prose, a key such as `J`, an
//!    acronym) are skipped.
//! 4. Anything else (JSON such as `"path"`, `window.sketchmesh`, `Ctrl+Z`) is skipped.

use std::collections::HashSet;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context as _, bail};

use crate::Workspace;

/// The documents whose backticks are checked, relative to the repository root.
pub const CHECKED_DOCS: [&str; 2] = ["ARCHITECTURE.md", "docs/guide.md"];

/// Documents with a length a reader finishes, in characters (issue 48): the README is a landing
/// page, ARCHITECTURE.md what changes rarely.
pub const LENGTH_LIMITS: [(&str, usize); 2] = [("README.md", 8_000), ("ARCHITECTURE.md", 15_000)];

/// Endings that make a span without `/` a file name.
pub const PATH_EXTENSIONS: [&str; 12] = [
    ".rs",
    ".md",
    ".toml",
    ".js",
    ".mjs",
    ".html",
    ".wgsl",
    ".css",
    ".ttf",
    ".txt",
    ".yml",
    ".webmanifest",
];

/// Capitalized words that are keys, not types.
pub const KEY_NAMES: [&str; 9] = [
    "Esc",
    "Enter",
    "Delete",
    "Backspace",
    "Home",
    "Tab",
    "Space",
    "Shift",
    "Ctrl",
];

/// Leading segments that name a crate rather than an item in it.
const CRATE_NAMES: [&str; 6] = ["core", "app", "cli", "xtask", "sketchmesh_core", "crate"];

/// Runs the check on [`CHECKED_DOCS`]; fails with one line per name that does not exist.
pub fn docs_command(workspace: &Workspace) -> anyhow::Result<()> {
    let root = &workspace.root;
    let definitions = Definitions::scan(root)?;
    let mut problems = Vec::new();
    let mut checked = 0;
    for doc in CHECKED_DOCS {
        let text = fs::read_to_string(root.join(doc)).with_context(|| format!("reading {doc}"))?;
        for (line, span) in code_spans(&text) {
            for reference in references(&span) {
                checked += 1;
                if let Some(problem) = reference.missing(root, &definitions) {
                    problems.push(format!("{doc}:{line}: `{span}`: {problem}"));
                }
            }
        }
    }
    for (doc, limit) in LENGTH_LIMITS {
        let text = fs::read_to_string(root.join(doc)).with_context(|| format!("reading {doc}"))?;
        let length = text.chars().count();
        if length > limit {
            problems.push(format!(
                "{doc} is {length} characters, over its {limit}: move what changes often or \
                 serves one reader elsewhere (the guide, BENCHMARKS.md)"
            ));
        }
    }
    if !problems.is_empty() {
        bail!(
            "{} name(s) in backticks do not exist, or documents are too long (rule: crates/xtask/src/doc_check.rs):\n{}",
            problems.len(),
            problems.join("\n")
        );
    }
    println!("xtask: docs: {checked} paths and items named in backticks exist");
    Ok(())
}

/// A name in the docs that must exist.
#[derive(Debug, PartialEq, Eq)]
pub enum Reference {
    /// A file or folder.
    Path(String),
    /// A Rust item, as its path's segments (crate name dropped).
    Item(Vec<String>),
}

impl Reference {
    /// Why it does not exist, or `None` when it does.
    pub fn missing(&self, root: &Path, definitions: &Definitions) -> Option<String> {
        match self {
            Reference::Path(path) => (!path_exists(root, path))
                .then(|| format!("no file or folder {path} at the root or under a crates/*/src/")),
            Reference::Item(segments) => {
                let undefined: Vec<&str> = segments
                    .iter()
                    .filter(|segment| !definitions.defines(segment))
                    .map(String::as_str)
                    .collect();
                (!undefined.is_empty())
                    .then(|| format!("not defined in crates/*/src: {}", undefined.join(", ")))
            }
        }
    }
}

fn path_exists(root: &Path, path: &str) -> bool {
    root.join(path).exists()
        || crate_sources(root)
            .iter()
            .any(|src| src.join(path).exists())
}

/// `crates/*/src`.
fn crate_sources(root: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(root.join("crates")) else {
        return Vec::new();
    };
    entries
        .filter_map(Result::ok)
        .map(|entry| entry.path().join("src"))
        .filter(|src| src.is_dir())
        .collect()
}

/// The code spans of a Markdown text with their line numbers, outside fenced blocks and HTML
/// comments; a span's line breaks read as spaces.
pub fn code_spans(text: &str) -> Vec<(usize, String)> {
    let readable = blank_unread_parts(text);
    let bytes = readable.as_bytes();
    let mut spans = Vec::new();
    let mut at = 0;
    while at < bytes.len() {
        if bytes[at] != b'`' {
            at += 1;
            continue;
        }
        let run = backtick_run(bytes, at);
        let content_start = at + run;
        let Some(end) = closing_run(bytes, content_start, run) else {
            at = content_start;
            continue;
        };
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        let content = readable[content_start..end].replace('\n', " ");
        spans.push((line, content.trim().to_owned()));
        at = end + run;
    }
    spans
}

fn backtick_run(bytes: &[u8], from: usize) -> usize {
    bytes[from..].iter().take_while(|&&b| b == b'`').count()
}

/// Where the next run of exactly `run` backticks after `from` starts.
fn closing_run(bytes: &[u8], from: usize, run: usize) -> Option<usize> {
    let mut at = from;
    while at < bytes.len() {
        if bytes[at] == b'`' {
            let length = backtick_run(bytes, at);
            if length == run {
                return Some(at);
            }
            at += length;
        } else {
            at += 1;
        }
    }
    None
}

/// The text with fenced code blocks and HTML comments turned into spaces, its line breaks kept.
fn blank_unread_parts(text: &str) -> String {
    let mut kept = String::with_capacity(text.len());
    let mut in_fence = false;
    for line in text.split_inclusive('\n') {
        let fence = line.trim_start().starts_with("```");
        if in_fence || fence {
            kept.push_str(&blank(line));
        } else {
            kept.push_str(line);
        }
        if fence {
            in_fence = !in_fence;
        }
    }
    let mut out = String::with_capacity(kept.len());
    let mut rest = kept.as_str();
    while let Some(start) = rest.find("<!--") {
        out.push_str(&rest[..start]);
        let end = rest[start..]
            .find("-->")
            .map_or(rest.len(), |end| start + end + 3);
        out.push_str(&blank(&rest[start..end]));
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

fn blank(text: &str) -> String {
    text.chars()
        .map(|c| if c == '\n' { '\n' } else { ' ' })
        .collect()
}

/// What a code span names that must exist, by the rule of the module's doc.
pub fn references(span: &str) -> Vec<Reference> {
    if span.contains("://") {
        return Vec::new();
    }
    expand_braces(span)
        .iter()
        .filter_map(|name| reference(name))
        .collect()
}

/// `a::{b, c}` -> `a::b`, `a::c`; anything else as it is.
fn expand_braces(span: &str) -> Vec<String> {
    match (span.find('{'), span.strip_suffix('}')) {
        (Some(open), Some(body)) if span.starts_with(|c: char| c.is_alphanumeric()) => body
            [open + 1..]
            .split(',')
            .map(|part| format!("{}{}", &span[..open], part.trim()))
            .collect(),
        _ => vec![span.to_owned()],
    }
}

fn reference(name: &str) -> Option<Reference> {
    let plainly_not_a_name = name.is_empty()
        || name.contains(char::is_whitespace)
        || name.contains(['<', '>', '*'])
        || name.starts_with(['.', '-'])
        || name.starts_with("std::");
    if plainly_not_a_name {
        return None;
    }
    if name.contains('/') || PATH_EXTENSIONS.iter().any(|ext| name.ends_with(ext)) {
        return path_reference(name);
    }
    item_reference(name)
}

fn path_reference(name: &str) -> Option<Reference> {
    let path = name.split('#').next().unwrap_or(name).trim_end_matches('/');
    let path_like = path
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '/'));
    (path_like && !path.is_empty()).then(|| Reference::Path(path.to_owned()))
}

fn item_reference(name: &str) -> Option<Reference> {
    let (path, called) = match name.find('(') {
        Some(open) if name.ends_with(')') => (&name[..open], true),
        _ => (name, false),
    };
    let mut segments: Vec<&str> = path.split("::").collect();
    if !segments.iter().all(|segment| is_identifier(segment)) {
        return None;
    }
    if segments.len() > 1 && CRATE_NAMES.contains(&segments[0]) {
        segments.remove(0);
    }
    let checked = called || segments.len() > 1 || looks_like_type_or_const(segments[0]);
    checked.then(|| Reference::Item(segments.iter().map(|s| (*s).to_owned()).collect()))
}

fn is_identifier(text: &str) -> bool {
    let mut chars = text.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

fn looks_like_type_or_const(word: &str) -> bool {
    let starts_upper = word.starts_with(|c: char| c.is_ascii_uppercase());
    let has_lower = word.contains(|c: char| c.is_ascii_lowercase());
    let type_name = starts_upper && has_lower && !KEY_NAMES.contains(&word);
    let constant = word.contains('_') && !has_lower;
    type_name || constant
}

/// Every name defined in `crates/*/src`: a name counts as defined when a line of Rust declares
/// it after `fn`, `struct`, `enum`, `trait`, `type`, `const`, `static`, `union` or `mod`, when
/// it begins a line one indentation step inside an `enum`'s body (a variant), or when it is a
/// `name:` line one step inside a `struct`'s body (a field). The sources are `rustfmt`ed (CI
/// checks it), so a body's lines sit one step (four spaces) in from its header.
#[derive(Debug, Default)]
pub struct Definitions {
    names: HashSet<String>,
}

impl Definitions {
    /// Reads every `.rs` file under `crates/*/src`.
    pub fn scan(root: &Path) -> anyhow::Result<Self> {
        let mut definitions = Self::default();
        let mut folders = crate_sources(root);
        while let Some(folder) = folders.pop() {
            let entries =
                fs::read_dir(&folder).with_context(|| format!("listing {}", folder.display()))?;
            for entry in entries {
                let path = entry?.path();
                if path.is_dir() {
                    folders.push(path);
                } else if path.extension().is_some_and(|ext| ext == "rs") {
                    let source = fs::read_to_string(&path)
                        .with_context(|| format!("reading {}", path.display()))?;
                    definitions.add_source(&source);
                }
            }
        }
        Ok(definitions)
    }

    /// Adds the names one Rust file defines.
    pub fn add_source(&mut self, source: &str) {
        // The bodies being read: whether each is an enum's, and its header's indentation.
        let mut bodies: Vec<(bool, usize)> = Vec::new();
        for line in source.lines() {
            let code = line.split("//").next().unwrap_or("");
            let text = code.trim();
            if text.is_empty() {
                continue;
            }
            let indent = code.len() - code.trim_start().len();
            if let Some(&(is_enum, header)) = bodies.last() {
                if indent == header && text.starts_with('}') {
                    bodies.pop();
                    continue;
                }
                if indent == header + 4 {
                    self.add_member(text, is_enum);
                }
            }
            let words: Vec<&str> = text
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .filter(|word| !word.is_empty())
                .collect();
            for pair in words.windows(2) {
                let keyword = matches!(
                    pair[0],
                    "fn" | "struct"
                        | "enum"
                        | "trait"
                        | "type"
                        | "const"
                        | "static"
                        | "union"
                        | "mod"
                );
                if keyword && is_identifier(pair[1]) {
                    self.names.insert(pair[1].to_owned());
                }
            }
            let opens_body = text.ends_with('{')
                && words.iter().any(|word| matches!(*word, "enum" | "struct"))
                && !text.contains("impl");
            if opens_body {
                bodies.push((words.contains(&"enum"), indent));
            }
        }
    }

    fn add_member(&mut self, text: &str, in_enum: bool) {
        let text = strip_visibility(text);
        let name: String = text
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect();
        if !is_identifier(&name) {
            return;
        }
        let rest = &text[name.len()..];
        let member = if in_enum {
            rest.is_empty() || rest.starts_with([',', '(', ' ', '{', '='])
        } else {
            rest.starts_with(':') && !rest.starts_with("::")
        };
        if member {
            self.names.insert(name);
        }
    }

    /// Whether `name` is defined.
    pub fn defines(&self, name: &str) -> bool {
        self.names.contains(name)
    }
}

/// `pub x`, `pub(crate) x` -> `x`.
fn strip_visibility(text: &str) -> &str {
    let Some(rest) = text.strip_prefix("pub") else {
        return text;
    };
    let rest = match rest.strip_prefix('(') {
        Some(inner) => inner.find(')').map_or(rest, |close| &inner[close + 1..]),
        None => rest,
    };
    rest.trim_start()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn workspace_root() -> PathBuf {
        Workspace::locate().root
    }

    fn spans(text: &str) -> Vec<String> {
        code_spans(text).into_iter().map(|(_, span)| span).collect()
    }

    #[test]
    fn spans_skip_fences_and_comments_and_keep_line_numbers() {
        let text = "one `a.rs`\n```\n`in_fence.rs`\n```\n<!-- `in_comment.rs`\n-->\n``b `x` c``\n";
        assert_eq!(
            code_spans(text),
            vec![(1, "a.rs".to_owned()), (7, "b `x` c".to_owned())]
        );
        assert_eq!(spans("an unclosed `` run and `c::D`"), ["c::D"]);
    }

    #[test]
    fn commands_keys_and_words_are_not_checked() {
        for span in [
            "cargo xtask test",
            "J",
            "Esc",
            "Ctrl+Z",
            "cut",
            "https://example.com/a.rs",
            ".glb",
            "\"path\"",
            "Arc<Model>",
            "crates/app/src/tools/<name>/mod.rs",
            "w ⊙ T",
            "12",
        ] {
            assert_eq!(references(span), [], "{span}");
        }
    }

    #[test]
    fn paths_and_items_are_told_apart() {
        assert_eq!(
            references("document/edit.rs"),
            [Reference::Path("document/edit.rs".to_owned())]
        );
        assert_eq!(
            references("crates/core/tests/fixtures/"),
            [Reference::Path("crates/core/tests/fixtures".to_owned())]
        );
        assert_eq!(
            references("core::document::Editor::begin(op)"),
            [Reference::Item(vec![
                "document".into(),
                "Editor".into(),
                "begin".into()
            ])]
        );
        assert_eq!(
            references("finish()"),
            [Reference::Item(vec!["finish".into()])]
        );
        assert_eq!(
            references("core::fibermesh::{triangulate, inflate}"),
            [
                Reference::Item(vec!["fibermesh".into(), "triangulate".into()]),
                Reference::Item(vec!["fibermesh".into(), "inflate".into()]),
            ]
        );
        assert_eq!(
            references("FRAME_BUDGET_MS"),
            [Reference::Item(vec!["FRAME_BUDGET_MS".into()])]
        );
    }

    #[test]
    fn a_missing_path_is_caught_and_an_existing_one_passes() {
        let root = workspace_root();
        let none = Definitions::default();
        assert_eq!(
            Reference::Path("crates/xtask/src/main.rs".into()).missing(&root, &none),
            None
        );
        // Relative to a crate's sources.
        assert_eq!(
            Reference::Path("doc_check.rs".into()).missing(&root, &none),
            None
        );
        assert!(
            Reference::Path("crates/xtask/src/no_such_file.rs".into())
                .missing(&root, &none)
                .is_some()
        );
    }

    #[test]
    fn definitions_hold_items_variants_and_fields() {
        let mut definitions = Definitions::default();
        definitions.add_source(
            "pub struct Editor {\n    pub history: Vec<u8>,\n    revision: u64,\n}\n\
             impl Editor {\n    pub fn begin(&mut self) {}\n    const fn quiet() {}\n}\n\
             pub(crate) enum Op {\n    /// Doc.\n    Create { stroke: u8 },\n    Cut(u8),\n    Undo,\n}\n\
             mod nested;\n// fn commented_out() {}\n",
        );
        for name in [
            "Editor", "history", "revision", "begin", "quiet", "Op", "Create", "Cut", "Undo",
            "nested",
        ] {
            assert!(definitions.defines(name), "{name}");
        }
        for name in ["stroke", "commented_out", "u8"] {
            assert!(!definitions.defines(name), "{name}");
        }
        let root = workspace_root();
        assert_eq!(
            Reference::Item(vec!["Op".into(), "Cut".into()]).missing(&root, &definitions),
            None
        );
        assert!(
            Reference::Item(vec!["Op".into(), "Stroke".into()])
                .missing(&root, &definitions)
                .is_some()
        );
    }

    #[test]
    fn the_real_sources_define_the_editor() {
        let definitions = Definitions::scan(&workspace_root()).unwrap();
        for name in ["Editor", "begin", "docs_command", "Reference", "Path"] {
            assert!(definitions.defines(name), "{name}");
        }
    }
}
