//! The 3D view: a custom wgpu pass inside egui, free of tools and UI.
//!
//! The scene is drawn in `prepare` into an offscreen target of our own (with 4× MSAA where
//! the adapter supports it, and its own depth buffer), because eframe's web painter offers
//! neither MSAA nor a depth buffer we could rely on; `paint` then composites that target
//! into egui's pass over a background gradient. Buffers are re-uploaded only when the
//! document revision changes; a frame otherwise writes one small uniform buffer.

pub mod geometry;
mod grid;
mod mesh_textures;
mod pipelines;
mod target;

use std::sync::Arc;

use bytemuck::{Pod, Zeroable};
use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait, ScreenDescriptor, wgpu};
use eframe::wgpu::util::DeviceExt;

pub use geometry::SceneGeometry;
use mesh_textures::MeshTextures;
use pipelines::Pipelines;
use target::SceneTarget;

/// Per-frame shader constants (must match `Uniforms` in scene.wgsl).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct Uniforms {
    /// World to clip space.
    pub clip_from_world: [[f32; 4]; 4],
    /// Eye position (w unused).
    pub eye: [f32; 4],
    /// Target width and height in pixels, pixels per point, 1 to draw everything as clay.
    pub viewport: [f32; 4],
}

/// What to draw besides the document.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ViewOptions {
    /// Draw mesh edges.
    pub wireframe: bool,
    /// Draw the ground grid.
    pub grid: bool,
    /// Draw imported models as clay, not in their colours.
    pub clay: bool,
}

/// GPU buffers holding one [`SceneGeometry`].
struct GeometryBuffers {
    generation: u64,
    /// The [`SceneGeometry::motion`] last written.
    motion: u64,
    vertices: Option<wgpu::Buffer>,
    triangles: Option<(wgpu::Buffer, u32)>,
    edges: Option<(wgpu::Buffer, u32)>,
    curves: Option<(wgpu::Buffer, u32)>,
    /// The triangles' runs, each with its texture's key.
    draws: Vec<(std::ops::Range<u32>, Option<usize>)>,
}

/// GPU state of the 3D view, kept in egui's callback resources.
pub struct SceneRenderer {
    pipelines: Pipelines,
    samples: u32,
    uniforms: wgpu::Buffer,
    scene_bind_group: wgpu::BindGroup,
    blit_params: wgpu::Buffer,
    sampler: wgpu::Sampler,
    grid: (wgpu::Buffer, u32),
    textures: MeshTextures,
    geometry: Option<GeometryBuffers>,
    /// The vertices of a large new [`SceneGeometry`], uploaded in pieces over frames before
    /// the rest of it, while the old geometry is still drawn.
    staged: Option<Staged>,
    target: Option<SceneTarget>,
}

/// How far [`SceneRenderer::upload`] got.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Uploaded {
    /// The buffers hold the scene.
    Wholly,
    /// Part of its vertices are uploaded; more, then the rest, come in the next frames.
    Partly,
}

/// The most bytes of a large scene's arrays uploaded in one frame: its vertices go in pieces
/// of this size, a frame each, then its triangles, edges and curves (a million triangles'
/// 28 MB of vertices and 12 MB of triangles took one frame of 61–66 ms in the page).
const UPLOAD_PIECE_BYTES: usize = 12 << 20;

/// The vertex buffer of a scene being uploaded in pieces.
struct Staged {
    generation: u64,
    /// The [`SceneGeometry::motion`] its first piece was written at.
    motion: u64,
    vertices: wgpu::Buffer,
    /// How many of its bytes are written.
    written: usize,
}

impl SceneRenderer {
    /// Creates the renderer and registers it with egui's wgpu painter.
    pub fn install(rs: &egui_wgpu::RenderState) {
        let device = &rs.device;
        let samples = msaa_samples(&rs.adapter);
        let pipelines = Pipelines::new(device, samples, rs.target_format);
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("scene uniforms"),
            size: size_of::<Uniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let scene_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene uniforms"),
            layout: &pipelines.scene_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniforms.as_entire_binding(),
            }],
        });
        // A sRGB output would encode again what the scene already wrote gamma-encoded.
        let flags: [f32; 4] = [
            if rs.target_format.is_srgb() { 1.0 } else { 0.0 },
            0.0,
            0.0,
            0.0,
        ];
        let blit_params = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("blit params"),
            contents: bytemuck::cast_slice(&flags),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("scene"),
            ..Default::default()
        });
        let grid_vertices = grid::grid_quad();
        let grid = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("grid"),
            contents: bytemuck::cast_slice(&grid_vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let textures = MeshTextures::new(device, &rs.queue, &pipelines.texture_layout);
        let renderer = Self {
            textures,
            pipelines,
            samples,
            uniforms,
            scene_bind_group,
            blit_params,
            sampler,
            grid: (grid, grid_vertices.len() as u32),
            geometry: None,
            staged: None,
            target: None,
        };
        log::info!(
            "3D view: {:?} backend, {samples}x MSAA, output {:?}",
            rs.adapter.get_info().backend,
            rs.target_format
        );
        rs.renderer.write().callback_resources.insert(renderer);
    }

    /// Brings the GPU's buffers to `scene`: whether they hold it, or only part of its
    /// vertices so far (a large scene, whose upload is spread over frames).
    fn upload(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &SceneGeometry,
    ) -> Uploaded {
        if let Some(g) = self
            .geometry
            .as_mut()
            .filter(|g| g.generation == scene.generation)
        {
            // Same arrays, moved vertices (a pull in progress): rewrite in place.
            if g.motion != scene.motion {
                g.motion = scene.motion;
                if let Some(vertices) = &g.vertices {
                    queue.write_buffer(vertices, 0, bytemuck::cast_slice(&scene.vertices));
                }
                if let Some((curves, _)) = &g.curves {
                    queue.write_buffer(curves, 0, bytemuck::cast_slice(&scene.curves));
                }
            }
            return Uploaded::Wholly;
        }
        let vertex = wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST;
        let index = wgpu::BufferUsages::INDEX;
        let bytes: &[u8] = bytemuck::cast_slice(&scene.vertices);
        let staged = (self.staged.take()).filter(|s| s.generation == scene.generation);
        let vertices = match staged {
            None if bytes.len() <= UPLOAD_PIECE_BYTES => {
                buffer(device, "mesh vertices", &scene.vertices, vertex).map(|(b, _)| b)
            }
            staged => {
                // A large scene: a piece of its vertices per frame, then the rest; the old
                // geometry is drawn meanwhile.
                let mut staged = staged.unwrap_or_else(|| Staged {
                    generation: scene.generation,
                    motion: scene.motion,
                    vertices: device.create_buffer(&wgpu::BufferDescriptor {
                        label: Some("mesh vertices"),
                        size: bytes.len() as u64,
                        usage: vertex,
                        mapped_at_creation: false,
                    }),
                    written: 0,
                });
                if staged.written < bytes.len() {
                    // Whole vertices, so a multiple of 4 bytes as a copy needs.
                    let stride = size_of::<geometry::MeshVertex>();
                    let piece =
                        (UPLOAD_PIECE_BYTES / stride * stride).min(bytes.len() - staged.written);
                    let at = staged.written;
                    queue.write_buffer(&staged.vertices, at as u64, &bytes[at..at + piece]);
                    staged.written += piece;
                    self.staged = Some(staged);
                    return Uploaded::Partly;
                }
                if staged.motion != scene.motion {
                    queue.write_buffer(&staged.vertices, 0, bytes);
                }
                Some(staged.vertices)
            }
        };
        let layout = &self.pipelines.texture_layout;
        self.textures.keep(device, queue, layout, &scene.draws);
        self.geometry = Some(GeometryBuffers {
            generation: scene.generation,
            motion: scene.motion,
            vertices,
            triangles: buffer(device, "mesh triangles", &scene.triangles, index),
            edges: buffer(device, "mesh edges", &scene.edges, index),
            curves: buffer(device, "curves", &scene.curves, vertex),
            draws: (scene.draws.iter())
                .map(|d| {
                    (
                        d.indices.clone(),
                        d.texture.as_ref().map(mesh_textures::key),
                    )
                })
                .collect(),
        });
        Uploaded::Wholly
    }

    fn draw_scene(&self, pass: &mut wgpu::RenderPass<'_>, options: ViewOptions) {
        pass.set_bind_group(0, &self.scene_bind_group, &[]);
        let Some(g) = &self.geometry else {
            return;
        };
        if let (Some(vertices), Some((triangles, n))) = (&g.vertices, &g.triangles) {
            pass.set_pipeline(&self.pipelines.mesh);
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_index_buffer(triangles.slice(..), wgpu::IndexFormat::Uint32);
            for (indices, texture) in &g.draws {
                pass.set_bind_group(1, self.textures.bind_group(*texture), &[]);
                pass.draw_indexed(indices.clone(), 0, 0..1);
            }
            debug_assert_eq!(g.draws.last().map(|d| d.0.end), Some(*n));
            if let (true, Some((edges, n))) = (options.wireframe, &g.edges) {
                pass.set_pipeline(&self.pipelines.wire);
                pass.set_index_buffer(edges.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..*n, 0, 0..1);
            }
        }
        if options.grid {
            pass.set_pipeline(&self.pipelines.grid);
            pass.set_vertex_buffer(0, self.grid.0.slice(..));
            pass.draw(0..self.grid.1, 0..1);
        }
        if let Some((curves, n)) = &g.curves {
            pass.set_vertex_buffer(0, curves.slice(..));
            for pipeline in [&self.pipelines.curve_hidden, &self.pipelines.curve_visible] {
                pass.set_pipeline(pipeline);
                pass.draw(0..6, 0..*n);
            }
        }
    }
}

fn buffer<T: Pod>(
    device: &wgpu::Device,
    label: &str,
    data: &[T],
    usage: wgpu::BufferUsages,
) -> Option<(wgpu::Buffer, u32)> {
    (!data.is_empty()).then(|| {
        let b = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(data),
            usage,
        });
        (b, data.len() as u32)
    })
}

/// 4× MSAA when both scene formats support it on a GPU, else none. A software adapter
/// (SwiftShader, llvmpipe: a machine without a GPU) rasterizes on the cores that also run
/// the page and its worker: four samples a pixel would make every frame several times
/// longer there, and a frame drawn while the worker computes longer still.
fn msaa_samples(adapter: &wgpu::Adapter) -> u32 {
    let info = adapter.get_info();
    log::info!("Adapter: {:?} {:?}", info.device_type, info.name);
    if info.device_type == wgpu::DeviceType::Cpu {
        return 1;
    }
    let supports = |format| {
        adapter
            .get_texture_format_features(format)
            .flags
            .sample_count_supported(4)
    };
    if supports(pipelines::SCENE_FORMAT) && supports(pipelines::DEPTH_FORMAT) {
        4
    } else {
        1
    }
}

/// One frame of the 3D view, handed to egui as a paint callback.
pub struct SceneCallback {
    /// The viewport rectangle in points.
    pub rect: egui::Rect,
    /// Shader constants for this frame (`viewport` is filled in by `prepare`).
    pub uniforms: Uniforms,
    /// The document's arrays (uploaded only when their generation changes).
    pub geometry: Arc<SceneGeometry>,
    /// Wireframe and grid switches.
    pub options: ViewOptions,
    /// Asked for another frame while an upload is spread over frames.
    pub repaint: egui::Context,
}

impl CallbackTrait for SceneCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen: &ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(renderer) = resources.get_mut::<SceneRenderer>() else {
            return Vec::new();
        };
        let ppp = screen.pixels_per_point;
        let size = [
            (self.rect.width() * ppp).round().max(1.0) as u32,
            (self.rect.height() * ppp).round().max(1.0) as u32,
        ];
        if renderer.upload(device, queue, &self.geometry) == Uploaded::Partly {
            self.repaint.request_repaint();
        }
        let mut uniforms = self.uniforms;
        let clay = if self.options.clay { 1.0 } else { 0.0 };
        uniforms.viewport = [size[0] as f32, size[1] as f32, ppp, clay];
        queue.write_buffer(&renderer.uniforms, 0, bytemuck::bytes_of(&uniforms));
        SceneTarget::ensure(
            &mut renderer.target,
            device,
            &renderer.pipelines,
            renderer.samples,
            size,
            &renderer.sampler,
            &renderer.blit_params,
        );
        let Some(target) = renderer.target.as_ref() else {
            return Vec::new();
        };
        let mut pass = target.begin_pass(encoder);
        renderer.draw_scene(&mut pass, self.options);
        drop(pass);
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(renderer) = resources.get::<SceneRenderer>() else {
            return;
        };
        let Some(target) = &renderer.target else {
            return;
        };
        pass.set_pipeline(&renderer.pipelines.blit);
        pass.set_bind_group(0, &target.blit_bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}
