//! Base-colour textures on the GPU: uploaded with their mip chains the first time a draw
//! needs them, dropped when no draw does; draws without a texture sample a white texel.

use std::collections::HashMap;
use std::sync::Arc;

use eframe::egui_wgpu::wgpu;
use eframe::wgpu::util::DeviceExt;

use super::geometry::MeshDraw;
use crate::textures::TextureImage;

/// The key of a decoded texture.
pub fn key(texture: &Arc<TextureImage>) -> usize {
    Arc::as_ptr(texture) as usize
}

/// The textures the current draws use, as bind groups.
pub struct MeshTextures {
    sampler: wgpu::Sampler,
    white: wgpu::BindGroup,
    uploaded: HashMap<usize, (Arc<TextureImage>, wgpu::BindGroup)>,
}

impl MeshTextures {
    /// The white texel's bind group, and no texture yet.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, layout: &wgpu::BindGroupLayout) -> Self {
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("mesh textures"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        let white = TextureImage {
            size: [1, 1],
            levels: vec![vec![255; 4]],
        };
        let white = bind_group(device, queue, layout, &sampler, &white);
        MeshTextures {
            sampler,
            white,
            uploaded: HashMap::new(),
        }
    }

    /// Uploads the textures of `draws` not on the GPU yet and drops those no draw uses.
    pub fn keep(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        draws: &[MeshDraw],
    ) {
        let used: Vec<&Arc<TextureImage>> =
            draws.iter().filter_map(|d| d.texture.as_ref()).collect();
        self.uploaded
            .retain(|k, _| used.iter().any(|t| key(t) == *k));
        for texture in used {
            if !self.uploaded.contains_key(&key(texture)) {
                let group = bind_group(device, queue, layout, &self.sampler, texture);
                self.uploaded
                    .insert(key(texture), (Arc::clone(texture), group));
            }
        }
    }

    /// The bind group of the texture keyed `texture`, or the white texel's.
    pub fn bind_group(&self, texture: Option<usize>) -> &wgpu::BindGroup {
        texture
            .and_then(|k| self.uploaded.get(&k))
            .map_or(&self.white, |(_, group)| group)
    }
}

/// An sRGB texture with `image`'s mip chain, bound with `sampler`.
fn bind_group(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    layout: &wgpu::BindGroupLayout,
    sampler: &wgpu::Sampler,
    image: &TextureImage,
) -> wgpu::BindGroup {
    let [width, height] = image.size;
    let data: Vec<u8> = image.levels.concat();
    let texture = device.create_texture_with_data(
        queue,
        &wgpu::TextureDescriptor {
            label: Some("base colour"),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: image.levels.len() as u32,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8UnormSrgb,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        &data,
    );
    let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("base colour"),
        layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(&view),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::Sampler(sampler),
            },
        ],
    })
}
