//! Remeshing at the mesh's own resolution ([`RemeshParams::keep_resolution`]), as FiberMesh
//! does after each sketch op and on release of a curve pull: icospheres with 10,242 and
//! 40,962 vertices and a closed chain along the equator, once as they are (near-isotropic:
//! the cost of a remesh with little to do) and once with the chain's half at `x > 0` pushed
//! out by 50%, so long chain edges and stretched triangles need splits, collapses and flips.
//! Target: the whole remesh at 10k vertices well under 60 ms natively. Results go in
//! BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^remesh_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec3;
use sketchmesh_core::mesh::remesh::{Chain, RemeshParams, remesh};
use sketchmesh_core::mesh::{HalfedgeId, Mesh, VertexId, primitives};

/// The closed edge loop between faces with centroids above a slightly tilted equator plane
/// and the others (off the icosphere's symmetry planes, so the loop never touches itself).
fn equator(mesh: &Mesh) -> Chain {
    let normal = DVec3::new(0.01, 0.02, 1.0).normalize();
    let is_above = |h: HalfedgeId| {
        let [a, b, c] = mesh.face_positions(mesh.face(h));
        normal.dot(a + b + c) > 0.009
    };
    let mut head_of_tail = vec![u32::MAX; mesh.n_vertices()];
    let mut start = u32::MAX;
    for h in (0..mesh.n_halfedges() as u32).map(HalfedgeId) {
        let t = mesh.twin(h).expect("an icosphere is closed");
        if is_above(h) && !is_above(t) {
            head_of_tail[mesh.tail(h).index()] = mesh.head(h).0;
            start = start.min(mesh.tail(h).0);
        }
    }
    let mut vertices = vec![start];
    loop {
        let next = head_of_tail[*vertices.last().expect("starts non-empty") as usize];
        if next == start {
            break;
        }
        assert!(
            vertices.len() < mesh.n_vertices(),
            "the cut is not one loop"
        );
        vertices.push(next);
    }
    Chain {
        vertices: vertices.into_iter().map(VertexId).collect(),
        closed: true,
    }
}

/// The sphere with the chain's vertices at `x > 0` pushed out by half their radius.
fn stretched(mesh: &Mesh, chain: &Chain) -> Mesh {
    let mut mesh = mesh.clone();
    for &v in &chain.vertices {
        let p = &mut mesh.positions_mut()[v.index()];
        if p.x > 0.0 {
            *p *= 1.5;
        }
    }
    mesh
}

fn bench_remesh(c: &mut Criterion) {
    let mut group = c.benchmark_group("remesh_keep_resolution");
    group.sample_size(20);
    for subdivisions in [5, 6] {
        let sphere = primitives::icosphere(1.0, subdivisions);
        let chains = [equator(&sphere)];
        let params = RemeshParams::keep_resolution(&sphere);
        let cases = [
            ("sphere", sphere.clone()),
            ("stretched", stretched(&sphere, &chains[0])),
        ];
        for (name, mesh) in &cases {
            let id = BenchmarkId::from_parameter(format!("{name}_{}", sphere.n_vertices()));
            group.bench_function(id, |b| {
                b.iter(|| {
                    remesh(black_box(mesh), &chains, &params).expect("chain is an edge loop")
                });
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench_remesh);
