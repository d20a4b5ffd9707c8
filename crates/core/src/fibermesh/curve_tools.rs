//! The stroke-along-curve tools of FiberMesh (Nealen's thesis §3.2.3–3.2.4): erase, type
//! change and rub. Each finds the curve parts a screen-space stroke passes over and changes
//! the curve set or the curve points; re-optimizing the surface is the caller's.
//!
//! A stroke *passes over* a curve vertex when the vertex is visible (no surface between it
//! and the eye) and within the pick radius of the stroke polyline on the screen; it passes
//! over a curve edge when it passes over both its ends. Erase and type change act on
//! edges, so a stroke that merely crosses a curve touches at most a vertex or two and
//! changes nothing, while a stroke along it takes the part it covers; the pieces that are
//! left share their end vertices, so a curve made partly sharp stays one connected chain.
//!
//! Rubbing (§3.2.3: "moves each vertex one by one so that it locally improves inner and
//! outer fairness"; the update is not given) moves each rubbed interior vertex towards the
//! midpoint of its curve neighbours, a curve `L1` step, by an amount that grows with the
//! length of stroke passing near it, so each back-and-forth pass smooths more. Outer
//! fairness, the surface around, follows in the caller's re-optimization. Curve ends and
//! junctions stay, so the network keeps its shape.

use glam::{DVec2, DVec3};

use crate::camera::Camera;
use crate::curve::polyline::{distance_to_polyline, distance_to_segment};
use crate::geometry::{Bvh, vertex_normals};
use crate::mesh::{Mesh, VertexId};
use crate::model::{ControlCurve, CurveKind};

/// How far a rubbed vertex moves towards its neighbours' midpoint per pick radius of stroke
/// passing over it (at the stroke's centre line).
const RUB_STRENGTH: f64 = 0.35;

/// Which vertices of each curve a stroke passes over (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct StrokeHits {
    /// Per curve, per vertex.
    vertices: Vec<Vec<bool>>,
}

impl StrokeHits {
    /// Whether the stroke passes over no curve edge.
    pub fn is_empty(&self) -> bool {
        self.curve_indices().next().is_none()
    }

    /// The mesh vertices of the curve edges the stroke passes over (`curves` as given to
    /// [`hit_curves`]).
    pub fn vertices_hit(&self, curves: &[ControlCurve]) -> Vec<VertexId> {
        let mut hit = Vec::new();
        for (curve, mask) in curves.iter().zip(&self.vertices) {
            for (_, piece) in pieces(curve, mask).into_iter().filter(|(h, _)| *h) {
                hit.extend(piece.vertices.iter().copied());
            }
        }
        hit
    }

    /// The curves with at least one edge the stroke passes over.
    pub fn curve_indices(&self) -> impl Iterator<Item = usize> + '_ {
        self.vertices
            .iter()
            .enumerate()
            .filter(|(_, hit)| hit.windows(2).any(|w| w[0] && w[1]) || all_of_closed(hit))
            .map(|(k, _)| k)
    }
}

/// A one-vertex closed curve has no window of two; treat a fully hit curve as hit.
fn all_of_closed(hit: &[bool]) -> bool {
    hit.len() >= 2 && hit.iter().all(|&h| h)
}

/// The curve vertices of `mesh` that the screen-space `stroke` (CSS px, seen through
/// `camera` in `viewport`) passes over within `radius` px.
pub fn hit_curves(
    mesh: &Mesh,
    curves: &[ControlCurve],
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
    radius: f64,
) -> StrokeHits {
    let visible = VisibleCurves::new(
        mesh,
        curves.iter().flat_map(|c| &c.vertices),
        camera,
        viewport,
    );
    let vertices = curves
        .iter()
        .map(|curve| {
            curve
                .vertices
                .iter()
                .map(|&v| {
                    visible
                        .screen(v)
                        .is_some_and(|s| distance_to_polyline(s, stroke) <= radius)
                })
                .collect()
        })
        .collect();
    StrokeHits { vertices }
}

/// The curves without the edges the stroke passed over; pieces of fewer than two vertices
/// are dropped.
pub fn erase(curves: &[ControlCurve], hits: &StrokeHits) -> Vec<ControlCurve> {
    curves
        .iter()
        .zip(&hits.vertices)
        .flat_map(|(curve, hit)| pieces(curve, hit))
        .filter(|(is_hit, _)| !is_hit)
        .map(|(_, piece)| piece)
        .collect()
}

/// The curves with the edges the stroke passed over made `kind`.
pub fn set_kind(curves: &[ControlCurve], hits: &StrokeHits, kind: CurveKind) -> Vec<ControlCurve> {
    curves
        .iter()
        .zip(&hits.vertices)
        .flat_map(|(curve, hit)| pieces(curve, hit))
        .map(|(is_hit, mut piece)| {
            if is_hit {
                piece.kind = kind;
            }
            piece
        })
        .collect()
}

/// `curve` cut into runs of edges that all are, or all are not, passed over (with that
/// flag); consecutive runs share their end vertex. A curve that is all one run comes back
/// whole, closed if it was.
fn pieces(curve: &ControlCurve, hit: &[bool]) -> Vec<(bool, ControlCurve)> {
    let n = curve.vertices.len();
    let n_edges = if curve.is_closed {
        n
    } else {
        n.saturating_sub(1)
    };
    let edge_hit = |k: usize| hit[k] && hit[(k + 1) % n];
    if n_edges == 0 || (0..n_edges).all(|k| edge_hit(k) == edge_hit(0)) {
        return vec![(n_edges > 0 && edge_hit(0), curve.clone())];
    }
    // Start at a change of run, so that a closed curve's runs do not wrap.
    let start = if curve.is_closed {
        (0..n_edges)
            .find(|&k| edge_hit(k) != edge_hit((k + n_edges - 1) % n_edges))
            .unwrap_or(0)
    } else {
        0
    };
    let mut runs: Vec<(bool, ControlCurve)> = Vec::new();
    for step in 0..n_edges {
        let k = (start + step) % n_edges;
        let (a, b) = (curve.vertices[k], curve.vertices[(k + 1) % n]);
        match runs.last_mut() {
            Some((flag, piece)) if *flag == edge_hit(k) => piece.vertices.push(b),
            _ => runs.push((
                edge_hit(k),
                ControlCurve {
                    vertices: vec![a, b],
                    is_closed: false,
                    kind: curve.kind,
                },
            )),
        }
    }
    runs
}

/// The mesh positions after rubbing the curves along `stroke` (see the module docs): only
/// interior curve vertices within `radius` px of the stroke move.
pub fn rub(
    mesh: &Mesh,
    curves: &[ControlCurve],
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
    radius: f64,
) -> Vec<DVec3> {
    let visible = VisibleCurves::new(
        mesh,
        curves.iter().flat_map(|c| &c.vertices),
        camera,
        viewport,
    );
    let mut uses = vec![0u32; mesh.n_vertices()];
    for v in curves.iter().flat_map(|c| &c.vertices) {
        uses[v.index()] += 1;
    }
    // Each rubbable vertex with its two curve neighbours, and its screen position.
    let mut rubbed = Vec::new();
    for curve in curves {
        let n = curve.vertices.len();
        for k in 0..n {
            let is_end = !curve.is_closed && (k == 0 || k + 1 == n);
            let v = curve.vertices[k];
            if is_end || n < 3 || uses[v.index()] > 1 {
                continue;
            }
            if let Some(s) = visible.screen(v) {
                let (prev, next) = (curve.vertices[(k + n - 1) % n], curve.vertices[(k + 1) % n]);
                rubbed.push((v, prev, next, s));
            }
        }
    }
    let mut positions = mesh.positions().to_vec();
    for segment in stroke.windows(2) {
        let length = segment[0].distance(segment[1]);
        for &(v, prev, next, s) in &rubbed {
            let d = distance_to_segment(s, segment[0], segment[1]);
            if d > radius {
                continue;
            }
            let falloff = 1.0 - d / radius;
            let amount = (RUB_STRENGTH * length / radius * falloff * falloff).min(0.5);
            let midpoint = 0.5 * (positions[prev.index()] + positions[next.index()]);
            let p = &mut positions[v.index()];
            *p += amount * (midpoint - *p);
        }
    }
    positions
}

/// The screen positions of the visible curve vertices of a mesh in one view.
///
/// A curve vertex counts as visible when no surface lies between the eye and a point one
/// mean edge length above it (along its normal). Testing the vertex itself would hide the
/// outline of a created shape: it lies in the plane through the shape's middle, which in
/// perspective is a little behind the silhouette, so the view ray to it cuts through a
/// sliver of the front; the raised point clears that sliver and still lies behind any
/// other part of the surface.
pub struct VisibleCurves {
    screen: Vec<Option<DVec2>>,
}

impl VisibleCurves {
    /// The visible ones of the curve `vertices` of `mesh`, seen through `camera`.
    pub fn new<'a>(
        mesh: &Mesh,
        vertices: impl IntoIterator<Item = &'a VertexId>,
        camera: &Camera,
        viewport: DVec2,
    ) -> Self {
        let bvh = Bvh::new(mesh);
        let normals = vertex_normals(mesh);
        let lift = mesh.mean_edge_length();
        let mut screen = vec![None; mesh.n_vertices()];
        for &v in vertices {
            let p = mesh.position(v);
            let Some(s) = camera.screen_from_world(p, viewport) else {
                continue;
            };
            let raised = p + lift * normals[v.index()];
            let Some(raised_on_screen) = camera.screen_from_world(raised, viewport) else {
                continue;
            };
            let (origin, _) = camera.ray_in_world(raised_on_screen.truncate(), viewport);
            if !bvh.occluded(mesh, origin, raised, 0.5 * lift) {
                screen[v.index()] = Some(s.truncate());
            }
        }
        VisibleCurves { screen }
    }

    /// Where `v` is on the screen, if it is a visible curve vertex.
    pub fn screen(&self, v: VertexId) -> Option<DVec2> {
        self.screen.get(v.index()).copied().flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(n: u32, is_closed: bool) -> ControlCurve {
        ControlCurve {
            vertices: (0..n).map(VertexId).collect(),
            is_closed,
            kind: CurveKind::Smooth,
        }
    }

    fn hits(mask: &[bool]) -> StrokeHits {
        StrokeHits {
            vertices: vec![mask.to_vec()],
        }
    }

    #[test]
    fn erasing_the_middle_of_an_open_curve_leaves_two_pieces() {
        let c = curve(10, false);
        let mask: Vec<bool> = (0..10).map(|i| (3..=6).contains(&i)).collect();
        let kept = erase(std::slice::from_ref(&c), &hits(&mask));
        let ids: Vec<Vec<u32>> = kept
            .iter()
            .map(|c| c.vertices.iter().map(|v| v.0).collect())
            .collect();
        assert_eq!(ids, vec![vec![0, 1, 2, 3], vec![6, 7, 8, 9]]);
        assert!(kept.iter().all(|c| !c.is_closed));
    }

    #[test]
    fn a_crossing_that_hits_one_vertex_changes_nothing() {
        let c = curve(10, true);
        let mut mask = vec![false; 10];
        mask[4] = true;
        let h = hits(&mask);
        assert!(h.is_empty());
        assert_eq!(erase(std::slice::from_ref(&c), &h), vec![c]);
    }

    #[test]
    fn part_of_a_closed_curve_turns_sharp_as_one_connected_chain() {
        let c = curve(12, true);
        let mask: Vec<bool> = (0..12).map(|i| i >= 10 || i <= 2).collect();
        let retyped = set_kind(std::slice::from_ref(&c), &hits(&mask), CurveKind::Sharp);
        assert_eq!(retyped.len(), 2);
        let sharp: Vec<u32> = retyped
            .iter()
            .find(|c| c.kind == CurveKind::Sharp)
            .unwrap()
            .vertices
            .iter()
            .map(|v| v.0)
            .collect();
        assert_eq!(sharp, vec![10, 11, 0, 1, 2]);
        // Every edge of the original is in exactly one piece.
        let edges: usize = retyped.iter().map(|c| c.vertices.len() - 1).sum();
        assert_eq!(edges, 12);
        // All hit: the whole closed curve changes kind and stays closed.
        let all = set_kind(
            std::slice::from_ref(&c),
            &hits(&[true; 12]),
            CurveKind::Sharp,
        );
        assert_eq!(all.len(), 1);
        assert!(all[0].is_closed && all[0].kind == CurveKind::Sharp);
    }
}
