//! A model made symmetric: the half on one side of the plane kept, the other replaced by its
//! mirror image, the two joined along the plane.
//!
//! The half is the mesh clipped by the plane: an edge across it is split where it crosses,
//! each triangle keeps its part on the kept side (a triangle or a quad, cut along its shorter
//! diagonal). A vertex within a fifth of its edges' mean length of the plane is first moved
//! onto it, so no split lands next to a vertex and the join has no slivers. The mirror image
//! shares the vertices on the plane, so the result is symmetric in its connectivity as well
//! as its positions: each vertex off the plane has a partner whose position is its exact
//! mirror image.

use std::collections::HashMap;

use glam::DVec3;

use super::curves::{Place, mirrored_curves};
use super::{EXACT, SymmetryError, diagonal, partners};
use crate::mesh::{HalfedgeId, INVALID, Mesh, TriSoup, VertexId};
use crate::model::{ControlCurve, MirrorPlane, Model, Side};

/// A vertex this close to the plane, relative to the mean length of its edges, moves onto it.
const SNAP: f64 = 0.2;

/// A vertex on the plane whose kept side is two separate wedges (the surface crosses the
/// plane twice there) or its whole ring (the surface touches the plane there) moves off it by
/// this much of its edges' mean length: on the plane, the half and its image would meet at
/// that one point only.
const LIFT: f64 = 0.25;

/// Marks a piece of a curve that went with the other half.
const GONE: VertexId = VertexId(INVALID);

/// `model` made symmetric about `plane`, keeping the half on side `keep`: the rest removed,
/// the kept half mirrored and joined along the plane. Its control curves on the kept side are
/// mirrored too (see [`mirrored_curves`]); its imported look and key frames go (its vertices
/// are new).
///
/// Errors: [`SymmetryError::PlaneMissesModel`] when the plane does not cut the model;
/// [`SymmetryError::JoinFailed`] when the half and its image do not make one surface.
pub fn symmetrized(model: &Model, plane: &MirrorPlane, keep: Side) -> Result<Model, SymmetryError> {
    // Where the surface folds near the plane, a vertex moved onto it can join its half and
    // the image at a point only (a bowtie): then nothing moves but what lies on the plane.
    symmetrized_with(model, plane, keep, SNAP)
        .or_else(|_| symmetrized_with(model, plane, keep, 0.0))
}

/// [`symmetrized`], moving onto the plane the vertices within `snap` of their edges' mean
/// length of it.
fn symmetrized_with(
    model: &Model,
    plane: &MirrorPlane,
    keep: Side,
    snap: f64,
) -> Result<Model, SymmetryError> {
    let mesh = &model.mesh;
    let (mut kept_distance, mean_length) = signed_distances(mesh, plane, keep, snap)?;
    let mut positions = mesh.positions().to_vec();
    for v in pinched(mesh, &kept_distance) {
        // Lifted off the plane into the kept side: its image is then a vertex of its own.
        let lift = LIFT * mean_length[v];
        kept_distance[v] = lift;
        positions[v] = plane.project(positions[v]) + keep.sign() * lift * plane.normal();
    }
    let mut half = Half::new(&positions, &kept_distance, plane);
    for face in mesh.triangles().iter().filter(|t| t[0] != INVALID) {
        half.clip(face);
    }
    let curve_chains: Vec<ControlCurve> = (model.curves.iter())
        .map(|curve| half.chain(curve))
        .collect();
    let joined = half.joined_with_image(plane);
    let mesh = Mesh::from_soup(&joined.soup).map_err(|_| SymmetryError::JoinFailed)?;
    // Where the surface folds over the plane, two of its edges can cross it at one point:
    // the result would hold that point twice, and no longer pair up.
    if partners(&mesh, plane).is_none() {
        return Err(SymmetryError::Folded);
    }
    let chains: Vec<ControlCurve> = (curve_chains.into_iter())
        .map(|curve| joined.renumbered(curve))
        .collect();
    let place = |v: VertexId| match v {
        GONE => Place::Gone,
        v if joined.on_plane[v.index()] => Place::OnPlane,
        _ => Place::Kept,
    };
    let curves = mirrored_curves(&chains, place, |v| joined.partner[v.index()]);
    Ok(Model {
        mesh,
        curves,
        name: model.name.clone(),
        ..Model::default()
    })
}

/// Each vertex's distance to the plane, positive on the kept side, zero for those within
/// `snap` of their edges' mean length of it (or [`EXACT`] of the diagonal), which move onto it.
///
/// Errors: [`SymmetryError::PlaneMissesModel`] when every vertex is on one side.
fn signed_distances(
    mesh: &Mesh,
    plane: &MirrorPlane,
    keep: Side,
    snap: f64,
) -> Result<(Vec<f64>, Vec<f64>), SymmetryError> {
    let tolerance = EXACT * diagonal(mesh);
    let mut distance: Vec<f64> = (mesh.positions().iter())
        .map(|&p| keep.sign() * plane.signed_distance(p))
        .collect();
    let crosses =
        distance.iter().any(|&s| s > tolerance) && distance.iter().any(|&s| s < -tolerance);
    if !crosses {
        return Err(SymmetryError::PlaneMissesModel);
    }
    let (mut length, mut count) = (vec![0.0; distance.len()], vec![0u32; distance.len()]);
    for t in mesh.triangles().iter().filter(|t| t[0] != INVALID) {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let l = mesh.positions()[a].distance(mesh.positions()[b]);
            for v in [a, b] {
                length[v] += l;
                count[v] += 1;
            }
        }
    }
    let mean: Vec<f64> = (length.iter().zip(&count))
        .map(|(&l, &n)| l / f64::from(n.max(1)))
        .collect();
    for (s, &mean) in distance.iter_mut().zip(&mean) {
        if s.abs() < (snap * mean).max(tolerance) {
            *s = 0.0;
        }
    }
    // An edge across the plane is split no nearer its ends than `snap` of its length: the
    // end it would be split too near moves onto the plane instead.
    let mut onto_plane = Vec::new();
    for t in mesh.triangles().iter().filter(|t| t[0] != INVALID) {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let (sa, sb) = (distance[a], distance[b]);
            if sa * sb < 0.0 {
                let at = sa / (sa - sb);
                if at < snap {
                    onto_plane.push(a);
                } else if at > 1.0 - snap {
                    onto_plane.push(b);
                }
            }
        }
    }
    for v in onto_plane {
        distance[v] = 0.0;
    }
    Ok((distance, mean))
}

/// The vertices on the plane whose triangles reaching into the kept side form two or more
/// separate wedges around them, or all of their ring.
fn pinched(mesh: &Mesh, distance: &[f64]) -> Vec<usize> {
    let reaches_in = |h: HalfedgeId| {
        let f = mesh.face(h);
        mesh.face_vertices(f)
            .iter()
            .any(|v| distance[v.index()] > 0.0)
    };
    (0..distance.len())
        .filter(|&v| distance[v] == 0.0 && mesh.is_live_vertex(VertexId(v as u32)))
        .filter(|&v| {
            let wedges: Vec<bool> = mesh
                .outgoing_halfedges(VertexId(v as u32))
                .map(reaches_in)
                .collect();
            let n = wedges.len();
            let starts = (0..n)
                .filter(|&k| wedges[k] && !wedges[(k + n - 1) % n])
                .count();
            // Two wedges, or a whole ring on the kept side (the surface touches the plane
            // there without crossing it): either way, its image would meet it at a point.
            starts >= 2 || wedges.iter().all(|&w| w)
        })
        .collect()
}

/// The kept half being built: its vertices (old ones kept, and splits of edges across the
/// plane) and triangles.
struct Half<'a> {
    /// The mesh's positions, a pinched vertex lifted off the plane.
    old_positions: &'a [DVec3],
    distance: &'a [f64],
    plane: &'a MirrorPlane,
    positions: Vec<DVec3>,
    on_plane: Vec<bool>,
    triangles: Vec<[u32; 3]>,
    kept: Vec<Option<u32>>,
    splits: HashMap<(u32, u32), u32>,
    /// The half's vertex at each point of the plane: two vertices moved onto the same point
    /// (a symmetric model's partners near the plane, both moved onto it) become one.
    on_plane_at: HashMap<[u64; 3], u32>,
}

impl<'a> Half<'a> {
    fn new(old_positions: &'a [DVec3], distance: &'a [f64], plane: &'a MirrorPlane) -> Self {
        Self {
            old_positions,
            distance,
            plane,
            positions: Vec::new(),
            on_plane: Vec::new(),
            triangles: Vec::new(),
            kept: vec![None; old_positions.len()],
            splits: HashMap::new(),
            on_plane_at: HashMap::new(),
        }
    }

    /// The half's id of old vertex `v` (on the kept side or the plane).
    fn kept_vertex(&mut self, v: u32) -> u32 {
        if let Some(id) = self.kept[v as usize] {
            return id;
        }
        let p = self.old_positions[v as usize];
        let on_plane = self.distance[v as usize] == 0.0;
        let id = self.push(if on_plane { self.plane.project(p) } else { p }, on_plane);
        self.kept[v as usize] = Some(id);
        id
    }

    /// The half's id of the point where edge `a`–`b` crosses the plane.
    fn split_vertex(&mut self, a: u32, b: u32) -> u32 {
        let key = (a.min(b), a.max(b));
        if let Some(&id) = self.splits.get(&key) {
            return id;
        }
        let (sa, sb) = (self.distance[key.0 as usize], self.distance[key.1 as usize]);
        let (pa, pb) = (
            self.old_positions[key.0 as usize],
            self.old_positions[key.1 as usize],
        );
        let crossing = pa.lerp(pb, sa / (sa - sb));
        let id = self.push(self.plane.project(crossing), true);
        self.splits.insert(key, id);
        id
    }

    fn push(&mut self, p: DVec3, on_plane: bool) -> u32 {
        let key = p.to_array().map(f64::to_bits);
        if let Some(&id) = on_plane.then(|| self.on_plane_at.get(&key)).flatten() {
            return id;
        }
        self.positions.push(p);
        self.on_plane.push(on_plane);
        let id = (self.positions.len() - 1) as u32;
        if on_plane {
            self.on_plane_at.insert(key, id);
        }
        id
    }

    fn crosses(&self, a: u32, b: u32) -> bool {
        let (sa, sb) = (self.distance[a as usize], self.distance[b as usize]);
        (sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)
    }

    /// Adds the part of triangle `t` on the kept side (none, a triangle or a quad).
    fn clip(&mut self, t: &[u32; 3]) {
        let mut polygon: Vec<u32> = Vec::with_capacity(4);
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if self.distance[a as usize] >= 0.0 {
                polygon.push(self.kept_vertex(a));
            }
            if self.crosses(a, b) {
                polygon.push(self.split_vertex(a, b));
            }
        }
        polygon.dedup();
        if polygon.len() > 1 && polygon.first() == polygon.last() {
            polygon.pop();
        }
        if polygon.len() < 3 || polygon.iter().all(|&v| self.on_plane[v as usize]) {
            return;
        }
        if polygon.len() == 4 {
            let p = |i: usize| self.positions[polygon[i] as usize];
            let (first, second) = if p(0).distance(p(2)) <= p(1).distance(p(3)) {
                ([0, 1, 2], [0, 2, 3])
            } else {
                ([1, 2, 3], [1, 3, 0])
            };
            self.triangles.push(first.map(|i| polygon[i]));
            self.triangles.push(second.map(|i| polygon[i]));
        } else {
            self.triangles.push([polygon[0], polygon[1], polygon[2]]);
        }
    }

    /// `curve` in the half's ids: its kept vertices and the splits where it crosses, with
    /// [`GONE`] for each piece on the other side.
    fn chain(&self, curve: &ControlCurve) -> ControlCurve {
        let n = curve.vertices.len();
        let mut vertices = Vec::with_capacity(n + 2);
        for (i, &a) in curve.vertices.iter().enumerate() {
            vertices.push(self.kept[a.index()].map_or(GONE, VertexId));
            let is_last = i + 1 == n;
            if is_last && !curve.is_closed {
                break;
            }
            let b = curve.vertices[(i + 1) % n];
            if let Some(&split) = self.splits.get(&(a.0.min(b.0), a.0.max(b.0))) {
                vertices.push(VertexId(split));
            }
        }
        vertices.dedup();
        ControlCurve {
            vertices,
            ..curve.clone()
        }
    }

    /// The half and its mirror image as one soup (unused vertices dropped), each vertex's
    /// partner, which vertices lie on the plane, and the new id of each of the half's.
    fn joined_with_image(self, plane: &MirrorPlane) -> Joined {
        let n = self.positions.len();
        let mut partner: Vec<u32> = (0..n as u32).collect();
        let mut positions = self.positions.clone();
        for ((own, &p), &on_plane) in partner.iter_mut().zip(&self.positions).zip(&self.on_plane) {
            if !on_plane {
                *own = positions.len() as u32;
                positions.push(plane.reflect(p));
            }
        }
        let mut triangles = self.triangles.clone();
        let image = self.triangles.iter().map(|&[a, b, c]| {
            [
                partner[a as usize],
                partner[c as usize],
                partner[b as usize],
            ]
        });
        triangles.extend(image);
        let mut on_plane = self.on_plane.clone();
        on_plane.resize(positions.len(), false);
        let mut full_partner: Vec<u32> = (0..positions.len() as u32).collect();
        for v in 0..n {
            full_partner[v] = partner[v];
            full_partner[partner[v] as usize] = v as u32;
        }
        let mut soup = TriSoup {
            positions,
            triangles,
        };
        let new_of = soup.remove_unreferenced_vertices();
        let renumber = |v: u32| new_of[v as usize];
        let mut kept_partner = vec![VertexId(0); soup.positions.len()];
        let mut kept_on_plane = vec![false; soup.positions.len()];
        for (old, new) in new_of.iter().enumerate() {
            if let Some(new) = *new {
                kept_partner[new as usize] = VertexId(renumber(full_partner[old]).unwrap_or(new));
                kept_on_plane[new as usize] = on_plane[old];
            }
        }
        Joined {
            soup,
            partner: kept_partner,
            on_plane: kept_on_plane,
            new_of,
        }
    }
}

/// The half joined with its image ([`Half::joined_with_image`]).
struct Joined {
    soup: TriSoup,
    partner: Vec<VertexId>,
    on_plane: Vec<bool>,
    /// The new id of each vertex of the half and its image (`None`: unused, dropped).
    new_of: Vec<Option<u32>>,
}

impl Joined {
    /// A curve of the half's ids in the joined mesh's.
    fn renumbered(&self, mut curve: ControlCurve) -> ControlCurve {
        for v in &mut curve.vertices {
            if *v != GONE {
                *v = self.new_of[v.index()].map_or(GONE, VertexId);
            }
        }
        curve.vertices.dedup();
        curve
    }
}
