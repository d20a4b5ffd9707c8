// Composites the offscreen scene (premultiplied, gamma-encoded) over a soft gradient.

struct BlitOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

struct BlitParams {
    // x: 1 when the output target is sRGB (then we must write linear values).
    flags: vec4<f32>,
};

@group(0) @binding(0) var scene: texture_2d<f32>;
@group(0) @binding(1) var scene_sampler: sampler;
@group(0) @binding(2) var<uniform> params: BlitParams;

@vertex
fn vs_blit(@builtin(vertex_index) i: u32) -> BlitOut {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    var out: BlitOut;
    out.clip = vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
    out.uv = vec2<f32>(uv.x, 1.0 - uv.y);
    return out;
}

@fragment
fn fs_blit(in: BlitOut) -> @location(0) vec4<f32> {
    let scene_color = textureSample(scene, scene_sampler, in.uv);
    let top = vec3<f32>(0.20, 0.22, 0.26);
    let bottom = vec3<f32>(0.09, 0.10, 0.12);
    let background = mix(top, bottom, in.uv.y);
    var color = background * (1.0 - scene_color.a) + scene_color.rgb;
    if (params.flags.x > 0.5) {
        color = pow(color, vec3<f32>(2.2));
    }
    return vec4<f32>(color, 1.0);
}
