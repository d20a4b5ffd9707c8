//! `cargo xtask layers`: the import rules ARCHITECTURE.md states, checked against the code.
//!
//! ARCHITECTURE.md holds, between [`BLOCK_START`] and [`BLOCK_END`], one table per crate (under
//! a heading naming the crate's folder in backticks): each row a layer, its top-level modules
//! in backticks and what they may import besides themselves: modules in backticks, and layers
//! by name in italics (`*ground*`: all of its modules). Rows run from the bottom layer up, and a row imports
//! only from rows listed before it, so the table itself has no circle.
//!
//! The check reads the files each crate compiles outside tests (its module tree from
//! `lib.rs`, `#[cfg(test)]` and `#[cfg(doc)]` items and modules left out) with `syn`, resolves
//! every `use` path and every `crate::`, `super::` and `self::` path in code (and paths through
//! a module a `use` named) to the file that defines the item, following re-exports, and fails on an import between
//! top-level modules that the table does not allow and on any circle of files. A `pub use`
//! that only re-exports is no import of the file that makes it; one whose name the file's own
//! code uses is. Paths inside macro calls are not seen (`syn` leaves their tokens unparsed).

use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::fs;

use anyhow::{Context as _, bail};
use syn::visit::{self, Visit};

use crate::Workspace;

/// The line that opens the tables in ARCHITECTURE.md.
pub const BLOCK_START: &str = "<!-- layers: checked by cargo xtask layers -->";
/// The line that closes them.
pub const BLOCK_END: &str = "<!-- /layers -->";
/// The crates whose imports are checked, by folder.
const CHECKED: [&str; 2] = ["crates/core", "crates/app"];

/// Checks both crates against ARCHITECTURE.md's tables; fails with every breach and circle.
pub fn layers_command(workspace: &Workspace) -> anyhow::Result<()> {
    let doc_path = workspace.root.join("ARCHITECTURE.md");
    let doc =
        fs::read_to_string(&doc_path).with_context(|| format!("reading {}", doc_path.display()))?;
    let tables = parse_tables(&doc).context("ARCHITECTURE.md's layer tables")?;
    let mut problems = Vec::new();
    for dir in CHECKED {
        let Some(table) = tables.iter().find(|t| t.dir == dir) else {
            bail!(
                "ARCHITECTURE.md has no layer table for `{dir}` between {BLOCK_START} and {BLOCK_END}"
            );
        };
        let src = workspace.root.join(dir).join("src");
        let code = CrateCode::read(&format!("{dir}/src"), |file| {
            fs::read_to_string(src.join(file)).ok()
        })?;
        let found = check(table, &code);
        println!(
            "xtask: {dir}: {} files, {} imports between files: {}",
            code.files.len(),
            code.edges.len(),
            if found.is_empty() {
                "as the layer table says, no circle".to_owned()
            } else {
                format!("{} problems", found.len())
            }
        );
        problems.extend(found);
    }
    if problems.is_empty() {
        return Ok(());
    }
    for problem in &problems {
        eprintln!("\n{problem}");
    }
    bail!(
        "{} imports break the layer rules (ARCHITECTURE.md, \"Layers\"), or files import each other",
        problems.len()
    )
}

/// One crate's layer table.
#[derive(Debug)]
pub struct Table {
    /// The crate's folder, as the heading names it: `crates/core`.
    pub dir: String,
    /// The layer of each module: its name and its row's index, bottom row first.
    layer_of: BTreeMap<String, (String, usize)>,
    /// What each module may import besides itself.
    allowed: BTreeMap<String, BTreeSet<String>>,
}

/// One row as written.
struct Row {
    layer: String,
    modules: Vec<String>,
    /// Modules it may import, and layers (all of their modules).
    imports: Vec<String>,
    layers: Vec<String>,
}

/// The texts in italics (`*ground*`, not in backticks) in `cell`.
fn italic(cell: &str) -> Vec<String> {
    (cell.split('`').step_by(2))
        .flat_map(|text| text.split('*').skip(1).step_by(2))
        .map(|s| s.trim().to_owned())
        .filter(|s| !s.is_empty())
        .collect()
}

/// The texts in backticks in `cell`.
fn backticked(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .map(|s| s.trim().to_owned())
        .collect()
}

/// The tables of ARCHITECTURE.md's layer block; see the module docs for their form.
pub fn parse_tables(doc: &str) -> anyhow::Result<Vec<Table>> {
    let start = doc
        .find(BLOCK_START)
        .with_context(|| format!("no line {BLOCK_START}"))?;
    let end = doc[start..]
        .find(BLOCK_END)
        .with_context(|| format!("no {BLOCK_END} after {BLOCK_START}"))?;
    let mut written: Vec<(String, Vec<Row>, bool)> = Vec::new();
    for line in doc[start + BLOCK_START.len()..start + end].lines() {
        let line = line.trim();
        if line.starts_with('#') {
            if let Some(dir) = backticked(line)
                .into_iter()
                .find(|t| t.starts_with("crates/"))
            {
                written.push((dir, Vec::new(), false));
            }
            continue;
        }
        if !line.starts_with('|') {
            continue;
        }
        let Some((dir, rows, header_seen)) = written.last_mut() else {
            bail!("a table row before any heading naming a crate: {line}");
        };
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        if cells.iter().all(|c| c.chars().all(|ch| "-: ".contains(ch))) {
            continue;
        }
        if !*header_seen {
            *header_seen = true;
            continue;
        }
        let [layer, modules, imports] = cells[..] else {
            bail!("`{dir}`: a row needs three cells (layer, modules, may import): {line}");
        };
        rows.push(Row {
            layer: layer.trim_matches('*').to_owned(),
            modules: backticked(modules),
            imports: backticked(imports),
            layers: italic(imports),
        });
    }
    if written.is_empty() {
        bail!("no table between {BLOCK_START} and {BLOCK_END}");
    }
    written
        .into_iter()
        .map(|(dir, rows, _)| Table::from_rows(dir, &rows))
        .collect()
}

impl Table {
    fn from_rows(dir: String, rows: &[Row]) -> anyhow::Result<Table> {
        let mut layer_of = BTreeMap::new();
        for (index, row) in rows.iter().enumerate() {
            if row.modules.is_empty() {
                bail!("`{dir}`: the row of layer {} names no module", row.layer);
            }
            for module in &row.modules {
                if layer_of
                    .insert(module.clone(), (row.layer.clone(), index))
                    .is_some()
                {
                    bail!("`{dir}`: `{module}` is in two rows");
                }
            }
        }
        let mut allowed = BTreeMap::new();
        for (index, row) in rows.iter().enumerate() {
            let mut imports = BTreeSet::new();
            let mut named: Vec<&String> = Vec::new();
            for name in &row.imports {
                if !layer_of.contains_key(name) {
                    bail!(
                        "`{dir}`: the row of {} lets it import `{name}`, which is no module of \
                         the table (write reasons without backticks)",
                        row.modules.join(", ")
                    );
                }
                named.push(name);
            }
            for name in &row.layers {
                let before = named.len();
                named.extend(
                    (layer_of.iter())
                        .filter(|(_, (layer, _))| layer == name)
                        .map(|(module, _)| module),
                );
                if named.len() == before {
                    bail!(
                        "`{dir}`: the row of {} lets it import the layer *{name}*, which is no \
                         layer of the table (write reasons without italics)",
                        row.modules.join(", ")
                    );
                }
            }
            for module in named {
                if layer_of[module].1 >= index {
                    bail!(
                        "`{dir}`: the row of {} lets it import `{module}`, which is not in a row \
                         before it: the table must list layers from the bottom up",
                        row.modules.join(", ")
                    );
                }
                imports.insert(module.clone());
            }
            for module in &row.modules {
                allowed.insert(module.clone(), imports.clone());
            }
        }
        Ok(Table {
            dir,
            layer_of,
            allowed,
        })
    }
}

/// A module path inside a crate: `["document", "outcome"]`; the root is empty.
type ModPath = Vec<String>;

/// A `use` as flattened from its tree.
#[derive(Debug)]
struct UseItem {
    /// The path as written, with the last name for a name (`self` dropped).
    segments: Vec<String>,
    /// The name it binds (the rename if any); empty for a glob.
    name: String,
    glob: bool,
    /// `pub`, `pub(crate)`, …: a re-export.
    public: bool,
}

/// What a module holds that paths resolve through.
#[derive(Debug, Default)]
struct Module {
    file: usize,
    /// Items it defines (functions, types, constants, modules, macros).
    defines: BTreeSet<String>,
    uses: Vec<UseItem>,
}

/// A path of two segments or more in code, where it was written.
#[derive(Debug)]
struct CodePath {
    module: ModPath,
    segments: Vec<String>,
}

/// One source file.
#[derive(Debug)]
struct SourceFile {
    /// Its path as shown: `crates/core/src/io/glb.rs`.
    shown: String,
    /// Its module; empty for the crate root.
    module: ModPath,
    paths: Vec<CodePath>,
    /// Every name a path in its code starts with.
    names_used: BTreeSet<String>,
}

/// One crate's code: its files, its modules, and the imports between files.
pub struct CrateCode {
    files: Vec<SourceFile>,
    modules: BTreeMap<ModPath, Module>,
    /// Imports between files (importer, imported) with one path that makes each.
    edges: BTreeMap<(usize, usize), String>,
}

/// Whether `attrs` hold `#[cfg(test)]` or `#[cfg(doc)]` (an import for a doc link only).
fn is_left_out(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|attr| match &attr.meta {
        syn::Meta::List(list) => {
            list.path.is_ident("cfg") && ["test", "doc"].contains(&list.tokens.to_string().as_str())
        }
        _ => false,
    })
}

fn flatten_use(
    tree: &syn::UseTree,
    prefix: &mut Vec<String>,
    public: bool,
    out: &mut Vec<UseItem>,
) {
    let item = |segments: Vec<String>, name: String, glob| UseItem {
        segments,
        name,
        glob,
        public,
    };
    match tree {
        syn::UseTree::Path(path) => {
            prefix.push(path.ident.to_string());
            flatten_use(&path.tree, prefix, public, out);
            prefix.pop();
        }
        syn::UseTree::Name(name) => {
            let ident = name.ident.to_string();
            let mut segments = prefix.clone();
            if ident != "self" {
                segments.push(ident);
            }
            let bound = segments.last().cloned().unwrap_or_default();
            out.push(item(segments, bound, false));
        }
        syn::UseTree::Rename(rename) => {
            let mut segments = prefix.clone();
            if rename.ident != "self" {
                segments.push(rename.ident.to_string());
            }
            out.push(item(segments, rename.rename.to_string(), false));
        }
        syn::UseTree::Glob(_) => out.push(item(prefix.clone(), String::new(), true)),
        syn::UseTree::Group(group) => {
            for tree in &group.items {
                flatten_use(tree, prefix, public, out);
            }
        }
    }
}

/// The file a `#[path = "…"]` attribute names, if there is one.
fn path_attribute(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find_map(|attr| match &attr.meta {
        syn::Meta::NameValue(pair) if pair.path.is_ident("path") => match &pair.value {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(file),
                ..
            }) => Some(file.value()),
            _ => None,
        },
        _ => None,
    })
}

/// Walks one file's syntax tree, filling the crate's modules and the file's paths.
struct Reader<'a> {
    modules: &'a mut BTreeMap<ModPath, Module>,
    file: usize,
    /// The module being read (the file's, then any inline module's).
    module: ModPath,
    paths: Vec<CodePath>,
    names_used: BTreeSet<String>,
    /// Modules declared here whose body is another file, with the file a `#[path]` names.
    file_modules: Vec<(ModPath, Option<String>)>,
}

impl Reader<'_> {
    fn here(&mut self) -> &mut Module {
        let file = self.file;
        self.modules
            .entry(self.module.clone())
            .or_insert_with(|| Module {
                file,
                ..Module::default()
            })
    }

    fn define(&mut self, ident: &syn::Ident) {
        let name = ident.to_string();
        self.here().defines.insert(name);
    }
}

impl<'ast> Visit<'ast> for Reader<'_> {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        use syn::Item;
        let (attrs, ident) = match item {
            Item::Const(i) => (&i.attrs, Some(&i.ident)),
            Item::Enum(i) => (&i.attrs, Some(&i.ident)),
            Item::Fn(i) => (&i.attrs, Some(&i.sig.ident)),
            Item::Macro(i) => (&i.attrs, i.ident.as_ref()),
            Item::Mod(i) => (&i.attrs, Some(&i.ident)),
            Item::Static(i) => (&i.attrs, Some(&i.ident)),
            Item::Struct(i) => (&i.attrs, Some(&i.ident)),
            Item::Trait(i) => (&i.attrs, Some(&i.ident)),
            Item::TraitAlias(i) => (&i.attrs, Some(&i.ident)),
            Item::Type(i) => (&i.attrs, Some(&i.ident)),
            Item::Union(i) => (&i.attrs, Some(&i.ident)),
            Item::Impl(i) => (&i.attrs, None),
            Item::Use(i) => (&i.attrs, None),
            _ => return,
        };
        if is_left_out(attrs) {
            return;
        }
        if let Some(ident) = ident {
            self.define(ident);
        }
        match item {
            Item::Mod(module) => {
                self.module.push(module.ident.to_string());
                match &module.content {
                    Some((_, items)) => {
                        self.here();
                        for item in items {
                            self.visit_item(item);
                        }
                    }
                    None => self
                        .file_modules
                        .push((self.module.clone(), path_attribute(&module.attrs))),
                }
                self.module.pop();
            }
            Item::Use(used) => {
                let public = !matches!(used.vis, syn::Visibility::Inherited);
                if used.leading_colon.is_none() {
                    let mut items = Vec::new();
                    flatten_use(&used.tree, &mut Vec::new(), public, &mut items);
                    self.here().uses.extend(items);
                }
            }
            Item::Macro(_) => {}
            _ => visit::visit_item(self, item),
        }
    }

    fn visit_path(&mut self, path: &'ast syn::Path) {
        if let Some(first) = path.segments.first() {
            self.names_used.insert(first.ident.to_string());
        }
        if path.leading_colon.is_none() && path.segments.len() >= 2 {
            self.paths.push(CodePath {
                module: self.module.clone(),
                segments: path.segments.iter().map(|s| s.ident.to_string()).collect(),
            });
        }
        visit::visit_path(self, path);
    }

    fn visit_attribute(&mut self, _: &'ast syn::Attribute) {}

    fn visit_visibility(&mut self, _: &'ast syn::Visibility) {}
}

impl CrateCode {
    /// Reads the crate whose source folder is shown as `shown_root` (`crates/core/src`),
    /// following its module tree from `lib.rs`; `read` gives a file's text by its path under
    /// that folder.
    pub fn read(
        shown_root: &str,
        read: impl Fn(&str) -> Option<String>,
    ) -> anyhow::Result<CrateCode> {
        let mut code = CrateCode {
            files: Vec::new(),
            modules: BTreeMap::new(),
            edges: BTreeMap::new(),
        };
        let mut queue: VecDeque<(String, ModPath)> = VecDeque::from([("lib.rs".into(), vec![])]);
        while let Some((relative, module)) = queue.pop_front() {
            let text = read(&relative)
                .with_context(|| format!("{shown_root}/{relative}: cannot be read"))?;
            let syntax = syn::parse_file(&text)
                .with_context(|| format!("{shown_root}/{relative}: cannot be parsed"))?;
            let file = code.files.len();
            let mut reader = Reader {
                modules: &mut code.modules,
                file,
                module: module.clone(),
                paths: Vec::new(),
                names_used: BTreeSet::new(),
                file_modules: Vec::new(),
            };
            reader.here();
            for item in &syntax.items {
                reader.visit_item(item);
            }
            // A `mod.rs`, or the root, holds its children beside it; `name.rs` in `name/`.
            let name = relative.rsplit('/').next().unwrap_or_default();
            let folder = match name {
                "lib.rs" | "mod.rs" => relative[..relative.len() - name.len()].to_owned(),
                _ => format!("{}/", relative.trim_end_matches(".rs")),
            };
            for (child, named) in &reader.file_modules {
                // A `#[path]` is relative to the declaring file's own folder (as rustc reads a
                // declaration outside inline modules, the only place this tree uses one).
                let beside = &relative[..relative.len() - name.len()];
                // Inline modules between the file and the declaration are folders too.
                let inner = child[module.len()..].join("/");
                let flat = format!("{folder}{inner}.rs");
                let nested = format!("{folder}{inner}/mod.rs");
                let path = match named {
                    Some(named) => format!("{beside}{named}"),
                    None if read(&flat).is_some() => flat,
                    None => nested,
                };
                queue.push_back((path, child.clone()));
            }
            code.files.push(SourceFile {
                shown: format!("{shown_root}/{relative}"),
                module,
                paths: reader.paths,
                names_used: reader.names_used,
            });
        }
        code.link();
        Ok(code)
    }

    /// Fills `edges`: the imports between files.
    fn link(&mut self) {
        let mut edges = BTreeMap::new();
        let mut add = |from: usize, to: Option<usize>, shown: String| {
            if let Some(to) = to.filter(|&to| to != from) {
                edges.entry((from, to)).or_insert(shown);
            }
        };
        for (path, module) in &self.modules {
            for used in &module.uses {
                let reexport_only =
                    used.public && !self.files[module.file].names_used.contains(&used.name);
                if reexport_only || (!used.glob && self.module_at(path, &used.segments).is_some()) {
                    continue;
                }
                let shown = format!(
                    "use {}{}",
                    used.segments.join("::"),
                    if used.glob { "::*" } else { "" }
                );
                add(module.file, self.resolve(path, &used.segments, 0), shown);
            }
        }
        for (index, file) in self.files.iter().enumerate() {
            for code in &file.paths {
                add(index, self.resolve_code(code), code.segments.join("::"));
            }
        }
        self.edges = edges;
    }

    /// Where a path written in `from` starts: the module and the segments left; `None` for a
    /// path that leaves the crate or starts at an item.
    fn anchor<'p>(
        &self,
        from: &[String],
        segments: &'p [String],
    ) -> Option<(ModPath, &'p [String])> {
        let first = segments.first()?;
        match first.as_str() {
            "crate" => Some((Vec::new(), &segments[1..])),
            "self" => Some((from.to_vec(), &segments[1..])),
            "super" => {
                let ups = segments.iter().take_while(|s| *s == "super").count();
                let kept = from.len().checked_sub(ups)?;
                Some((from[..kept].to_vec(), &segments[ups..]))
            }
            _ => {
                let mut child = from.to_vec();
                child.push(first.clone());
                self.modules
                    .contains_key(&child)
                    .then(|| (from.to_vec(), segments))
            }
        }
    }

    /// The module a path names, when all of it names modules.
    fn module_at(&self, from: &[String], segments: &[String]) -> Option<ModPath> {
        let (mut module, rest) = self.anchor(from, segments)?;
        for segment in rest {
            module.push(segment.clone());
            if !self.modules.contains_key(&module) {
                return None;
            }
        }
        Some(module)
    }

    /// The file that defines what a path names (a module names its own file).
    fn resolve(&self, from: &[String], segments: &[String], depth: usize) -> Option<usize> {
        let (mut module, rest) = self.anchor(from, segments)?;
        let mut rest = rest.iter();
        for segment in rest.by_ref() {
            module.push(segment.clone());
            if !self.modules.contains_key(&module) {
                let name = module.pop()?;
                let found = self.find(&module, &name, depth);
                return Some(found.unwrap_or(self.modules[&module].file));
            }
        }
        Some(self.modules[&module].file)
    }

    /// The file that defines `name` as `module` sees it: its own, or through its `use`s.
    fn find(&self, module: &ModPath, name: &str, depth: usize) -> Option<usize> {
        let here = self.modules.get(module)?;
        if here.defines.contains(name) {
            return Some(here.file);
        }
        if depth > 16 {
            return None;
        }
        let named = here.uses.iter().filter(|u| !u.glob && u.name == name);
        for used in named {
            if let Some(file) = self.resolve(module, &used.segments, depth + 1) {
                return Some(file);
            }
        }
        (here.uses.iter().filter(|u| u.glob))
            .filter_map(|u| self.module_at(module, &u.segments))
            .find_map(|target| self.find(&target, name, depth + 1))
    }

    /// The file a path in code reaches: from `crate`, `super`, `self`, a child module, or a
    /// module a `use` named.
    fn resolve_code(&self, code: &CodePath) -> Option<usize> {
        if let Some(file) = self.resolve(&code.module, &code.segments, 0) {
            return Some(file);
        }
        let module = self.modules.get(&code.module)?;
        let alias = (module.uses.iter())
            .filter(|u| !u.glob && u.name == code.segments[0])
            .find_map(|u| self.module_at(&code.module, &u.segments))?;
        let mut absolute = vec!["crate".to_owned()];
        absolute.extend(alias);
        absolute.extend_from_slice(&code.segments[1..]);
        self.resolve(&[], &absolute, 0)
    }

    /// The top-level module a file belongs to; `None` for the crate root.
    fn top(&self, file: usize) -> Option<&str> {
        self.files[file].module.first().map(String::as_str)
    }
}

/// Every breach of `table` and every circle of files in `code`, each a sentence.
pub fn check(table: &Table, code: &CrateCode) -> Vec<String> {
    let dir = &table.dir;
    let mut problems = Vec::new();
    let in_code: BTreeSet<&str> = (0..code.files.len()).filter_map(|f| code.top(f)).collect();
    for module in &in_code {
        if !table.layer_of.contains_key(*module) {
            problems.push(format!(
                "`{dir}`: the module `{module}` is in no row of the layer table in ARCHITECTURE.md"
            ));
        }
    }
    for module in table.layer_of.keys() {
        if !in_code.contains(module.as_str()) {
            problems.push(format!(
                "`{dir}`: the layer table in ARCHITECTURE.md names `{module}`, which is no module of the crate"
            ));
        }
    }
    let mut reported = BTreeSet::new();
    for (&(from, to), shown) in &code.edges {
        let (Some(importer), Some(imported)) = (code.top(from), code.top(to)) else {
            continue;
        };
        let Some(allowed) = table.allowed.get(importer) else {
            continue;
        };
        if importer != imported && !allowed.contains(imported) && reported.insert((from, imported))
        {
            let (layer, _) = &table.layer_of[importer];
            let may = if allowed.is_empty() {
                "nothing of the crate".to_owned()
            } else {
                let named: Vec<String> = allowed.iter().map(|m| format!("`{m}`")).collect();
                format!("only {}", named.join(", "))
            };
            problems.push(format!(
                "{} imports `{imported}` (`{shown}`, in {}), but the layer table in ARCHITECTURE.md \
                 lets `{importer}` ({layer}) import {may}",
                code.files[from].shown, code.files[to].shown
            ));
        }
    }
    for circle in circles(code) {
        problems.push(circle);
    }
    problems
}

/// The files of `code` that import each other, directly or around a loop: one sentence per
/// group (a strongly connected component), naming its files and one loop with its imports.
fn circles(code: &CrateCode) -> Vec<String> {
    let n = code.files.len();
    let mut out: Vec<Vec<usize>> = vec![Vec::new(); n];
    for &(from, to) in code.edges.keys() {
        out[from].push(to);
    }
    let mut sentences = Vec::new();
    for group in strongly_connected(&out) {
        if group.len() < 2 {
            continue;
        }
        let members: BTreeSet<usize> = group.iter().copied().collect();
        let start = group[0];
        let cycle = shortest_loop(&out, &members, start);
        let mut sentence = format!(
            "files that import each other: {}. A loop: ",
            group
                .iter()
                .map(|&f| code.files[f].shown.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        );
        let steps: Vec<String> = cycle
            .windows(2)
            .map(|pair| {
                format!(
                    "{} imports {} (`{}`)",
                    code.files[pair[0]].shown,
                    code.files[pair[1]].shown,
                    code.edges[&(pair[0], pair[1])]
                )
            })
            .collect();
        sentence.push_str(&steps.join("; "));
        sentence.push_str(". A piece two files share belongs in a third.");
        sentences.push(sentence);
    }
    sentences
}

/// The strongly connected components of a graph (Tarjan's algorithm, iterative), each sorted,
/// in order of their smallest node.
fn strongly_connected(out: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = out.len();
    let mut index = vec![usize::MAX; n];
    let mut low = vec![0; n];
    let mut on_stack = vec![false; n];
    let mut stack = Vec::new();
    let mut groups = Vec::new();
    let mut next = 0;
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        // (node, next edge to follow)
        let mut frames = vec![(root, 0)];
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root);
        on_stack[root] = true;
        while let Some(&mut (node, ref mut edge)) = frames.last_mut() {
            if let Some(&to) = out[node].get(*edge) {
                *edge += 1;
                if index[to] == usize::MAX {
                    index[to] = next;
                    low[to] = next;
                    next += 1;
                    stack.push(to);
                    on_stack[to] = true;
                    frames.push((to, 0));
                } else if on_stack[to] {
                    low[node] = low[node].min(index[to]);
                }
                continue;
            }
            frames.pop();
            if let Some(&(parent, _)) = frames.last() {
                low[parent] = low[parent].min(low[node]);
            }
            if low[node] == index[node] {
                let mut group = Vec::new();
                while let Some(member) = stack.pop() {
                    on_stack[member] = false;
                    group.push(member);
                    if member == node {
                        break;
                    }
                }
                group.sort_unstable();
                groups.push(group);
            }
        }
    }
    groups.sort();
    groups
}

/// A shortest loop from `start` back to it inside `members`: the nodes in order, `start` at
/// both ends.
fn shortest_loop(out: &[Vec<usize>], members: &BTreeSet<usize>, start: usize) -> Vec<usize> {
    let mut came_from = BTreeMap::new();
    let mut queue = VecDeque::from([start]);
    while let Some(node) = queue.pop_front() {
        for &to in &out[node] {
            if !members.contains(&to) || came_from.contains_key(&to) {
                continue;
            }
            came_from.insert(to, node);
            if to == start {
                let mut cycle = vec![start];
                let mut at = node;
                while at != start {
                    cycle.push(at);
                    at = came_from[&at];
                }
                cycle.push(start);
                cycle.reverse();
                return cycle;
            }
            queue.push_back(to);
        }
    }
    vec![start]
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    const TABLE: &str = "
<!-- layers: checked by cargo xtask layers -->
#### `crates/demo`

| layer | modules | may import |
| --- | --- | --- |
| ground | `mesh`, `solve` | nothing of the crate |
| ground | `geometry` | `mesh` and `solve` (its Laplacians are solved) |
| techniques | `deform` | the *ground* layer |
| editing | `document` | *ground*, *techniques* |
<!-- /layers -->
";

    fn table() -> Table {
        parse_tables(TABLE).unwrap().remove(0)
    }

    fn crate_of(files: &[(&str, &str)]) -> CrateCode {
        let files: BTreeMap<String, String> = (files.iter())
            .map(|(path, text)| (path.to_string(), text.to_string()))
            .collect();
        CrateCode::read("src", |path| files.get(path).cloned()).unwrap()
    }

    /// A crate that keeps the table: deform uses geometry through a re-export and a module
    /// path, document uses everything, tests import upward.
    fn clean() -> Vec<(&'static str, &'static str)> {
        vec![
            (
                "lib.rs",
                "pub mod mesh; pub mod solve; pub mod geometry; pub mod deform; pub mod document;",
            ),
            (
                "mesh.rs",
                "pub struct Mesh; #[cfg(test)] mod tests { use crate::deform::Edit; } \
                 #[cfg(doc)] use crate::deform::Edit;",
            ),
            ("solve.rs", "pub fn solve() {}"),
            ("geometry/mod.rs", "mod normals; pub use normals::normals;"),
            (
                "geometry/normals.rs",
                "use crate::mesh::Mesh; pub fn normals(_: &Mesh) { crate::solve::solve() }",
            ),
            (
                "deform.rs",
                "use crate::geometry; pub struct Edit; fn f(m: &crate::mesh::Mesh) { geometry::normals(m) }",
            ),
            (
                "document.rs",
                "use crate::deform::Edit; use crate::{geometry, mesh::Mesh};",
            ),
        ]
    }

    #[test]
    fn a_clean_tree_passes_and_its_imports_are_found() {
        let code = crate_of(&clean());
        assert_eq!(check(&table(), &code), Vec::<String>::new());
        let shown: BTreeSet<(String, String)> = (code.edges.keys())
            .map(|&(a, b)| (code.files[a].shown.clone(), code.files[b].shown.clone()))
            .collect();
        let expect = |a: &str, b: &str| (format!("src/{a}"), format!("src/{b}"));
        // Through the re-export in geometry/mod.rs to the file that defines `normals`.
        assert!(
            shown.contains(&expect("deform.rs", "geometry/normals.rs")),
            "{shown:?}"
        );
        assert!(shown.contains(&expect("geometry/normals.rs", "solve.rs")));
        assert!(shown.contains(&expect("document.rs", "deform.rs")));
        // The re-export alone is no import of mod.rs; the upward uses of the test module and
        // of the doc link are left out.
        assert!(!shown.contains(&expect("geometry/mod.rs", "geometry/normals.rs")));
        assert!(!shown.iter().any(|(a, _)| a == "src/mesh.rs"));
    }

    #[test]
    fn an_import_the_table_does_not_allow_is_named_with_its_rule() {
        let mut files = clean();
        files[2] = ("solve.rs", "pub fn solve() { let _ = crate::mesh::Mesh; }");
        let problems = check(&table(), &crate_of(&files));
        assert_eq!(
            problems,
            [
                "src/solve.rs imports `mesh` (`crate::mesh::Mesh`, in src/mesh.rs), but the layer \
              table in ARCHITECTURE.md lets `solve` (ground) import nothing of the crate"
            ]
        );
        files[2].1 = "pub fn solve() {}";
        files[4].1 = "pub fn normals(_: &crate::mesh::Mesh) { let _ = crate::deform::Edit; }";
        let problems = check(&table(), &crate_of(&files));
        assert!(
            problems[0].ends_with("lets `geometry` (ground) import only `mesh`, `solve`"),
            "{problems:?}"
        );
    }

    #[test]
    fn a_circle_of_files_is_caught_with_its_loop() {
        let mut files = clean();
        files.push((
            "deform/shared.rs",
            "use super::Edit; pub fn shared(_: Edit) {}",
        ));
        files[5] = (
            "deform.rs",
            "mod shared; use shared::shared; pub struct Edit; fn f() { shared(Edit) }",
        );
        let problems = check(&table(), &crate_of(&files));
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].contains(
                "src/deform.rs imports src/deform/shared.rs (`use shared::shared`); \
                 src/deform/shared.rs imports src/deform.rs (`use super::Edit`)"
            ),
            "{}",
            problems[0]
        );
    }

    #[test]
    fn a_module_declared_with_a_path_attribute_is_read_from_that_file() {
        let mut files = clean();
        files[3].1 = "mod normals; pub use normals::normals; #[path = \"extra/lift.rs\"] mod lift;";
        files.push((
            "geometry/extra/lift.rs",
            "fn f() { let _ = crate::deform::Edit; }",
        ));
        let problems = check(&table(), &crate_of(&files));
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].starts_with("src/geometry/extra/lift.rs"),
            "{}",
            problems[0]
        );
    }

    #[test]
    fn a_loop_through_three_files_and_inline_paths_is_caught() {
        let mut files = clean();
        files[6] = ("document/mod.rs", "mod a; mod b; mod c; pub use a::a;");
        files.extend([
            ("document/a.rs", "pub fn a() { super::b::b() }"),
            ("document/b.rs", "pub fn b() { crate::document::c::c() }"),
            ("document/c.rs", "use super::a; pub fn c() { a::a() }"),
        ]);
        let problems = check(&table(), &crate_of(&files));
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].starts_with(
                "files that import each other: src/document/a.rs, src/document/b.rs, \
                 src/document/c.rs. A loop: src/document/a.rs imports src/document/b.rs \
                 (`super::b::b`); src/document/b.rs imports src/document/c.rs \
                 (`crate::document::c::c`); src/document/c.rs imports src/document/a.rs (`a::a`)"
            ),
            "{}",
            problems[0]
        );
    }

    #[test]
    fn a_re_export_that_its_own_file_uses_is_an_import() {
        let mut files = clean();
        files.push((
            "deform/shared.rs",
            "use super::Edit; pub fn shared(_: Edit) {}",
        ));
        files[5] = (
            "deform.rs",
            "mod shared; pub use shared::shared; pub struct Edit;",
        );
        assert_eq!(check(&table(), &crate_of(&files)), Vec::<String>::new());
        files[5].1 = "mod shared; pub use shared::shared; pub struct Edit; fn f() { shared(Edit) }";
        let problems = check(&table(), &crate_of(&files));
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0]
                .starts_with("files that import each other: src/deform.rs, src/deform/shared.rs")
        );
    }

    #[test]
    fn the_tables_of_architecture_md_parse_and_cover_both_crates() {
        let doc =
            fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../ARCHITECTURE.md"))
                .unwrap();
        let tables = parse_tables(&doc).unwrap();
        for dir in CHECKED {
            assert!(tables.iter().any(|t| t.dir == dir), "no table for {dir}");
        }
    }

    #[test]
    fn a_table_that_drifts_from_the_code_or_points_up_is_refused() {
        let code = crate_of(&clean());
        let missing = TABLE.replace("| techniques | `deform` | the *ground* layer |\n", "");
        let missing = missing.replace("*ground*, *techniques*", "*ground*");
        let problems = check(&parse_tables(&missing).unwrap().remove(0), &code);
        assert!(
            problems[0].contains("the module `deform` is in no row"),
            "{problems:?}"
        );
        let upward = TABLE.replace("| nothing of the crate |", "| `deform` |");
        let err = parse_tables(&upward).unwrap_err().to_string();
        assert!(err.contains("not in a row before it"), "{err}");
        let unknown = TABLE.replace("the *ground* layer", "*grond*");
        let err = parse_tables(&unknown).unwrap_err().to_string();
        assert!(
            err.contains("the layer *grond*, which is no layer"),
            "{err}"
        );
        let unknown = TABLE.replace("the *ground* layer", "`grond`");
        let err = parse_tables(&unknown).unwrap_err().to_string();
        assert!(err.contains("`grond`, which is no module"), "{err}");
    }
}
