//! Writing a document to the file type its name asks for: .glb, .stl or .obj (with its .mtl
//! beside it), in a unit for the two that have none.

use std::path::{Path, PathBuf};

use anyhow::{Context as _, bail};
use sketchmesh_core::io::{ExportScope, write_glb, write_obj, write_stl};
use sketchmesh_core::model::Document;
use sketchmesh_core::unit::Unit;

/// A file type the CLI writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Glb,
    Stl,
    Obj,
}

/// Where to write and how, checked before any work is done, so that a refusal writes nothing.
pub struct Output {
    path: PathBuf,
    format: Format,
    unit: Unit,
}

impl Output {
    /// The output `path` by its extension, in `unit` (a symbol: mm, cm, m, in) or the
    /// format's default: millimetres for STL (what slicers assume), metres for OBJ.
    pub fn new(path: &Path, unit: Option<&str>) -> anyhow::Result<Self> {
        let extension = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        let format = match extension.as_deref() {
            Some("glb") => Format::Glb,
            Some("stl") => Format::Stl,
            Some("obj") => Format::Obj,
            _ => bail!(
                "Sketchmesh cannot write {}: name the output .glb (glTF), .stl or .obj.",
                path.display()
            ),
        };
        let unit = match (format, unit) {
            (Format::Glb, Some(_)) => {
                bail!("--unit is for .stl and .obj files; glTF is always in metres.")
            }
            (_, Some(symbol)) => symbol.parse::<Unit>()?,
            (Format::Obj, None) => Unit::Metre,
            (_, None) => Unit::Millimetre,
        };
        Ok(Self {
            path: path.to_path_buf(),
            format,
            unit,
        })
    }

    /// Writes `doc`; returns what was written, for the line the command prints
    /// ("out.stl in mm (4,884 bytes)").
    pub fn write(&self, doc: &Document) -> anyhow::Result<String> {
        let refused = || format!("Could not write {}", self.path.display());
        let unit = self.unit;
        match self.format {
            Format::Glb => {
                let bytes = write_glb(doc);
                write_file(&self.path, &bytes)?;
                Ok(format!("{} ({} bytes)", self.path.display(), bytes.len()))
            }
            Format::Stl => {
                let bytes = write_stl(doc, ExportScope::Document, unit).with_context(refused)?;
                write_file(&self.path, &bytes)?;
                Ok(format!(
                    "{} in {unit} ({} bytes)",
                    self.path.display(),
                    bytes.len()
                ))
            }
            Format::Obj => {
                let mtl_path = self.path.with_extension("mtl");
                let mtl_name = mtl_path
                    .file_name()
                    .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
                let files =
                    write_obj(doc, ExportScope::Document, unit, &mtl_name).with_context(refused)?;
                write_file(&self.path, files.obj.as_bytes())?;
                write_file(&mtl_path, files.mtl.as_bytes())?;
                Ok(format!(
                    "{} and {} in {unit} ({} bytes)",
                    self.path.display(),
                    mtl_path.display(),
                    files.obj.len() + files.mtl.len()
                ))
            }
        }
    }
}

fn write_file(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    std::fs::write(path, bytes).with_context(|| format!("Could not write {}", path.display()))
}
