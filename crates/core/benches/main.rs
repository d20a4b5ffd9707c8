//! The criterion benches of `sketchmesh-core`, one binary with a module per area: linked
//! once, where fourteen binaries each linked the core, faer and criterion again in the CI's
//! build. Every group: `cargo bench -p sketchmesh-core` (what `cargo xtask bench` runs); one
//! module's groups: the filter its doc gives, e.g.
//! `cargo bench -p sketchmesh-core --bench core -- '^volumetric/'`. Results go in
//! BENCHMARKS.md.

/// What several benches build: created shapes, scans, the over-sketch's sphere, the
/// volumetric capsule (`benches/common/`; the examples include some of them too).
mod common {
    pub mod feature;
    pub mod fibermesh_shape;
    pub mod oversketch;
    pub mod scan;
    pub mod volumetric_capsule;
}

mod add_curve;
mod curve_edit;
mod deform;
mod feature;
mod fibermesh;
mod gltf;
mod optimize;
mod oversketch;
mod paint;
mod region_edit;
mod remesh;
mod silhouette;
mod skeleton;
mod solve;
mod symmetry;
mod volumetric;

criterion::criterion_main!(
    add_curve::benches,
    curve_edit::benches,
    deform::benches,
    feature::benches,
    fibermesh::benches,
    gltf::benches,
    optimize::benches,
    oversketch::benches,
    paint::benches,
    region_edit::benches,
    remesh::benches,
    silhouette::benches,
    skeleton::benches,
    solve::benches,
    symmetry::benches,
    volumetric::benches,
);
