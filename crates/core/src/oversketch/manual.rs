//! Manual over-sketching (Nealen's dissertation ch. 4, §4.2–4.3): the user says which curve
//! moves instead of letting matching guess, then sketches where it goes.
//!
//! A handle is picked with one stroke ([`pick_handle`]):
//! - drawn along a visible silhouette, it picks that silhouette's piece between the points
//!   nearest the stroke's ends ([`ManualHandle::Silhouette`]); the ends can then be dragged
//!   to crop it (the `from`/`to` points move, `via` keeps the side of a closed outline);
//! - drawn over the model anywhere else, it is a curve on the surface
//!   ([`ManualHandle::Surface`]), embedded in the mesh as a feature sketch is (§4.4.1: the
//!   edge path under it, moved onto it).
//!
//! The second stroke is the handle's new shape ([`oversketch_manual`]). A silhouette piece
//! moves as in the automatic over-sketch (targets blended at the ends, the band around it
//! carried along); a surface curve goes onto the stroke whole, its path vertices
//! constrained (or, when it cannot be embedded, its points inside their triangles, Eq.
//! 4.2). Both handles are kept as screen points, so a session replays them exactly with the
//! same camera.

use glam::{DVec2, DVec3};
use serde::{Deserialize, Serialize};

use super::bend::{BendOptions, HandleCurve, bend};
use super::pipeline::{piece_points, seen_silhouettes};
use super::track::Track;
use super::{OversketchError, Oversketched, handle_points, simplify_stroke};
use crate::camera::Camera;
use crate::curve::polyline::{
    closest_point, cumulative_lengths, distance_to_polyline, point_at, resample,
};
use crate::deform::HandlePoint;
use crate::feature::{Embedded, Sketch, embed_sketch};
use crate::geometry::Bvh;
use crate::mesh::Mesh;
use crate::silhouette::{OutlineChain, Silhouette, outline_chains};

/// A pick stroke whose ends and [`PICK_SHARE`] of its points lie this close (px) to one
/// silhouette picks that silhouette; a `via` point this close to a silhouette finds it again.
pub const PICK_DISTANCE_PX: f64 = 12.0;

/// The share of a pick stroke's points that must lie near a silhouette: people trace an
/// outline roughly, leaving it here and there.
pub const PICK_SHARE: f64 = 0.8;

/// Spacing (px) of the points of a curve drawn on the surface: wider than the stroke's
/// samples so that neighbouring constraints rarely share a triangle.
pub const SURFACE_HANDLE_SPACING_PX: f64 = 6.0;

/// The handle of a manual over-sketch, in screen CSS px of the op's viewport.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ManualHandle {
    /// The piece of the silhouette nearest `via`, from the point nearest `from` to the point
    /// nearest `to`, running through `via` (which decides the way round a closed outline).
    Silhouette {
        /// One end of the piece.
        from: DVec2,
        /// A point of the piece between its ends.
        via: DVec2,
        /// The other end.
        to: DVec2,
        /// Which outline the piece is taken from.
        #[serde(default, skip_serializing_if = "OutlineKind::is_smooth")]
        outline: OutlineKind,
    },
    /// A curve on the surface: the points where these screen points' rays meet the mesh.
    Surface {
        /// The curve as drawn, in order.
        points: Vec<DVec2>,
    },
}

/// Which outline a manual handle is picked from (Nealen §4.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OutlineKind {
    /// The smooth silhouette: where the interpolated normals turn edge-on, inside the
    /// faces; it follows a smooth surface between its vertices.
    #[default]
    Smooth,
    /// The edge silhouette: the mesh edges between faces turned towards and away from the
    /// eye, the outline as rendered. A sharp crest seen edge-on (a ridge, a camel's nose) is
    /// one, where the smooth silhouette may pass beside it or not at all.
    Edge,
}

impl OutlineKind {
    /// Whether this is the default (for serde's `skip_serializing_if`).
    pub fn is_smooth(&self) -> bool {
        *self == OutlineKind::Smooth
    }
}

/// The handle a pick stroke selects: a piece of the `outline` when the stroke's ends and
/// [`PICK_SHARE`] of its points lie within [`PICK_DISTANCE_PX`] of one visible outline,
/// else a curve on the surface when at least two of its points hit the mesh. `None`
/// otherwise.
pub fn pick_handle(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
    outline: OutlineKind,
) -> Option<ManualHandle> {
    let stroke = simplify_stroke(stroke);
    let (&from, &to) = (stroke.first()?, stroke.last()?);
    let polylines = SeenOutline::new(mesh, camera, viewport, outline).polylines;
    let samples = resample(&stroke, 2.0);
    let follows = |polyline: &Vec<DVec2>| {
        if polyline.len() < 2 {
            return false;
        }
        let is_near = |p: DVec2| distance_to_polyline(p, polyline) <= PICK_DISTANCE_PX;
        let near = samples.iter().filter(|&&p| is_near(p)).count();
        is_near(from) && is_near(to) && near as f64 >= PICK_SHARE * samples.len() as f64
    };
    if from.distance(to) > 0.0 && polylines.iter().any(follows) {
        let via = stroke_midpoint(&stroke);
        return Some(ManualHandle::Silhouette {
            from,
            via,
            to,
            outline,
        });
    }
    let handle = ManualHandle::Surface { points: stroke };
    let on_surface = resolve(mesh, camera, viewport, &handle)?;
    (on_surface.curve.points.len() >= 2).then_some(handle)
}

/// The handle as it would move, on screen (CSS px), for highlighting; `None` when it no
/// longer finds its silhouette or misses the mesh.
pub fn manual_handle_preview(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    handle: &ManualHandle,
) -> Option<Vec<DVec2>> {
    resolve(mesh, camera, viewport, handle).map(|resolved| resolved.curve.screen)
}

/// Moves `handle` onto `stroke` (its new shape, screen points in drawing order) and bends
/// the surface around it with its details. The handle's end nearer the stroke's start goes
/// to the stroke's start.
///
/// Errors: [`OversketchError::HandleLost`] when the handle no longer resolves on the mesh,
/// [`OversketchError::NoMatch`] for a degenerate stroke, and
/// [`OversketchError::Deform`] when the edit cannot be made.
pub fn oversketch_manual(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    handle: &ManualHandle,
    stroke: &[DVec2],
    options: BendOptions,
) -> Result<Oversketched, OversketchError> {
    let stroke = if stroke.iter().all(|p| p.is_finite()) {
        simplify_stroke(stroke)
    } else {
        Vec::new()
    };
    let (&start, &end) = stroke
        .first()
        .zip(stroke.last())
        .filter(|(a, b)| a != b)
        .ok_or(OversketchError::NoMatch)?;
    let Resolved { curve, embedded } =
        resolve(mesh, camera, viewport, handle).ok_or(OversketchError::HandleLost)?;
    let (first, last) = (curve.screen[0], curve.screen[curve.screen.len() - 1]);
    let curve = if start.distance(last) + end.distance(first)
        < start.distance(first) + end.distance(last)
    {
        curve.reversed()
    } else {
        curve
    };
    let Some(embedded) = embedded else {
        let (positions, roi) = bend(mesh, camera, viewport, &curve, &stroke, options)?;
        return Ok(Oversketched {
            positions,
            handle: curve.screen,
            roi_size: roi.iter().filter(|&&r| r).count(),
            score: 1.0,
        });
    };
    let mut on_curve = mesh.clone();
    on_curve.positions_mut().copy_from_slice(&embedded);
    let (positions, roi) = bend(&on_curve, camera, viewport, &curve, &stroke, options)?;
    // The embedding moved the path's surroundings too: they belong to the region.
    let roi_size = roi
        .iter()
        .zip(mesh.positions().iter().zip(&embedded))
        .filter(|&(&r, (a, b))| r || a != b)
        .count();
    Ok(Oversketched {
        positions,
        handle: curve.screen,
        roi_size,
        score: 1.0,
    })
}

/// A handle found on the mesh: its curve, and for a curve on the surface, every vertex's
/// position with the curve embedded (the curve's points are then those vertices).
struct Resolved {
    curve: HandleCurve,
    embedded: Option<Vec<DVec3>>,
}

/// The handle's points on the mesh as seen now; `None` (or fewer than two points) when the
/// silhouette is gone or the curve misses the mesh.
fn resolve(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    handle: &ManualHandle,
) -> Option<Resolved> {
    let resolved = match handle {
        ManualHandle::Silhouette {
            from,
            via,
            to,
            outline,
        } => Resolved {
            curve: silhouette_piece(mesh, camera, viewport, *outline, [*from, *via, *to])?,
            embedded: None,
        },
        ManualHandle::Surface { points } => surface_curve(mesh, camera, viewport, points),
    };
    (resolved.curve.points.len() >= 2).then_some(resolved)
}

/// The piece of the `outline` nearest `via` between the points nearest `from` and `to`,
/// the way round that passes `via`.
fn silhouette_piece(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    outline: OutlineKind,
    [from, via, to]: [DVec2; 3],
) -> Option<HandleCurve> {
    let seen = SeenOutline::new(mesh, camera, viewport, outline);
    let polylines = &seen.polylines;
    let nearest = polylines
        .iter()
        .enumerate()
        .filter(|(_, polyline)| polyline.len() >= 2)
        .map(|(i, polyline)| (i, distance_to_polyline(via, polyline)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .filter(|&(_, distance)| distance <= PICK_DISTANCE_PX)?;
    let polyline = &polylines[nearest.0];
    let track = Track::new(polyline)?;
    let cumulative = cumulative_lengths(polyline);
    let [s_from, s_via, s_to] =
        [from, via, to].map(|p| closest_point(polyline, &cumulative, p).arclength);
    let (start, end) = if track.is_closed() {
        let length = track.length();
        let forward = (s_to - s_from).rem_euclid(length);
        if (s_via - s_from).rem_euclid(length) <= forward {
            (track.index(s_from), track.index(s_from + forward))
        } else {
            // Backwards: both indices in the unrolled second lap, end below start.
            let backward = length - forward;
            (
                track.index(s_from + length),
                track.index(s_from + length - backward),
            )
        }
    } else {
        (track.index(s_from), track.index(s_to))
    };
    let indices: Vec<f64> = handle_points(polyline, start, end)
        .into_iter()
        .map(|(index, _)| index)
        .collect();
    Some(seen.piece(mesh, nearest.0, &indices))
}

/// The visible outlines of one kind as seen, with their screen polylines (a closed one
/// repeats its first point at the end, as matching expects).
struct SeenOutline {
    curves: Curves,
    polylines: Vec<Vec<DVec2>>,
}

/// The outlines behind [`SeenOutline::polylines`].
enum Curves {
    Smooth(Vec<Silhouette>),
    Edge(Vec<OutlineChain>),
}

impl SeenOutline {
    fn new(mesh: &Mesh, camera: &Camera, viewport: DVec2, outline: OutlineKind) -> Self {
        match outline {
            OutlineKind::Smooth => {
                let (curves, polylines) = seen_silhouettes(mesh, camera, viewport);
                SeenOutline {
                    curves: Curves::Smooth(curves),
                    polylines,
                }
            }
            OutlineKind::Edge => {
                let chains = outline_chains(mesh, &Bvh::new(mesh), camera, viewport);
                let polylines = chains
                    .iter()
                    .map(|chain| {
                        let mut points = chain.screen.clone();
                        if chain.closed {
                            points.push(points[0]);
                        }
                        points
                    })
                    .collect();
                SeenOutline {
                    curves: Curves::Edge(chains),
                    polylines,
                }
            }
        }
    }

    /// The handle along outline `which` at fractional polyline `indices`: silhouette
    /// points inside their edges, or the chain's vertices, each once.
    fn piece(&self, mesh: &Mesh, which: usize, indices: &[f64]) -> HandleCurve {
        let polyline_len = self.polylines[which].len();
        match &self.curves {
            Curves::Smooth(curves) => {
                HandleCurve::of_silhouette(&piece_points(&curves[which], polyline_len, indices))
            }
            Curves::Edge(chains) => {
                let chain = &chains[which];
                let n = chain.vertices.len();
                let mut ks: Vec<usize> = Vec::new();
                for &index in indices {
                    // The repeated closing point of a closed chain is its vertex 0.
                    let k = (index.round() as usize).min(polyline_len - 1) % n;
                    if !ks.contains(&k) {
                        ks.push(k);
                    }
                }
                HandleCurve {
                    points: ks
                        .iter()
                        .map(|&k| HandlePoint::vertex(chain.vertices[k]))
                        .collect(),
                    worlds: ks
                        .iter()
                        .map(|&k| mesh.position(chain.vertices[k]))
                        .collect(),
                    screen: ks.iter().map(|&k| chain.screen[k]).collect(),
                    is_silhouette: true,
                }
            }
        }
    }
}

/// A curve drawn on the surface, embedded as feature sketches are (§4.4.1): the edge path
/// under it with its vertices moved onto it ([`embed_sketch`]), so that the handle is made
/// of mesh vertices lying on the curve as drawn. A curve the embedding refuses (one that
/// leaves the mesh or folds back) is taken as drawn instead: its points inside their
/// triangles ([`points_in_faces`], Eq. 4.2).
fn surface_curve(mesh: &Mesh, camera: &Camera, viewport: DVec2, points: &[DVec2]) -> Resolved {
    let sketch = Sketch {
        camera: *camera,
        viewport,
        points: points.to_vec(),
        region: None,
    };
    let Ok(Embedded { path, positions }) = embed_sketch(mesh, &sketch) else {
        return Resolved {
            curve: points_in_faces(mesh, camera, viewport, points),
            embedded: None,
        };
    };
    let worlds: Vec<DVec3> = path.iter().map(|v| positions[v.index()]).collect();
    let screen = worlds
        .iter()
        .map(|&p| {
            camera
                .screen_from_world(p, viewport)
                .map_or(DVec2::ZERO, |s| s.truncate())
        })
        .collect();
    Resolved {
        curve: HandleCurve {
            points: path.iter().map(|&v| HandlePoint::vertex(v)).collect(),
            worlds,
            screen,
            is_silhouette: false,
        },
        embedded: Some(positions),
    }
}

/// The points where the rays through `points` (resampled every
/// [`SURFACE_HANDLE_SPACING_PX`]) first meet the mesh, one per triangle.
fn points_in_faces(mesh: &Mesh, camera: &Camera, viewport: DVec2, points: &[DVec2]) -> HandleCurve {
    let bvh = Bvh::new(mesh);
    let mut curve = HandleCurve {
        points: Vec::new(),
        worlds: Vec::new(),
        screen: Vec::new(),
        is_silhouette: false,
    };
    let mut last_face = None;
    for p in resample(points, SURFACE_HANDLE_SPACING_PX) {
        let (origin, dir) = camera.ray_in_world(p, viewport);
        let Some(hit) = bvh.raycast(mesh, origin, dir) else {
            continue;
        };
        if last_face == Some(hit.face) {
            continue;
        }
        last_face = Some(hit.face);
        let world: DVec3 = origin + dir * hit.distance;
        curve
            .points
            .push(HandlePoint::in_face(mesh, hit.face, hit.barycentric));
        curve.worlds.push(world);
        curve.screen.push(p);
    }
    curve
}

/// The point halfway along `stroke` by arclength.
fn stroke_midpoint(stroke: &[DVec2]) -> DVec2 {
    let cumulative = cumulative_lengths(stroke);
    let half = 0.5 * cumulative.last().copied().unwrap_or(0.0);
    point_at(stroke, &cumulative, half)
}
