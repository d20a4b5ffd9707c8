//! Sketchmesh's eframe app: wgpu rendering, camera, input, tools and panels.
//!
//! Algorithms live in `sketchmesh_core`; this crate only turns input into document
//! operations and draws the result. It builds natively (`main.rs`) and for the web
//! (`web.rs`, the `start` entry point the page calls).

pub mod app;
pub mod autosave;
#[cfg(target_arch = "wasm32")]
pub mod autosave_writer;
pub mod backdrop;
pub mod camera;
pub mod clock;
pub mod command;
pub mod edit_runner;
pub mod file_actions;
pub mod files;
pub mod fonts;
#[cfg(target_arch = "wasm32")]
pub mod image_decode;
pub mod input;
pub mod making;
pub mod offload;
pub mod overlay;
#[cfg(target_arch = "wasm32")]
pub mod page_store;
pub mod panels;
pub mod playback;
pub mod pointer;
pub mod render;
pub mod scene_view;
pub mod shared;
pub mod shortcuts;
pub mod status;
pub mod textures;
pub mod thumbnail;
pub mod tools;
pub mod ui_size;
pub mod view_overlay;
#[cfg(target_arch = "wasm32")]
pub mod web;

pub use app::SketchApp;
