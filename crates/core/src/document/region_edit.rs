//! The `region_edit` op ([`crate::region_edit`]) and its live preview while the user drags
//! the transform.
//!
//! The preview keeps the [`RegionEdit`] found for the op's curves: a new transform only
//! moves the region again (one pass, nothing allocated), new levels only weigh it again, and
//! the committed result is that edit applied to the final transform, bit for bit what
//! [`region_edit_op`] computes from the op alone, so replay gives the same document.

use std::sync::Arc;

use glam::{DMat4, DVec2, DVec3};

use super::curve_edit::{remesh_only, with_splits};
use super::next::target;
use super::{
    AreaInput, CommandError, Document, Model, RegionEditInput, StrokeInput, model_under, surface_at,
};
use crate::curve::polyline::thin;
use crate::curve::process_stroke;
use crate::mesh::VertexId;
use crate::region_edit::{
    Area, Finding, Flattening, Handle, Levels, Motion, RegionEdit, RegionError, RegionSketch,
    checked_transform,
};

/// Input samples nearer than this (CSS px) to the last kept one are dropped before the
/// curves are smoothed (Bujans §4.1).
const THIN_PX: f64 = 10.0;

/// The index of the model under the reference curve and the model with its region moved.
///
/// Errors: [`CommandError::BadView`], a curve too short, or the region's refusal.
pub(super) fn region_edit_op(
    doc: &Document,
    input: &RegionEditInput,
) -> Result<(usize, Model), CommandError> {
    let (index, edit) = region_of(doc, input)?;
    let positions = moved(&edit, input)?;
    Ok((index, edited_model(doc, index, &edit, &positions, input)?))
}

/// Model `index` of `doc` on the edit's mesh (the curves embedded), its control curves
/// through the vertices the embedding put on their edges, at `positions`; its region
/// remeshed when `input` asks and the model has no corner attributes a remesh would lose.
///
/// Errors: the remesher's refusal.
fn edited_model(
    doc: &Document,
    index: usize,
    edit: &RegionEdit,
    positions: &[DVec3],
    input: &RegionEditInput,
) -> Result<Model, CommandError> {
    let mut model = embedded_model(&doc.models[index], edit);
    model.mesh.positions_mut().copy_from_slice(positions);
    if input.remesh && !is_textured(&model) {
        let mut region = vec![false; model.mesh.n_vertices()];
        for v in edit.vertices() {
            region[v.index()] = true;
        }
        (model.mesh, model.curves) = remesh_only(&model.mesh, &model.curves, &region)?;
    }
    Ok(model)
}

/// How `input` moves the region of `edit`.
enum Moves {
    /// By a transform per point of the reference curve: one, or handles blended.
    Motion(Motion),
    /// By a re-sketched cross-section at a place along the curve, in its plane.
    Profile(f64, Vec<DVec2>),
}

/// How `input` moves the region of `edit`: its one transform, its handles or its profile.
///
/// Errors: [`RegionError::MotionUnclear`], or a transform's or the handles' refusal.
fn moves_of(edit: &RegionEdit, input: &RegionEditInput) -> Result<Moves, RegionError> {
    match (&input.transform, &input.handles, &input.profile) {
        (Some(transform), None, None) => Ok(Moves::Motion(checked_transform(transform)?.into())),
        (None, Some(handles), None) => {
            let handles: Vec<Handle> = handles
                .iter()
                .map(|h| Handle {
                    at: h.at,
                    transform: DMat4::from_cols_array(&h.transform),
                })
                .collect();
            Ok(Moves::Motion(edit.motion(&handles)?))
        }
        (None, None, Some(profile)) => {
            let stroke = profile.stroke.iter().map(|&[u, v]| DVec2::new(u, v));
            Ok(Moves::Profile(profile.at, stroke.collect()))
        }
        _ => Err(RegionError::MotionUnclear),
    }
}

/// `model` on `edit`'s mesh, where the curves are embedded: its control curves get the
/// vertices the embedding put on their edges.
fn embedded_model(model: &Model, edit: &RegionEdit) -> Model {
    Model {
        mesh: edit.mesh().clone(),
        curves: with_splits(&model.curves, edit.splits()),
        ..model.clone()
    }
}

/// Whether `model` has an imported look (UVs or colours per corner) that belongs to its
/// triangles as they are: such a model is neither embedded into nor remeshed.
fn is_textured(model: &Model) -> bool {
    (model.appearance.as_ref()).is_some_and(|a| a.uvs.is_some() || a.colors.is_some())
}

/// Every vertex of the edit's mesh moved as `input` says.
///
/// Errors: as [`moves_of`], and a profile's refusal.
fn moved(edit: &RegionEdit, input: &RegionEditInput) -> Result<Vec<DVec3>, RegionError> {
    match moves_of(edit, input)? {
        Moves::Motion(motion) => Ok(edit.applied(&motion)),
        Moves::Profile(at, stroke) => edit.profile_applied(at, &stroke),
    }
}

/// The model under the reference curve's first point and the region of `input` on it, the
/// curves embedded in its mesh unless the model's imported look forbids (see
/// [`RegionEdit::on_edges`]), found at once; the preview finds it in steps
/// ([`RegionPreview::step`]).
///
/// Errors: as [`region_edit_op`].
fn region_of(doc: &Document, input: &RegionEditInput) -> Result<(usize, RegionEdit), CommandError> {
    let Start {
        model,
        sketch,
        embeds,
    } = start_of(doc, input)?;
    let mesh = &doc.models[model].mesh;
    let found = RegionEdit::finding(mesh, &sketch, embeds)?;
    Ok((model, weighed(found, mesh, input)?))
}

/// What finding the region of an op starts from.
struct Start {
    /// The model under the reference curve.
    model: usize,
    /// The curves, smoothed.
    sketch: RegionSketch,
    /// Whether the curves may be embedded in the model's mesh (see [`is_textured`]).
    embeds: bool,
}

/// The model and the curves of `input`, checked.
///
/// Errors: [`CommandError::BadView`], a curve too short, a bad transform or levels, or a
/// reference curve that misses every model.
fn start_of(doc: &Document, input: &RegionEditInput) -> Result<Start, CommandError> {
    let reference = input.reference_input();
    let viewport = reference.checked_viewport()?;
    levels_of(input)?;
    if let Some(transform) = &input.transform {
        checked_transform(transform)?;
    }
    let smoothed = |stroke: &StrokeInput| -> Result<Vec<DVec2>, CommandError> {
        let points = process_stroke(&thin(&stroke.points(), THIN_PX))?;
        Ok(points.iter().map(|p| p.pos).collect())
    };
    let boundary = StrokeInput {
        stroke: input.boundary.clone(),
        ..reference.clone()
    };
    let model = model_under(doc, &reference).ok_or(RegionError::ReferenceMissesModel)?;
    let sketch = RegionSketch {
        camera: input.camera,
        viewport,
        reference: smoothed(&reference)?,
        boundary: smoothed(&boundary).map_err(|_| RegionError::BoundaryMissesReference)?,
    };
    let embeds = !is_textured(target(doc, model)?);
    Ok(Start {
        model,
        sketch,
        embeds,
    })
}

/// The region `found` on `mesh` weighed with `input`'s levels and areas: its last step.
///
/// Errors: bad levels or areas.
fn weighed(
    found: Finding,
    mesh: &crate::mesh::Mesh,
    input: &RegionEditInput,
) -> Result<RegionEdit, CommandError> {
    let levels = levels_of(input)?;
    let mut edit = found.weigh(mesh, &levels);
    if !input.areas.is_empty() {
        edit.set_falloff(&levels, &areas_of(input)?);
    }
    Ok(edit)
}

/// What a drag does to a region, about the surface point under the reference curve's
/// middle sample (its anchor).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RegionDrag {
    /// Moves the anchor with the pointer, parallel to the screen (Bujans §4, step 5).
    #[default]
    Move,
    /// Turns about the view axis through the anchor: right turns clockwise as seen.
    Turn,
    /// Scales about the anchor: up grows, down shrinks.
    Scale,
}

/// Degrees a [`RegionDrag::Turn`] turns per CSS px of sideways drag.
const TURN_DEGREES_PER_PX: f64 = 0.5;
/// The largest turn a drag makes: short of half a turn, where `w ⊙ T` has no meaning.
const MAX_TURN_DEGREES: f64 = 170.0;
/// CSS px of upward drag that double the size in a [`RegionDrag::Scale`].
const PX_PER_DOUBLING: f64 = 150.0;
/// The scale a drag stays within: 1/10 to 10.
const MAX_SCALE: f64 = 10.0;

/// `region` with its transform set by a drag of `offset` CSS px on screen (y down); see
/// [`RegionDrag`]. An offset that cannot be placed (a ray parallel to the view plane) moves
/// nothing.
pub fn dragged_region(
    doc: &Document,
    region: &RegionEditInput,
    drag: RegionDrag,
    offset: DVec2,
) -> RegionEditInput {
    let reference = region.reference_input();
    let viewport = reference.viewport_size();
    let camera = &region.camera;
    let middle = (reference.stroke)
        .get(reference.stroke.len() / 2)
        .map_or(DVec2::ZERO, |&[x, y, _]| DVec2::new(x, y));
    let anchor = surface_at(doc, &reference, middle).map_or(camera.target, |(_, p)| p);
    let about = |m: DMat4| DMat4::from_translation(anchor) * m * DMat4::from_translation(-anchor);
    let transform = match drag {
        RegionDrag::Move => {
            let on_plane = |at: DVec2| camera.point_on_plane_through(anchor, at, viewport);
            let shift = match (on_plane(middle), on_plane(middle + offset)) {
                (Some(from), Some(to)) => to - from,
                _ => DVec3::ZERO,
            };
            DMat4::from_translation(shift)
        }
        RegionDrag::Turn => {
            let degrees =
                (offset.x * TURN_DEGREES_PER_PX).clamp(-MAX_TURN_DEGREES, MAX_TURN_DEGREES);
            about(DMat4::from_axis_angle(
                camera.forward(),
                degrees.to_radians(),
            ))
        }
        RegionDrag::Scale => {
            let factor = (-offset.y / PX_PER_DOUBLING).exp2();
            about(DMat4::from_scale(DVec3::splat(
                factor.clamp(1.0 / MAX_SCALE, MAX_SCALE),
            )))
        }
    };
    RegionEditInput {
        transform: Some(transform.to_cols_array()),
        handles: None,
        profile: None,
        ..region.clone()
    }
}

/// The op `input` with only what its region depends on: the curves and the view.
fn curves_key(input: &RegionEditInput) -> RegionEditInput {
    RegionEditInput {
        transform: None,
        handles: None,
        profile: None,
        levels: None,
        areas: Vec::new(),
        remesh: false,
        ..input.clone()
    }
}

/// The kept region `edit` of model `model`, found for the curves `key` and weighed with
/// `input`'s levels, with the document it shows.
fn built(
    base: &Document,
    key: RegionEditInput,
    model: usize,
    edit: RegionEdit,
    input: &RegionEditInput,
) -> Built {
    let mut document = base.clone();
    document.models[model] = Arc::new(embedded_model(&base.models[model], &edit));
    Built {
        key,
        model,
        edit,
        document,
        levels: (input.levels.clone(), input.areas.clone()),
        disc: None,
    }
}

fn levels_of(input: &RegionEditInput) -> Result<Levels, RegionError> {
    input
        .levels
        .clone()
        .map_or(Ok(Levels::default()), Levels::new)
}

/// The op's areas of the fall-off.
///
/// Errors: [`RegionError::BadLevels`], [`RegionError::BadArea`] for a lasso of fewer than
/// three points or one that is not finite.
fn areas_of(input: &RegionEditInput) -> Result<Vec<Area>, RegionError> {
    (input.areas.iter())
        .map(|area| {
            let lasso: Vec<DVec2> = area
                .lasso
                .iter()
                .map(|&[x, y, _]| DVec2::new(x, y))
                .collect();
            if lasso.len() < 3 || lasso.iter().any(|p| !p.is_finite()) {
                return Err(RegionError::BadArea);
            }
            Ok(Area {
                lasso,
                levels: Levels::new(area.levels.clone())?,
            })
        })
        .collect()
}

/// A live region edit on one model: the region behind it and what it shows.
#[derive(Debug)]
pub(super) struct RegionPreview {
    /// The region of the curves last asked for while it is found, a step per frame.
    finding: Option<Searched>,
    built: Option<Built>,
    /// Whether the region was found anew since [`RegionPreview::take_rebuilt`] last asked:
    /// the document shown changed (the curves embedded elsewhere).
    rebuilt: bool,
    /// The op the shown positions are for, once shown.
    shown_for: Option<RegionEditInput>,
    shown: Vec<DVec3>,
}

/// A region being found, and for what.
#[derive(Debug)]
struct Searched {
    /// The op's curves (see [`curves_key`]).
    key: RegionEditInput,
    model: usize,
    finding: Finding,
}

/// A region edit and what it was found for.
#[derive(Debug)]
struct Built {
    /// The op, its transform and levels left out.
    key: RegionEditInput,
    model: usize,
    edit: RegionEdit,
    /// The document as the edit shows it: the model on the edit's mesh, the curves
    /// embedded, not yet moved.
    document: Document,
    /// The levels and areas the edit is weighed with.
    levels: (Option<Vec<f64>>, Vec<AreaInput>),
    /// The region laid flat in the unit disc, for the fall-off panel; found in three steps
    /// of their own after the region is first shown.
    disc: Option<Disc>,
}

/// The region laid flat, on its way.
#[derive(Debug)]
enum Disc {
    /// Its system analysed, to be factored, then solved, in the next steps.
    Laying(Box<Flattening>),
    /// Laid, or why it cannot be.
    Laid(Result<Vec<DVec2>, RegionError>),
}

impl Built {
    /// Whether the region is laid flat (or known not to be a disc).
    fn is_laid(&self) -> bool {
        matches!(self.disc, Some(Disc::Laid(_)))
    }
}

impl Disc {
    /// The next step of laying the region of `edit` flat, from `disc`: whether it is laid.
    fn step(disc: &mut Option<Disc>, edit: &RegionEdit) -> bool {
        let next = match disc.take() {
            None => match edit.flattening() {
                Ok(flattening) => Disc::Laying(Box::new(flattening)),
                Err(why) => Disc::Laid(Err(why)),
            },
            Some(Disc::Laying(mut flattening)) if !flattening.is_factored() => {
                match flattening.factor() {
                    Ok(()) => Disc::Laying(flattening),
                    Err(why) => Disc::Laid(Err(why)),
                }
            }
            Some(Disc::Laying(flattening)) => Disc::Laid(flattening.finish()),
            Some(laid) => laid,
        };
        matches!(disc.insert(next), Disc::Laid(_))
    }
}

impl RegionPreview {
    /// Shows the document as it is until the first step.
    pub(super) fn new() -> Self {
        RegionPreview {
            finding: None,
            built: None,
            rebuilt: false,
            shown_for: None,
            shown: Vec::new(),
        }
    }

    /// Brings what is shown to `input`'s transform and levels, finding the region first if
    /// the curves changed (in three steps, see [`Finding`]: for the bunny each is a third
    /// of the 50 ms it takes at once), then (in the next three steps) laying it flat for the
    /// fall-off panel: `None` when all is there already, `Some(true)` after a step with more
    /// to come, `Some(false)` after a step that got there.
    ///
    /// Errors: the region's refusal (the edit then repeats it; the document is untouched).
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &RegionEditInput,
    ) -> Result<Option<bool>, CommandError> {
        if self.find(base, input)? {
            return Ok(Some(true));
        }
        let built = edit_for(&mut self.built, &mut self.rebuilt, base, input)?;
        let mesh = built.edit.mesh();
        if self.shown_for.as_ref() == Some(input) {
            // The region is shown: the disc comes next, in three steps of its own.
            if built.is_laid() {
                return Ok(None);
            }
            return Ok(Some(!Disc::step(&mut built.disc, &built.edit)));
        }
        match moves_of(&built.edit, input)? {
            // A drag: the region moved again in place, nothing allocated.
            Moves::Motion(motion) => {
                if self.shown.len() != mesh.n_vertices() {
                    self.shown = mesh.positions().to_vec();
                }
                built
                    .edit
                    .apply_into(&motion, mesh.positions(), &mut self.shown);
            }
            Moves::Profile(at, stroke) => {
                self.shown = built.edit.profile_applied(at, &stroke)?;
            }
        }
        self.shown_for = Some(input.clone());
        Ok(Some(!built.is_laid()))
    }

    /// Takes the next step of finding the region of `input`'s curves unless it is found:
    /// whether a step was taken.
    ///
    /// Errors: the region's refusal.
    fn find(&mut self, base: &Document, input: &RegionEditInput) -> Result<bool, CommandError> {
        let key = curves_key(input);
        if self.built.as_ref().is_some_and(|built| built.key == key) {
            return Ok(false);
        }
        let Some(searched) = self.finding.as_mut().filter(|searched| searched.key == key) else {
            let start = start_of(base, input)?;
            let mesh = &base.models[start.model].mesh;
            self.finding = Some(Searched {
                key,
                model: start.model,
                finding: RegionEdit::finding(mesh, &start.sketch, start.embeds)?,
            });
            return Ok(true);
        };
        let mesh = &base.models[searched.model].mesh;
        if !searched.finding.is_embedded() {
            searched.finding.embed(mesh);
            return Ok(true);
        }
        let Searched {
            key,
            model,
            finding,
        } = self.finding.take().expect("found above");
        let edit = weighed(finding, mesh, input)?;
        self.built = Some(built(base, key, model, edit, input));
        self.rebuilt = true;
        Ok(true)
    }

    /// The committed result of `input`, from the kept region when it serves.
    ///
    /// Errors: the region's refusal.
    pub(super) fn result(
        &mut self,
        base: &Document,
        input: &RegionEditInput,
    ) -> Result<(usize, Model), CommandError> {
        let built = edit_for(&mut self.built, &mut self.rebuilt, base, input)?;
        let positions = moved(&built.edit, input)?;
        let model = edited_model(base, built.model, &built.edit, &positions, input)?;
        Ok((built.model, model))
    }

    /// The document shown: the one the edit began on with the model's curves embedded, once
    /// the region is found.
    pub(super) fn document(&self) -> Option<&Document> {
        self.built.as_ref().map(|built| &built.document)
    }

    /// Whether the document shown changed since the last call.
    pub(super) fn take_rebuilt(&mut self) -> bool {
        std::mem::take(&mut self.rebuilt)
    }

    /// The model shown and its positions, once the first step moved it.
    pub(super) fn moved(&self) -> Option<(usize, &[DVec3])> {
        let built = self.built.as_ref()?;
        self.shown_for
            .as_ref()
            .map(|_| (built.model, &self.shown[..]))
    }

    /// The region laid flat in the unit disc (in the order of its vertices), or why it
    /// cannot be: what the fall-off panel draws.
    pub(super) fn disc(&self) -> Option<Result<&[DVec2], &RegionError>> {
        match self.built.as_ref()?.disc.as_ref()? {
            Disc::Laid(disc) => Some(disc.as_ref().map(Vec::as_slice)),
            Disc::Laying(_) => None,
        }
    }

    /// The region found, when it was found for the curves of `curves`.
    pub(super) fn found_for(&self, curves: &RegionEditInput) -> Option<&RegionEdit> {
        let built = self.built.as_ref()?;
        (built.key == curves_key(curves)).then_some(&built.edit)
    }

    /// The model, the region's vertices and their weights, for the fall-off overlay.
    pub(super) fn falloff(&self) -> Option<(usize, &[VertexId], &[f64])> {
        let built = self.built.as_ref()?;
        Some((built.model, built.edit.vertices(), built.edit.weights()))
    }
}

/// The edit in `slot` if it was found for `input`'s curves (weighed with its levels), else
/// a new one put there and `rebuilt` set.
fn edit_for<'a>(
    slot: &'a mut Option<Built>,
    rebuilt: &mut bool,
    base: &Document,
    input: &RegionEditInput,
) -> Result<&'a mut Built, CommandError> {
    let key = curves_key(input);
    let mut built = match slot.take() {
        Some(built) if built.key == key => built,
        _ => {
            let (model, edit) = region_of(base, input)?;
            *rebuilt = true;
            built(base, key, model, edit, input)
        }
    };
    // Weighed again only when the levels change, not in every drag frame.
    let wanted = (input.levels.clone(), input.areas.clone());
    if built.levels != wanted {
        built
            .edit
            .set_falloff(&levels_of(input)?, &areas_of(input)?);
        built.levels = wanted;
    }
    Ok(slot.insert(built))
}
