//! The render pipelines of the scene pass and the blit that shows it.

use eframe::wgpu;

use super::geometry::{CurveSegment, MeshVertex};
use super::grid::GridVertex;

/// Depth format of the offscreen scene target (available on WebGL2 and WebGPU).
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Colour format of the offscreen scene target.
pub const SCENE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// All pipelines, built once at start-up.
pub struct Pipelines {
    /// Uniforms shared by the scene pipelines.
    pub scene_layout: wgpu::BindGroupLayout,
    /// A mesh draw's base-colour texture and its sampler.
    pub texture_layout: wgpu::BindGroupLayout,
    /// Texture, sampler and flags of the blit.
    pub blit_layout: wgpu::BindGroupLayout,
    /// Lit triangles.
    pub mesh: wgpu::RenderPipeline,
    /// Mesh edges.
    pub wire: wgpu::RenderPipeline,
    /// Ground grid (a procedural quad).
    pub grid: wgpu::RenderPipeline,
    /// Curve parts hidden behind surfaces, dimmed.
    pub curve_hidden: wgpu::RenderPipeline,
    /// Curve parts in front, full strength.
    pub curve_visible: wgpu::RenderPipeline,
    /// Draws the scene texture into egui's pass.
    pub blit: wgpu::RenderPipeline,
}

struct Pass<'a> {
    device: &'a wgpu::Device,
    module: &'a wgpu::ShaderModule,
    layout: &'a wgpu::PipelineLayout,
    samples: u32,
}

impl Pass<'_> {
    #[allow(clippy::too_many_arguments)]
    fn pipeline(
        &self,
        label: &str,
        (vs, fs): (&str, &str),
        buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
        topology: wgpu::PrimitiveTopology,
        depth: (bool, wgpu::CompareFunction),
        blend: Option<wgpu::BlendState>,
    ) -> wgpu::RenderPipeline {
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(self.layout),
                vertex: wgpu::VertexState {
                    module: self.module,
                    entry_point: Some(vs),
                    compilation_options: Default::default(),
                    buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(depth.0),
                    depth_compare: Some(depth.1),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: self.samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: self.module,
                    entry_point: Some(fs),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: SCENE_FORMAT,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }
}

impl Pipelines {
    /// Builds every pipeline; `samples` is the scene's MSAA count, `output` egui's format.
    pub fn new(device: &wgpu::Device, samples: u32, output: wgpu::TextureFormat) -> Self {
        let scene_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene uniforms"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let texture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mesh texture"),
            entries: &texture_and_sampler(),
        });
        let module = device.create_shader_module(wgpu::include_wgsl!("scene.wgsl"));
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene"),
            bind_group_layouts: &[Some(&scene_layout)],
            immediate_size: 0,
        });
        let mesh_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh"),
            bind_group_layouts: &[Some(&scene_layout), Some(&texture_layout)],
            immediate_size: 0,
        });
        let pass = Pass {
            device,
            module: &module,
            layout: &layout,
            samples,
        };
        let mesh_pass = Pass {
            layout: &mesh_layout,
            ..pass
        };
        let premultiplied = Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING);
        let tri = wgpu::PrimitiveTopology::TriangleList;
        let lines = wgpu::PrimitiveTopology::LineList;
        let less = wgpu::CompareFunction::LessEqual;
        let mesh_buffers = [Some(MeshVertex::layout())];
        let curve_buffers = [Some(CurveSegment::layout())];
        let (blit_layout, blit) = blit_pipeline(device, output);
        Self {
            mesh: mesh_pass.pipeline(
                "mesh",
                ("vs_mesh", "fs_mesh"),
                &mesh_buffers,
                tri,
                (true, less),
                None,
            ),
            wire: pass.pipeline(
                "wire",
                ("vs_wire", "fs_wire"),
                &mesh_buffers,
                lines,
                (false, less),
                premultiplied,
            ),
            grid: pass.pipeline(
                "grid",
                ("vs_grid", "fs_grid"),
                &[Some(GridVertex::layout())],
                tri,
                (false, less),
                premultiplied,
            ),
            curve_hidden: pass.pipeline(
                "curve hidden",
                ("vs_curve", "fs_curve_hidden"),
                &curve_buffers,
                tri,
                (false, wgpu::CompareFunction::Greater),
                premultiplied,
            ),
            curve_visible: pass.pipeline(
                "curve visible",
                ("vs_curve", "fs_curve_visible"),
                &curve_buffers,
                tri,
                (false, less),
                premultiplied,
            ),
            scene_layout,
            texture_layout,
            blit_layout,
            blit,
        }
    }
}

/// A filterable 2D texture (binding 0) and its filtering sampler (binding 1), for the
/// fragment stage.
fn texture_and_sampler() -> [wgpu::BindGroupLayoutEntry; 2] {
    [
        wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: true },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        },
        wgpu::BindGroupLayoutEntry {
            binding: 1,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        },
    ]
}

fn blit_pipeline(
    device: &wgpu::Device,
    output: wgpu::TextureFormat,
) -> (wgpu::BindGroupLayout, wgpu::RenderPipeline) {
    let [texture, sampler] = texture_and_sampler();
    let flags = wgpu::BindGroupLayoutEntry {
        binding: 2,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("blit"),
        entries: &[texture, sampler, flags],
    });
    let module = device.create_shader_module(wgpu::include_wgsl!("blit.wgsl"));
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("blit"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("blit"),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs_blit"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs_blit"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: output,
                blend: None,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    });
    (layout, pipeline)
}

impl MeshVertex {
    const ATTRIBUTES: [wgpu::VertexAttribute; 5] = wgpu::vertex_attr_array![
        0 => Float32x3, 1 => Float32x3, 2 => Float32x2, 3 => Float32x4, 4 => Float32x2
    ];

    fn layout() -> wgpu::VertexBufferLayout<'static> {
        wgpu::VertexBufferLayout {
            array_stride: size_of::<Self>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &Self::ATTRIBUTES,
        }
    }
}

impl CurveSegment {
    const ATTRIBUTES: [wgpu::VertexAttribute; 5] = wgpu::vertex_attr_array![
        0 => Float32x3, 1 => Float32, 2 => Float32x3, 3 => Float32, 4 => Float32x4
    ];

    fn layout() -> wgpu::VertexBufferLayout<'static> {
        wgpu::VertexBufferLayout {
            array_stride: size_of::<Self>() as u64,
            step_mode: wgpu::VertexStepMode::Instance,
            attributes: &Self::ATTRIBUTES,
        }
    }
}

impl GridVertex {
    const ATTRIBUTES: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![0 => Float32x3];

    fn layout() -> wgpu::VertexBufferLayout<'static> {
        wgpu::VertexBufferLayout {
            array_stride: size_of::<Self>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &Self::ATTRIBUTES,
        }
    }
}
