//! The volumetric bench's problem, shared with its libigl comparison: a capsule (5,252
//! vertices, 28.6k graph points) with its left end held and its right end turned about z,
//! the turn spread linearly between them.

use glam::{DMat3, DMat4, DVec3};
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::volumetric::{
    Constraints, Falloff, Similarity, VolumetricGraph, VolumetricParams, spread,
};

/// The capsule, its graph, the constraints (both ends hard) and the geodesic distances to
/// the turned end and to the held one.
pub struct Capsule {
    pub mesh: Mesh,
    pub graph: VolumetricGraph,
    pub constraints: Constraints,
    pub params: VolumetricParams,
    to_handle: Vec<Vec<f64>>,
    to_fixed: Vec<f64>,
}

impl Capsule {
    pub fn new() -> Capsule {
        let mesh = primitives::capsule(0.5, 3.0, 42, 126);
        let graph = VolumetricGraph::build(&mesh).expect("a closed capsule");
        let points = graph.points();
        let ends = |keep: fn(f64) -> bool| -> Vec<u32> {
            (0..points.len() as u32)
                .filter(|&i| keep(points[i as usize].x))
                .collect()
        };
        let (fixed, handle) = (ends(|x| x < -2.0), ends(|x| x > 2.0));
        let mut hard = vec![false; points.len()];
        for &i in fixed.iter().chain(&handle) {
            hard[i as usize] = true;
        }
        Capsule {
            to_handle: vec![graph.distances(&mesh, &handle)],
            to_fixed: graph.distances(&mesh, &fixed),
            constraints: Constraints {
                hard,
                soft: Vec::new(),
            },
            params: VolumetricParams::default(),
            mesh,
            graph,
        }
    }

    /// The turn by `angle` about z spread over the graph into `transforms`, and where it
    /// takes a hard point (the right end turns, the left one holds).
    pub fn turn(
        &self,
        angle: f64,
        transforms: &mut [Similarity],
    ) -> impl Fn(usize, DVec3) -> DVec3 + use<> {
        let turn = Similarity::nearest(DMat3::from_rotation_z(angle)).expect("a turn");
        spread(
            &[turn],
            &self.to_handle,
            &self.to_fixed,
            Falloff::Linear,
            transforms,
        );
        let rotate = DMat4::from_rotation_z(angle);
        move |_, p: DVec3| {
            if p.x > 2.0 {
                rotate.transform_point3(p)
            } else {
                p
            }
        }
    }
}
