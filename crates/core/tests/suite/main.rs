//! The core's integration tests, linked into one binary: each module was its own test crate,
//! and linking nine binaries against the optimized dependencies cost minutes of every cold CI
//! run (issue 15). Each module keeps its own imports and helpers.

mod animation;
mod common;
mod curve_edit;
mod deform;
mod edit;
mod editor_properties;
mod examples;
mod feature;
mod fibermesh;
mod gltf_import;
mod gltf_testdata;
mod golden_sessions;
mod optimize;
mod oversketch;
mod oversketch_pipeline;
mod paint;
mod previews;
mod print_check;
mod region_edit;
mod silhouette;
mod skeleton;
mod symmetry;
mod topology;
mod volumetric;
