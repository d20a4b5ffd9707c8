//! The offscreen scene target: multisampled colour and depth, resolved for the blit.

use eframe::wgpu;

use super::pipelines::{DEPTH_FORMAT, Pipelines, SCENE_FORMAT};

/// Textures of one viewport size.
pub struct SceneTarget {
    size: [u32; 2],
    /// Multisampled colour, when MSAA is on.
    msaa: Option<wgpu::TextureView>,
    /// Single-sampled colour the blit reads.
    resolved: wgpu::TextureView,
    depth: wgpu::TextureView,
    /// Binds `resolved` for the blit.
    pub blit_bind_group: wgpu::BindGroup,
}

impl SceneTarget {
    /// Makes `slot` hold a target of `size`, recreating it only when the size changed.
    pub fn ensure(
        slot: &mut Option<SceneTarget>,
        device: &wgpu::Device,
        pipelines: &Pipelines,
        samples: u32,
        size: [u32; 2],
        sampler: &wgpu::Sampler,
        blit_params: &wgpu::Buffer,
    ) {
        if slot.as_ref().is_some_and(|t| t.size == size) {
            return;
        }
        let texture = |label, format, samples, usage| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: wgpu::Extent3d {
                        width: size[0],
                        height: size[1],
                        depth_or_array_layers: 1,
                    },
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        };
        let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let resolved = texture(
            "scene colour",
            SCENE_FORMAT,
            1,
            attachment | wgpu::TextureUsages::TEXTURE_BINDING,
        );
        let msaa =
            (samples > 1).then(|| texture("scene colour msaa", SCENE_FORMAT, samples, attachment));
        let depth = texture("scene depth", DEPTH_FORMAT, samples, attachment);
        let blit_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("blit"),
            layout: &pipelines.blit_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&resolved),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(sampler),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: blit_params.as_entire_binding(),
                },
            ],
        });
        *slot = Some(Self {
            size,
            msaa,
            resolved,
            depth,
            blit_bind_group,
        });
    }

    /// Begins the scene pass: colour cleared to transparent, depth to far.
    pub fn begin_pass(&self, encoder: &mut wgpu::CommandEncoder) -> wgpu::RenderPass<'static> {
        let (view, resolve_target) = match &self.msaa {
            Some(msaa) => (msaa, Some(&self.resolved)),
            None => (&self.resolved, None),
        };
        let color = wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                store: wgpu::StoreOp::Store,
            },
        };
        encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("scene"),
                color_attachments: &[Some(color)],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &self.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime()
    }
}
