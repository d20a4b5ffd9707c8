//! The curve-handle ops ([`crate::skeleton`], Blanco): `curve_handle`, `handle_edit`,
//! `link_handles`, `delete_handle`, and the live preview of a handle being dragged.
//!
//! A handle lives in the document ([`Document::handles`]) beside the model or point cloud it
//! deforms, numbered in creation order. An edit binds the target as it is now to the handles
//! it moves (the edited one and, for a move, the handles linked at that control point,
//! which move with it), rebuilds every point from the new poses, and carries the control
//! points of the target's other handles along. A model repaired from an imported soup is
//! deformed as the soup ([`crate::model::AsImported`]): the soup's points move and the
//! mesh follows them. The preview keeps the [`Deformation`]: a drag frame is one pass over
//! the points, and the committed result is that pass at the final pose, bit for bit what
//! the op computes from the document alone.

use std::borrow::Cow;
use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::{CommandError, CurveHandleInput, Document, HandleEditInput, LinkHandlesInput};
use crate::model::{CurveHandle, HandleCurve, HandleTarget, PointCloud};
use crate::skeleton::{
    Deformation, HandleStroke, Link, Mover, Neighbours, PointEdit, Segmented, Shape, SkeletonError,
    Slabs, place_handle,
};

/// Applies a `curve_handle` op: a new handle on the nearest model or cloud under the stroke.
///
/// Errors: a bad view; the stroke over nothing, too short, or too few control points.
pub(super) fn curve_handle_op(
    doc: &Document,
    input: &CurveHandleInput,
) -> Result<Document, CommandError> {
    let view = input.stroke_input();
    let viewport = view.checked_viewport()?;
    let points: Vec<DVec2> = view.points().iter().map(|p| p.pos).collect();
    if !points.iter().all(|p| p.is_finite()) {
        return Err(CommandError::StrokeNotFinite);
    }
    let stroke = HandleStroke {
        points: &points,
        camera: &view.camera,
        viewport,
    };
    let mut best: Option<(f64, HandleTarget, HandleCurve)> = None;
    let mut refusal = SkeletonError::StrokeMisses;
    for target in targets(doc) {
        let positions = points_of(doc, target);
        let triangles = triangles_of(doc, target);
        let shape = Shape {
            positions: &positions,
            triangles,
        };
        match place_handle(
            &shape,
            &stroke,
            input.kind,
            input.control_points,
            input.rigid,
        ) {
            Ok(curve) => {
                let depth = view.camera.eye.distance(curve.points[0]);
                if best.as_ref().is_none_or(|b| depth < b.0) {
                    best = Some((depth, target, curve));
                }
            }
            Err(SkeletonError::StrokeMisses) => {}
            Err(error) => refusal = error,
        }
    }
    let (_, target, curve) = best.ok_or(refusal)?;
    let mut next = doc.clone();
    next.handles.push(Arc::new(CurveHandle {
        id: doc.handles_made,
        target,
        kind: input.kind,
        curve,
        links: Vec::new(),
    }));
    next.handles_made += 1;
    Ok(next)
}

/// Every model and point cloud of `doc`.
fn targets(doc: &Document) -> impl Iterator<Item = HandleTarget> {
    (0..doc.models.len())
        .map(HandleTarget::Model)
        .chain((0..doc.point_clouds.len()).map(HandleTarget::Cloud))
}

/// The points a handle on `target` moves: a cloud's, an imported soup's as it came, or the
/// mesh's.
fn points_of(doc: &Document, target: HandleTarget) -> Cow<'_, [DVec3]> {
    match target {
        HandleTarget::Model(m) => {
            let model = &doc.models[m];
            match model.as_imported() {
                Some(input) => Cow::Owned(input.positions_of(&model.mesh)),
                None => Cow::Borrowed(model.mesh.positions()),
            }
        }
        HandleTarget::Cloud(c) => Cow::Borrowed(&doc.point_clouds[c].positions),
    }
}

/// The moving handles' rest curves with their links, as a deformation takes them.
fn movers_of<'a>(movers: &'a [(usize, HandleCurve)], links: &'a [Vec<Link>]) -> Vec<Mover<'a>> {
    (movers.iter().zip(links))
        .map(|((_, curve), links)| Mover { rest: curve, links })
        .collect()
}

/// The triangles over [`points_of`] (none for a cloud).
fn triangles_of(doc: &Document, target: HandleTarget) -> &[[u32; 3]] {
    match target {
        HandleTarget::Model(m) => {
            let model = &doc.models[m];
            match model.as_imported() {
                Some(input) => &input.soup.triangles,
                None => model.mesh.triangles(),
            }
        }
        HandleTarget::Cloud(_) => &[],
    }
}

/// The place of handle `id` in `doc.handles`.
fn handle_index(doc: &Document, id: u32) -> Result<usize, CommandError> {
    doc.handles
        .iter()
        .position(|h| h.id == id)
        .ok_or(CommandError::NoSuchHandle(id))
}

/// A handle edit bound to its target, ready to follow new amounts.
#[derive(Debug)]
pub(super) struct HandleDrag {
    target: HandleTarget,
    /// The moving handles' places in the document, and their curves before.
    movers: Vec<(usize, HandleCurve)>,
    /// Each mover's links, as the deformation takes them.
    links: Vec<Vec<Link>>,
    /// The target's points before the edit (empty until the first step).
    rest: Vec<DVec3>,
    /// How far the binding of the target to the moving handles got, a stage per step.
    binding: Binding,
    /// The target's points at the last pose shown.
    moved: Vec<DVec3>,
    /// The mesh's vertices at that pose, for a model kept as imported.
    moved_mesh: Vec<DVec3>,
    /// The op last shown, to skip steps with nothing new.
    shown: Option<HandleEditInput>,
    /// The fraction of the move kept, when all of it would fold.
    limited: Option<f64>,
    /// A cloud's preview: the document with the cloud moved (a cloud has no moved-model
    /// path), and whether it changed since the renderer last asked.
    cloud_preview: Option<(Document, bool)>,
}

/// How far a [`HandleDrag`]'s binding got. Each stage is a step of its own, a frame in the
/// page: at half a million points each takes 25–50 ms there, so no frame waits for two.
#[derive(Debug)]
enum Binding {
    /// Nothing found yet.
    Unbound,
    /// The target's points taken and who is next to whom found.
    Neighbours(Neighbours),
    /// Each handle's parts of the target found.
    Segmented(Segmented),
    /// Each handle's region points bound to its slabs.
    Slabs(Slabs),
    /// Every point bound: the poses follow.
    Bound(Deformation),
}

impl HandleDrag {
    /// Finds the handles the edit of `input` moves; the first step binds the target to them.
    ///
    /// Errors: no such handle or control point.
    pub(super) fn start(doc: &Document, input: &HandleEditInput) -> Result<Self, CommandError> {
        let index = handle_index(doc, input.handle)?;
        let handle = &doc.handles[index];
        if input.point >= handle.curve.points.len() {
            return Err(SkeletonError::NoSuchPoint(input.point).into());
        }
        let mut movers = vec![(index, handle.curve.clone())];
        if input.translate.is_some() {
            for &(_, other, _) in handle.links.iter().filter(|l| l.0 == input.point) {
                let other = handle_index(doc, other)?;
                if movers.iter().all(|m| m.0 != other) {
                    movers.push((other, doc.handles[other].curve.clone()));
                }
            }
        }
        let links: Vec<Vec<Link>> = movers
            .iter()
            .map(|&(i, _)| {
                doc.handles[i]
                    .links
                    .iter()
                    .map(|&(point, other, their)| Link {
                        point,
                        partner: movers
                            .iter()
                            .position(|m| doc.handles[m.0].id == other)
                            .map(|m| (m, their)),
                    })
                    .collect()
            })
            .collect();
        Ok(HandleDrag {
            target: handle.target,
            movers,
            links,
            rest: Vec::new(),
            binding: Binding::Unbound,
            moved: Vec::new(),
            moved_mesh: Vec::new(),
            shown: None,
            limited: None,
            cloud_preview: None,
        })
    }

    /// The binding of the target to the moving handles, made on first use.
    ///
    /// Errors: a handle with no region.
    fn bound(&mut self, doc: &Document) -> Result<&Deformation, CommandError> {
        while self.bind_step(doc)? {}
        match &self.binding {
            Binding::Bound(deformation) => Ok(deformation),
            _ => unreachable!("bound above"),
        }
    }

    /// The next stage of the binding: whether there was one to take.
    ///
    /// Errors: a handle with no region.
    fn bind_step(&mut self, doc: &Document) -> Result<bool, CommandError> {
        if let Binding::Unbound = self.binding {
            self.rest = points_of(doc, self.target).into_owned();
            self.moved = self.rest.clone();
        }
        let shape = Shape {
            positions: &self.rest,
            triangles: triangles_of(doc, self.target),
        };
        let movers = movers_of(&self.movers, &self.links);
        self.binding = match std::mem::replace(&mut self.binding, Binding::Unbound) {
            Binding::Unbound => Binding::Neighbours(shape.neighbours()),
            Binding::Neighbours(neighbours) => {
                Binding::Segmented(Deformation::segmented(&shape, &neighbours, &movers)?)
            }
            Binding::Segmented(segmented) => Binding::Slabs(segmented.slabs(&shape)),
            Binding::Slabs(slabs) => Binding::Bound(slabs.bound(&shape, &movers)),
            bound @ Binding::Bound(_) => {
                self.binding = bound;
                return Ok(false);
            }
        };
        Ok(true)
    }

    /// The moving handles' curves after `input`, its move taken `fraction` of the way.
    fn poses(
        movers: &[(usize, HandleCurve)],
        doc: &Document,
        input: &HandleEditInput,
        fraction: f64,
    ) -> Result<Vec<HandleCurve>, CommandError> {
        let mut edit = point_edit(input)?;
        edit.translate = edit.translate.map(|t| t * fraction);
        let main = &doc.handles[movers[0].0];
        movers
            .iter()
            .enumerate()
            .map(|(m, (index, curve))| {
                if m == 0 {
                    return Ok(curve.edited(&edit)?);
                }
                // A linked handle: its linked point moves with the edited one.
                let their = doc.handles[*index]
                    .links
                    .iter()
                    .find(|l| l.1 == main.id && l.2 == input.point)
                    .map_or(0, |l| l.0);
                let moved = PointEdit {
                    point: their,
                    translate: edit.translate,
                    ..PointEdit::default()
                };
                Ok(curve.edited(&moved)?)
            })
            .collect()
    }

    /// Moves the points to `input`'s pose: `None` when it is the pose shown already, else
    /// `Some(false)` (the preview is up to date until the op changes).
    pub(super) fn step(
        &mut self,
        doc: &Document,
        input: &HandleEditInput,
    ) -> Result<Option<bool>, CommandError> {
        if self.shown.as_ref() == Some(input) {
            return Ok(None);
        }
        if self.bind_step(doc)? {
            return Ok(Some(true));
        }
        self.pose(doc, input)?;
        self.shown = Some(input.clone());
        if let HandleTarget::Cloud(_) = self.target {
            let mut shown = doc.clone();
            write_points(&mut shown, self.target, &self.moved);
            self.cloud_preview = Some((shown, true));
        }
        Ok(Some(false))
    }

    /// Moves the points to `input`'s pose, or as far towards it as folds nothing (the
    /// fraction of its move kept is [`HandleDrag::limited`]). Returns the poses.
    fn pose(
        &mut self,
        doc: &Document,
        input: &HandleEditInput,
    ) -> Result<Vec<HandleCurve>, CommandError> {
        Self::poses(&self.movers, doc, input, 1.0)?;
        self.bound(doc)?;
        let (Binding::Bound(deformation), movers) = (&self.binding, &self.movers) else {
            unreachable!("bound above");
        };
        let fraction = deformation.unfolded(
            &self.rest,
            |f| Self::poses(movers, doc, input, f).unwrap_or_default(),
            &mut self.moved,
        );
        self.limited = (fraction < 1.0).then_some(fraction);
        if let HandleTarget::Model(m) = self.target
            && let Some(imported) = doc.models[m].as_imported()
        {
            self.moved_mesh = imported.mesh_positions(&self.moved);
        }
        Self::poses(&self.movers, doc, input, fraction)
    }

    /// The fraction of the move shown when all of it would fold the surface through itself.
    pub(super) fn limited(&self) -> Option<f64> {
        self.limited
    }

    /// A cloud's preview document, once a pose was shown.
    pub(super) fn document(&self) -> Option<&Document> {
        self.cloud_preview.as_ref().map(|(doc, _)| doc)
    }

    /// Whether the preview document changed since the last call.
    pub(super) fn take_rebuilt(&mut self) -> bool {
        self.cloud_preview
            .as_mut()
            .is_some_and(|(_, changed)| std::mem::replace(changed, false))
    }

    /// The model whose vertices moved and where they are drawn (clouds: `None`, they show
    /// [`HandleDrag::document`]).
    pub(super) fn moved_model(&self) -> Option<(usize, &[DVec3])> {
        self.shown.as_ref()?;
        match self.target {
            HandleTarget::Model(m) if !self.moved_mesh.is_empty() => Some((m, &self.moved_mesh)),
            HandleTarget::Model(m) => Some((m, &self.moved)),
            HandleTarget::Cloud(_) => None,
        }
    }

    /// The committed document: the points at `input`'s pose, the handles moved.
    pub(super) fn result(
        &mut self,
        doc: &Document,
        input: &HandleEditInput,
    ) -> Result<Document, CommandError> {
        let poses = self.pose(doc, input)?;
        let Binding::Bound(deformation) = &self.binding else {
            unreachable!("posing binds");
        };
        let mut next = doc.clone();
        write_points(&mut next, self.target, &self.moved);
        for (h, handle) in next.handles.iter_mut().enumerate() {
            if let Some(m) = self.movers.iter().position(|m| m.0 == h) {
                Arc::make_mut(handle).curve = poses[m].clone();
            } else if handle.target == self.target {
                let carried = deformation.move_points(&handle.curve.points, &poses);
                Arc::make_mut(handle).curve.points = carried;
            }
        }
        Ok(next)
    }
}

/// The edit of `input` at its control point, with its twist in radians.
fn point_edit(input: &HandleEditInput) -> Result<PointEdit, CommandError> {
    if input.translate.is_none() && input.twist_deg.is_none() && input.scale.is_none() {
        return Err(CommandError::NothingToEdit);
    }
    Ok(input.change())
}

/// Writes moved points into the target of a copy of the document.
fn write_points(next: &mut Document, target: HandleTarget, moved: &[DVec3]) {
    match target {
        HandleTarget::Model(m) => {
            let model = Arc::make_mut(&mut next.models[m]);
            match model.as_imported() {
                Some(imported) => {
                    let mesh_positions = imported.mesh_positions(moved);
                    let mut kept = imported.clone();
                    kept.soup.positions = moved.to_vec();
                    model.mesh.positions_mut().copy_from_slice(&mesh_positions);
                    model.as_imported = Some(Arc::new(kept));
                }
                None => model.mesh.positions_mut().copy_from_slice(moved),
            }
        }
        HandleTarget::Cloud(c) => {
            let cloud = Arc::make_mut(&mut next.point_clouds[c]);
            *cloud = PointCloud {
                positions: moved.to_vec(),
                ..cloud.clone()
            };
        }
    }
}

/// Applies a `handle_edit` op.
pub(super) fn handle_edit_op(
    doc: &Document,
    input: &HandleEditInput,
) -> Result<Document, CommandError> {
    HandleDrag::start(doc, input)?.result(doc, input)
}

/// Applies a `link_handles` op: the two control points move together from now on, and the
/// parts between their handles blend.
///
/// Errors: no such handle or point; a handle linked to itself; handles on different objects.
pub(super) fn link_handles_op(
    doc: &Document,
    input: &LinkHandlesInput,
) -> Result<Document, CommandError> {
    let [(a, ka), (b, kb)] = [input.a, input.b];
    let (ia, ib) = (handle_index(doc, a)?, handle_index(doc, b)?);
    for (i, k) in [(ia, ka), (ib, kb)] {
        if k >= doc.handles[i].curve.points.len() {
            return Err(SkeletonError::NoSuchPoint(k).into());
        }
    }
    if ia == ib {
        return Err(CommandError::LinkToItself);
    }
    if doc.handles[ia].target != doc.handles[ib].target {
        return Err(CommandError::LinkAcrossObjects);
    }
    let mut next = doc.clone();
    Arc::make_mut(&mut next.handles[ia]).links.push((ka, b, kb));
    Arc::make_mut(&mut next.handles[ib]).links.push((kb, a, ka));
    Ok(next)
}

/// Applies a `delete_handle` op: the handle goes, and its links with it.
///
/// Errors: no such handle.
pub(super) fn delete_handle_op(doc: &Document, id: u32) -> Result<Document, CommandError> {
    let index = handle_index(doc, id)?;
    let mut next = doc.clone();
    next.handles.remove(index);
    for handle in &mut next.handles {
        if handle.links.iter().any(|l| l.1 == id) {
            Arc::make_mut(handle).links.retain(|l| l.1 != id);
        }
    }
    Ok(next)
}

/// Removes model `index` from a copy of a document, with the handles on it; the handles on
/// later models follow their models' new indices.
pub(super) fn remove_model(next: &mut Document, index: usize) {
    next.models.remove(index);
    next.handles
        .retain(|h| h.target != HandleTarget::Model(index));
    for handle in &mut next.handles {
        if let HandleTarget::Model(m) = handle.target
            && m > index
        {
            Arc::make_mut(handle).target = HandleTarget::Model(m - 1);
        }
    }
}
