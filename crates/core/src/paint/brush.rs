//! The round brush: a pen stroke over a model becomes dabs, balls around the points of the
//! surface under the pen, and each vertex a dab reaches takes the brush's colour in the
//! measure of its distance from the dab's centre.
//!
//! A vertex is painted once per stroke, with the strongest of the dabs that reached it
//! ([`PaintStroke`]): a stroke's overlapping dabs do not pile up past its opacity, as a
//! brush stroke at constant pressure lays one even coat. Only faces turned towards the eye
//! are painted, so a brush over a thin part does not colour its far side.
//!
//! Cost: a dab asks the hierarchy for the faces within its ball ([`Bvh::faces_within`]),
//! so a sample costs what the brush covers, not what the model holds.

use glam::{DVec2, DVec3};

use crate::camera::Camera;
use crate::geometry::{Bvh, face_normal};
use crate::mesh::{Mesh, VertexId};
use crate::model::MirrorPlane;

/// How the brush paints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Brush {
    /// Linear RGB, each 0..1.
    pub color: [f32; 3],
    /// Radius in CSS px at full pressure.
    pub radius: f64,
    /// The part of the radius painted at full strength (0: soft all the way, 1: a hard
    /// disc).
    pub hardness: f64,
    /// How much of the colour a stroke lays down, 0..1.
    pub opacity: f64,
}

impl Brush {
    /// This brush with its numbers in range (NaN as 0): a session's out-of-range colour or
    /// opacity is clamped, not refused.
    pub fn clamped(self) -> Brush {
        let unit = |x: f64| if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        Brush {
            color: self.color.map(|c| unit(f64::from(c)) as f32),
            radius: if self.radius.is_finite() {
                self.radius.max(0.0)
            } else {
                0.0
            },
            hardness: unit(self.hardness),
            opacity: unit(self.opacity),
        }
    }

    /// The radius in px at a sample's pressure. Full at pressure 0.5 and above: the mouse
    /// and a finger report 0.5, and paint at the size the panel shows; a pen pressed
    /// lightly paints finer, down to a tenth.
    pub fn radius_at(&self, pressure: f64) -> f64 {
        self.radius * (2.0 * pressure).clamp(0.1, 1.0)
    }

    /// The strength a point at `distance` from a dab's centre is painted with.
    fn strength(&self, distance: f64, radius: f64) -> f64 {
        let t = distance / radius;
        if t.is_nan() || t >= 1.0 {
            return 0.0;
        }
        let soft = if t <= self.hardness {
            1.0
        } else {
            let s = (t - self.hardness) / (1.0 - self.hardness);
            1.0 - s * s * (3.0 - 2.0 * s)
        };
        self.opacity * soft
    }
}

/// Where the eye is, to tell the faces turned towards it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Eye {
    /// A perspective camera's eye.
    At(DVec3),
    /// An orthographic camera's view direction.
    Along(DVec3),
}

impl Eye {
    fn of(camera: &Camera) -> Eye {
        match camera.ortho_height {
            Some(_) => Eye::Along(camera.forward()),
            None => Eye::At(camera.eye),
        }
    }

    fn sees(&self, point: DVec3, normal: DVec3) -> bool {
        let toward_eye = match *self {
            Eye::At(eye) => eye - point,
            Eye::Along(forward) => -forward,
        };
        normal.dot(toward_eye) > 0.0
    }

    fn mirrored(&self, plane: &MirrorPlane) -> Eye {
        match *self {
            Eye::At(eye) => Eye::At(plane.reflect(eye)),
            Eye::Along(forward) => Eye::Along(plane.reflect_vector(forward)),
        }
    }
}

/// One touch of the brush: the ball around a point of the surface under the pen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dab {
    /// The point of the surface under the pen.
    pub center: DVec3,
    /// The brush's radius there, in world units.
    pub radius: f64,
    eye: Eye,
}

/// The dab at the mirror image of `dab` across `plane`, seen from the mirrored eye: what
/// symmetry paints on the other side.
pub fn mirrored_dab(dab: &Dab, plane: &MirrorPlane) -> Dab {
    Dab {
        center: plane.reflect(dab.center),
        radius: dab.radius,
        eye: dab.eye.mirrored(plane),
    }
}

/// The dabs along the stroke from sample `from` (none: the stroke's first sample) to `to`,
/// each `[x, y, pressure]` in CSS px: a quarter of the brush radius apart at most, as a
/// fast pen's samples lie far apart, each where the view ray meets `mesh`; the points off
/// the model make none. `from` itself is not dabbed again.
pub fn dabs_between(
    camera: &Camera,
    viewport: DVec2,
    from: Option<[f64; 3]>,
    to: [f64; 3],
    brush: &Brush,
    mesh: &Mesh,
    bvh: &Bvh,
) -> Vec<Dab> {
    let eye = Eye::of(camera);
    let [x, y, pressure] = to;
    let (start, steps) = match from {
        Some([fx, fy, fp]) => {
            let length = DVec2::new(x - fx, y - fy).length();
            let spacing = (0.25 * brush.radius_at(pressure.min(fp))).max(0.5);
            ([fx, fy, fp], (length / spacing).ceil().max(1.0) as usize)
        }
        None => (to, 1),
    };
    let mut dabs = Vec::with_capacity(steps);
    for k in 1..=steps {
        let t = k as f64 / steps as f64;
        let at = |i: usize| start[i] + (to[i] - start[i]) * t;
        let screen = DVec2::new(at(0), at(1));
        let (origin, dir) = camera.ray_in_world(screen, viewport);
        let Some(hit) = bvh.raycast(mesh, origin, dir) else {
            continue;
        };
        let center = origin + dir * hit.distance;
        let depth = (center - camera.eye).dot(camera.forward());
        let radius = brush.radius_at(at(2)) * camera.world_per_pixel(depth, viewport);
        if radius > 0.0 && radius.is_finite() {
            dabs.push(Dab {
                center,
                radius,
                eye,
            });
        }
    }
    dabs
}

/// What one stroke paints on one mesh: the strength of each vertex it reached.
#[derive(Clone, Debug, Default)]
pub struct PaintStroke {
    /// Per vertex of the mesh, the strongest dab's strength so far (0: untouched).
    strength: Vec<f32>,
    /// The vertices with a strength, in the order they were first reached.
    touched: Vec<VertexId>,
}

impl PaintStroke {
    /// A stroke on a mesh of `n_vertices` that has painted nothing yet.
    pub fn new(n_vertices: usize) -> Self {
        Self {
            strength: vec![0.0; n_vertices],
            touched: Vec::new(),
        }
    }

    /// Paints one dab of `brush` on `mesh` (with its hierarchy `bvh`): each vertex of a face
    /// within the dab's ball that faces the eye.
    pub fn dab(&mut self, mesh: &Mesh, bvh: &Bvh, dab: &Dab, brush: &Brush) {
        bvh.faces_within(mesh, dab.center, dab.radius, |f| {
            let corners = mesh.face_vertices(f);
            let centroid = mesh.face_positions(f).iter().sum::<DVec3>() / 3.0;
            if !dab.eye.sees(centroid, face_normal(mesh, f)) {
                return;
            }
            for v in corners {
                let distance = mesh.position(v).distance(dab.center);
                let strength = brush.strength(distance, dab.radius) as f32;
                let slot = &mut self.strength[v.index()];
                if strength > *slot {
                    if *slot == 0.0 {
                        self.touched.push(v);
                    }
                    *slot = strength;
                }
            }
        });
    }

    /// Whether no dab reached a vertex.
    pub fn is_empty(&self) -> bool {
        self.touched.is_empty()
    }

    /// The vertices painted, in the order they were first reached.
    pub fn touched(&self) -> &[VertexId] {
        &self.touched
    }

    /// `colors` (one per vertex) with the stroke laid over them in `color`.
    pub fn apply(&self, colors: &mut [[f32; 3]], color: [f32; 3]) {
        for &v in &self.touched {
            let w = self.strength[v.index()];
            let old = &mut colors[v.index()];
            // Weighted so that full strength lays the colour exactly.
            *old = std::array::from_fn(|i| old[i] * (1.0 - w) + color[i] * w);
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::{DVec2, DVec3};

    use super::*;
    use crate::mesh::primitives;

    fn front_camera() -> Camera {
        Camera {
            eye: DVec3::new(0.0, 0.0, 4.0),
            ..Camera::default()
        }
    }

    const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

    fn brush(hardness: f64, opacity: f64) -> Brush {
        Brush {
            color: [1.0, 0.0, 0.0],
            radius: 40.0,
            hardness,
            opacity,
        }
    }

    #[test]
    fn a_dab_paints_a_disc_on_the_near_side_only() {
        let mesh = primitives::icosphere(1.0, 4);
        let bvh = Bvh::new(&mesh);
        let camera = front_camera();
        let brush = brush(1.0, 1.0);
        let dabs = dabs_between(
            &camera,
            VIEWPORT,
            None,
            [400.0, 300.0, 0.5],
            &brush,
            &mesh,
            &bvh,
        );
        assert_eq!(dabs.len(), 1);
        assert!((dabs[0].center - DVec3::Z).length() < 1e-2);
        let mut stroke = PaintStroke::new(mesh.n_vertices());
        stroke.dab(&mesh, &bvh, &dabs[0], &brush);
        assert!(!stroke.is_empty());
        for &v in stroke.touched() {
            let p = mesh.position(v);
            assert!(p.z > 0.0, "a back vertex was painted");
            assert!(p.distance(dabs[0].center) <= dabs[0].radius + 1e-9);
        }
        // 40 px at depth 3 with a 45° lens over 600 px: the ball's radius in world units.
        let expected = 40.0 * 2.0 * 3.0 * 22.5f64.to_radians().tan() / 600.0;
        assert!((dabs[0].radius - expected).abs() < 1e-2 * expected);
    }

    #[test]
    fn overlapping_dabs_lay_one_coat_at_the_opacity() {
        let mesh = primitives::icosphere(1.0, 4);
        let bvh = Bvh::new(&mesh);
        let brush = brush(1.0, 0.5);
        let camera = front_camera();
        let mut stroke = PaintStroke::new(mesh.n_vertices());
        let mut from = None;
        for x in [390.0, 400.0, 410.0, 400.0, 390.0] {
            let to = [x, 300.0, 0.5];
            for dab in dabs_between(&camera, VIEWPORT, from, to, &brush, &mesh, &bvh) {
                stroke.dab(&mesh, &bvh, &dab, &brush);
            }
            from = Some(to);
        }
        let mut colors = vec![[0.0, 0.0, 1.0]; mesh.n_vertices()];
        stroke.apply(&mut colors, brush.color);
        let centre = (mesh.vertices())
            .max_by(|&a, &b| mesh.position(a).z.total_cmp(&mesh.position(b).z))
            .unwrap();
        assert_eq!(colors[centre.index()], [0.5, 0.0, 0.5]);
    }

    #[test]
    fn soft_brushes_fade_to_nothing_at_the_rim() {
        let brush = brush(0.5, 1.0);
        assert_eq!(brush.strength(0.2, 1.0), 1.0);
        assert!((brush.strength(0.75, 1.0) - 0.5).abs() < 1e-12);
        assert_eq!(brush.strength(1.0, 1.0), 0.0);
        assert!(brush.strength(0.9, 1.0) < brush.strength(0.6, 1.0));
    }

    #[test]
    fn a_fast_stroke_is_dabbed_all_along() {
        let mesh = primitives::icosphere(1.0, 4);
        let bvh = Bvh::new(&mesh);
        let brush = brush(1.0, 1.0);
        let camera = front_camera();
        let dabs = dabs_between(
            &camera,
            VIEWPORT,
            Some([300.0, 300.0, 0.5]),
            [500.0, 300.0, 0.5],
            &brush,
            &mesh,
            &bvh,
        );
        // 200 px at most 10 px apart.
        assert!(dabs.len() >= 20, "{} dabs", dabs.len());
    }

    #[test]
    fn out_of_range_numbers_are_clamped() {
        let wild = Brush {
            color: [2.0, -1.0, f32::NAN],
            radius: f64::INFINITY,
            hardness: 3.0,
            opacity: -0.5,
        }
        .clamped();
        assert_eq!(wild.color, [1.0, 0.0, 0.0]);
        assert_eq!((wild.radius, wild.hardness, wild.opacity), (0.0, 1.0, 0.0));
    }
}
