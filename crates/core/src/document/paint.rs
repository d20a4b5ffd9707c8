//! The colour ops: `paint` (a brush stroke over a model), `fill` (a whole model one colour)
//! and `material` (its base colour, roughness and metalness), and the colours every other op
//! carries onto the models it makes.
//!
//! With symmetry on, these ops colour the mirror image too: a brush stroke paints at the
//! mirror image of each dab as well (the other side of a symmetric model, or its twin), and
//! a fill or a material reaches the twin. They change no position, so the general rule for
//! ops made with symmetry on (the changed side wins, `symmetry.rs`) has nothing to go by;
//! `symmetry.rs` calls these with the plane instead.

use glam::DVec2;

use super::next::{target, twin_of};
use super::{CommandError, Document, FillInput, MaterialInput, Model, Op, PaintInput, surface_at};
use crate::geometry::Bvh;
use crate::model::MirrorPlane;
use crate::paint::{
    PaintStroke, carried_colors, dabs_between, mirrored_dab, shown_colors, with_colors,
};
use crate::symmetry::partners;

/// Applies a `paint` op, with the mirror image of every dab when `mirror` is given.
///
/// Errors: [`CommandError::BadView`], [`CommandError::StrokeNotFinite`];
/// [`CommandError::NothingPainted`] when no dab reached a vertex (the stroke missed every
/// model).
pub(super) fn paint_op(
    doc: &Document,
    input: &PaintInput,
    mirror: Option<&MirrorPlane>,
) -> Result<Document, CommandError> {
    let mut painting = Painting::default();
    painting.follow(doc, input, mirror)?;
    painting.painted(doc)?.ok_or(CommandError::NothingPainted)
}

/// A paint stroke being followed sample by sample: the model it paints (found at the first
/// sample over one), its hierarchy, built once per stroke, and what the dabs so far reached
/// on it and on its twin.
#[derive(Debug, Default)]
struct Painting {
    /// The samples followed so far.
    followed: usize,
    /// The model painted and its mesh's hierarchy, once a sample lay over one.
    on: Option<(usize, Bvh, PaintStroke)>,
    /// Its twin across the plane, when painting with symmetry on.
    twin: Option<(usize, Bvh, PaintStroke)>,
    /// The brush's colour.
    color: [f32; 3],
}

impl Painting {
    /// Follows `input`'s samples past those followed so far. Returns whether any was new.
    ///
    /// Errors: [`CommandError::BadView`], [`CommandError::StrokeNotFinite`].
    fn follow(
        &mut self,
        doc: &Document,
        input: &PaintInput,
        mirror: Option<&MirrorPlane>,
    ) -> Result<bool, CommandError> {
        let stroke = input.stroke_input();
        let viewport = stroke.checked_viewport()?;
        let new = input.stroke.get(self.followed..).unwrap_or_default();
        if new.iter().flatten().any(|x| !x.is_finite()) {
            return Err(CommandError::StrokeNotFinite);
        }
        let brush = input.brush();
        self.color = brush.color;
        for &sample in new {
            if self.on.is_none()
                && let Some((index, _)) = surface_at(doc, &stroke, DVec2::new(sample[0], sample[1]))
            {
                let mesh = &target(doc, index)?.mesh;
                self.twin = mirrored_by(doc, index, mirror)?.map(|j| {
                    let mesh = &doc.models[j].mesh;
                    (j, Bvh::new(mesh), PaintStroke::new(mesh.n_vertices()))
                });
                self.on = Some((index, Bvh::new(mesh), PaintStroke::new(mesh.n_vertices())));
            }
            let from = self.followed.checked_sub(1).map(|k| input.stroke[k]);
            self.followed += 1;
            let Some((index, bvh, painted)) = &mut self.on else {
                continue;
            };
            let mesh = &doc.models[*index].mesh;
            for dab in dabs_between(&input.camera, viewport, from, sample, &brush, mesh, bvh) {
                painted.dab(mesh, bvh, &dab, &brush);
                let Some(plane) = mirror else {
                    continue;
                };
                let image = mirrored_dab(&dab, plane);
                painted.dab(mesh, bvh, &image, &brush);
                if let Some((j, twin_bvh, twin_painted)) = &mut self.twin {
                    twin_painted.dab(&doc.models[*j].mesh, twin_bvh, &image, &brush);
                }
            }
        }
        Ok(!new.is_empty())
    }

    /// `doc` with what the stroke painted so far laid over its models' colours; `None` while
    /// it reached no vertex.
    fn painted(&self, doc: &Document) -> Result<Option<Document>, CommandError> {
        let mut next = doc.clone();
        let mut is_empty = true;
        for (i, _, stroke) in self.on.iter().chain(&self.twin) {
            if stroke.is_empty() {
                continue;
            }
            let model = target(doc, *i)?;
            let mut colors = shown_colors(model);
            stroke.apply(&mut colors, self.color);
            next.models[*i] = with_colors(model, colors).into();
            is_empty = false;
        }
        Ok((!is_empty).then_some(next))
    }
}

/// A paint stroke's live preview: the document with what the stroke painted so far.
#[derive(Debug, Default)]
pub(super) struct PaintPreview {
    painting: Painting,
    shown: Option<Document>,
}

impl PaintPreview {
    /// Paints the samples added since the last step: `Some(false)` when there were any
    /// (the preview waits for the next), `None` when nothing changed.
    ///
    /// Errors: as [`paint_op`], but a stroke that has painted nothing yet is no error.
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &PaintInput,
        mirror: Option<&MirrorPlane>,
    ) -> Result<Option<bool>, CommandError> {
        if !self.painting.follow(base, input, mirror)? {
            return Ok(None);
        }
        self.shown = self.painting.painted(base)?;
        Ok(Some(false))
    }

    /// The document as painted so far, once the stroke reached a vertex.
    pub(super) fn document(&self) -> Option<&Document> {
        self.shown.as_ref()
    }
}

/// Applies a `fill` op: the model, and its twin when `mirror` is given, all one colour.
///
/// Errors: [`CommandError::NoSuchModel`].
pub(super) fn fill_op(
    doc: &Document,
    input: &FillInput,
    mirror: Option<&MirrorPlane>,
) -> Result<Document, CommandError> {
    let color = input.color.map(|c| c.clamp(0.0, 1.0) as f32);
    with_twin_too(doc, input.model, mirror, |model| {
        with_colors(model, vec![color; model.mesh.n_vertices()])
    })
}

/// Applies a `material` op to the model, and to its twin when `mirror` is given.
///
/// Errors: [`CommandError::NoSuchModel`].
pub(super) fn material_op(
    doc: &Document,
    input: &MaterialInput,
    mirror: Option<&MirrorPlane>,
) -> Result<Document, CommandError> {
    let finish = Some(input.finish());
    with_twin_too(doc, input.model, mirror, |model| Model {
        finish,
        ..model.clone()
    })
}

/// `doc` with model `index` made anew by `make`, and its twin across `mirror` too.
fn with_twin_too(
    doc: &Document,
    index: usize,
    mirror: Option<&MirrorPlane>,
    make: impl Fn(&Model) -> Model,
) -> Result<Document, CommandError> {
    let model = target(doc, index)?;
    let twin = mirrored_by(doc, index, mirror)?;
    let mut next = doc.clone();
    next.models[index] = make(model).into();
    if let Some(j) = twin {
        next.models[j] = make(&doc.models[j]).into();
    }
    Ok(next)
}

/// With symmetry on (`mirror`), model `index`'s twin, if it has one; `None` for a
/// symmetric model, which carries its mirror image itself.
///
/// Errors: [`CommandError::NotSymmetric`] for a model neither symmetric nor twinned, as for
/// every op made with symmetry on.
fn mirrored_by(
    doc: &Document,
    index: usize,
    mirror: Option<&MirrorPlane>,
) -> Result<Option<usize>, CommandError> {
    let Some(plane) = mirror else {
        return Ok(None);
    };
    match twin_of(doc, index, plane) {
        Some(j) => Ok(Some(j)),
        None if partners(&target(doc, index)?.mesh, plane).is_some() => Ok(None),
        None => Err(CommandError::NotSymmetric),
    }
}

/// `made`, the model `op` made at `index` of `doc`, with the colours of the models it was
/// made from carried onto it ([`carry_colors`]): the one it replaces, or a merge's two.
pub(super) fn with_colors_carried(
    doc: &Document,
    op: &Op,
    (index, mut made): (usize, Model),
) -> (usize, Model) {
    let from: Vec<&Model> = match op {
        Op::Merge(input) => {
            let (kept, gone) = input.kept_and_gone();
            [kept, gone]
                .iter()
                .filter_map(|&i| doc.models.get(i))
                .map(|m| &**m)
                .collect()
        }
        _ => doc.models.get(index).map(|m| &**m).into_iter().collect(),
    };
    carry_colors(&from, &mut made);
    (index, made)
}

/// Gives `model`, made from `sources`, their colours: vertex for vertex when it has the
/// triangles of its one source (a deformation), else by the nearest points of their
/// surfaces ([`carried_colors`]). Nothing changes when no source is painted, or when the
/// model's colours were carried already (they are its own, not a source's copied along with
/// the rest of it), so the page's main thread does not carry again what its worker did.
pub(super) fn carry_colors(sources: &[&Model], model: &mut Model) {
    if sources
        .iter()
        .all(|source| source.vertex_colors().is_none())
    {
        return;
    }
    if let [source] = sources
        && source.mesh.triangles() == model.mesh.triangles()
    {
        model.colors.clone_from(&source.colors);
        return;
    }
    let is_copied = |source: &&Model| match (&model.colors, &source.colors) {
        (Some(own), Some(theirs)) => std::sync::Arc::ptr_eq(own, theirs),
        _ => false,
    };
    if model.vertex_colors().is_some() && !sources.iter().any(is_copied) {
        return;
    }
    let shown: Vec<Vec<[f32; 3]>> = sources.iter().map(|&source| shown_colors(source)).collect();
    let pairs: Vec<_> = (sources.iter().zip(&shown))
        .map(|(source, colors)| (&source.mesh, colors.as_slice()))
        .collect();
    let colors = carried_colors(&pairs, &model.mesh, model.finish().rgb());
    *model = with_colors(model, colors);
}
