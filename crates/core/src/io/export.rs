//! What an STL or OBJ export writes: the whole document or one model, and the surfaces that
//! come out of that choice.

use super::export_error::ExportError;
use crate::model::{Document, Model};

/// Which models an export writes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ExportScope {
    /// Every model of the document.
    #[default]
    Document,
    /// One model, by its index in [`Document::models`].
    Model(usize),
}

/// A model to write, with the name the file gives it.
pub(super) struct Exported<'a> {
    pub model: &'a Model,
    pub name: String,
}

/// The models `scope` names that have triangles, with their names; a refusal when there is
/// nothing to write (`format` names the file type in the sentence).
pub(super) fn exported_models<'a>(
    doc: &'a Document,
    scope: ExportScope,
    format: &'static str,
) -> Result<Vec<Exported<'a>>, ExportError> {
    let named = |index: usize| Exported {
        model: &doc.models[index],
        name: model_name(index, &doc.models[index]),
    };
    match scope {
        ExportScope::Document => {
            let models: Vec<Exported> = (0..doc.models.len())
                .map(named)
                .filter(|m| m.model.mesh.n_faces() > 0)
                .collect();
            if models.is_empty() {
                return Err(ExportError::EmptyDocument { format });
            }
            Ok(models)
        }
        ExportScope::Model(index) => {
            if index >= doc.models.len() {
                return Err(ExportError::NoSuchModel {
                    index,
                    count: doc.models.len(),
                });
            }
            let model = named(index);
            if model.model.mesh.n_faces() == 0 {
                return Err(ExportError::EmptyModel {
                    name: model.name,
                    format,
                });
            }
            Ok(vec![model])
        }
    }
}

/// The model's imported name, or "model N" as the glTF export names it.
fn model_name(index: usize, model: &Model) -> String {
    model
        .name
        .clone()
        .unwrap_or_else(|| format!("model {index}"))
}
