// Sketchmesh scene shaders: lit meshes, wireframe, grid lines and screen-space thick curves.
// Colours are written premultiplied and gamma-encoded into an offscreen target that
// `blit.wgsl` composites over the background.

struct Uniforms {
    clip_from_world: mat4x4<f32>,
    eye: vec4<f32>,
    // x, y: target size in physical pixels; z: pixels per point; w: 1 to draw as clay.
    viewport: vec4<f32>,
};

@group(0) @binding(0) var<uniform> u: Uniforms;
// A mesh draw's base-colour texture (sRGB, so sampled linear; white where there is none).
@group(1) @binding(0) var base_texture: texture_2d<f32>;
@group(1) @binding(1) var base_sampler: sampler;

fn to_srgb(linear: vec3<f32>) -> vec3<f32> {
    return pow(clamp(linear, vec3<f32>(0.0), vec3<f32>(1.0)), vec3<f32>(1.0 / 2.2));
}

// The linear gray of a fall-off level (the app's harness test reads it back).
fn falloff_gray(weight: f32) -> f32 {
    return mix(0.04, 1.0, weight);
}

// ---- meshes -------------------------------------------------------------------------

struct MeshOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) world: vec3<f32>,
    // A region edit's fall-off weight in [0, 1] (negative: the model's own colour) and how
    // many gray levels show it.
    @location(2) shade: vec2<f32>,
    // The imported linear colour; alpha 0 for clay.
    @location(3) color: vec4<f32>,
    @location(4) uv: vec2<f32>,
};

@vertex
fn vs_mesh(
    @location(0) pos: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) shade: vec2<f32>,
    @location(3) color: vec4<f32>,
    @location(4) uv: vec2<f32>,
) -> MeshOut {
    var out: MeshOut;
    out.clip = u.clip_from_world * vec4<f32>(pos, 1.0);
    out.normal = normal;
    out.world = pos;
    out.shade = shade;
    out.color = color;
    out.uv = uv;
    return out;
}

@fragment
fn fs_mesh(in: MeshOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    // Sampled before any branch: texture sampling needs uniform control flow.
    let texel = textureSample(base_texture, base_sampler, in.uv);
    let to_eye = normalize(u.eye.xyz - in.world);
    var n = normalize(in.normal);
    // Two-sided: open surfaces and imported soups show their back faces, tinted.
    var base = vec3<f32>(0.78, 0.74, 0.68);
    if (in.color.a > 0.0 && u.viewport.w < 0.5) {
        base = in.color.rgb * texel.rgb;
    }
    if (dot(n, to_eye) < 0.0) {
        n = -n;
        base = base * vec3<f32>(0.7, 0.6, 0.73);
    }
    // A key light above the viewer's shoulder, a fill from below and a hemisphere ambient.
    let key = normalize(to_eye + vec3<f32>(0.4, 0.8, 0.2));
    if (in.shade.x >= 0.0) {
        // The fall-off as the thesis shows it, a gray-scale texture in N levels: white moves
        // fully, black not, unlit so that each level reads as its weight. The weight is
        // rounded here, per pixel, so the levels meet in crisp lines across triangles.
        let steps = max(in.shade.y - 1.0, 1.0);
        let level = round(clamp(in.shade.x, 0.0, 1.0) * steps) / steps;
        return vec4<f32>(to_srgb(vec3<f32>(falloff_gray(level))), 1.0);
    }
    let fill = normalize(vec3<f32>(-0.5, -0.3, 0.6));
    let diffuse = max(dot(n, key), 0.0) * 0.75 + max(dot(n, fill), 0.0) * 0.15;
    let ambient = mix(0.12, 0.25, n.y * 0.5 + 0.5);
    let half_vector = normalize(key + to_eye);
    let specular = pow(max(dot(n, half_vector), 0.0), 48.0) * 0.25;
    let rim = pow(1.0 - max(dot(n, to_eye), 0.0), 3.0) * 0.15;
    let linear = base * (diffuse + ambient) + vec3<f32>(specular + rim);
    return vec4<f32>(to_srgb(linear), 1.0);
}

// ---- wireframe (mesh edges as lines, pulled slightly towards the eye) ----------------

@vertex
fn vs_wire(@location(0) pos: vec3<f32>, @location(1) normal: vec3<f32>) -> @builtin(position) vec4<f32> {
    var clip = u.clip_from_world * vec4<f32>(pos, 1.0);
    clip.z = clip.z - 0.0004 * clip.w;
    return clip;
}

@fragment
fn fs_wire() -> @location(0) vec4<f32> {
    return vec4<f32>(0.12, 0.13, 0.16, 1.0) * 0.6;
}

// ---- grid: a quad on y = 0 whose lines are computed per fragment ----------------------

struct GridOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_grid(@location(0) pos: vec3<f32>) -> GridOut {
    var out: GridOut;
    out.clip = u.clip_from_world * vec4<f32>(pos, 1.0);
    out.world = pos;
    return out;
}

// Coverage (0..1) of lines every `spacing` units, about one pixel wide.
fn grid_lines(coord: vec2<f32>, spacing: f32) -> f32 {
    let c = coord / spacing;
    let width = fwidth(c);
    let distance = abs(fract(c - 0.5) - 0.5) / max(width, vec2<f32>(1e-6));
    return 1.0 - min(min(distance.x, distance.y), 1.0);
}

@fragment
fn fs_grid(in: GridOut) -> @location(0) vec4<f32> {
    let coord = in.world.xz;
    let fade = 1.0 - smoothstep(6.0, 22.0, length(coord));
    let minor = grid_lines(coord, 1.0) * 0.16;
    let major = grid_lines(coord, 5.0) * 0.32;
    var color = vec3<f32>(0.7, 0.72, 0.78);
    var alpha = max(minor, major);
    // The X axis (z = 0) in red and the Z axis (x = 0) in blue.
    let width = fwidth(coord);
    let on_x_axis = 1.0 - min(abs(coord.y) / max(width.y, 1e-6), 1.0);
    let on_z_axis = 1.0 - min(abs(coord.x) / max(width.x, 1e-6), 1.0);
    if (on_x_axis > 0.0) {
        color = vec3<f32>(0.85, 0.3, 0.3);
        alpha = max(alpha, on_x_axis * 0.8);
    } else if (on_z_axis > 0.0) {
        color = vec3<f32>(0.3, 0.5, 0.9);
        alpha = max(alpha, on_z_axis * 0.8);
    }
    let a = alpha * fade;
    return vec4<f32>(color * a, a);
}

// ---- curves: each instance is one segment, expanded to a screen-space quad ------------

struct CurveOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    // Signed distance across the line in pixels, and the half width.
    @location(1) across: vec2<f32>,
};

@vertex
fn vs_curve(
    @builtin(vertex_index) corner: u32,
    @location(0) p0: vec3<f32>,
    @location(1) w0: f32,
    @location(2) p1: vec3<f32>,
    @location(3) w1: f32,
    @location(4) color: vec4<f32>,
) -> CurveOut {
    // Two triangles: (t, side) for corners 0..6.
    var ts = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    var sides = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let t = ts[corner];
    let side = sides[corner];
    let c0 = u.clip_from_world * vec4<f32>(p0, 1.0);
    let c1 = u.clip_from_world * vec4<f32>(p1, 1.0);
    var out: CurveOut;
    if (c0.w <= 1e-5 || c1.w <= 1e-5) {
        // Behind the eye: drop the segment rather than draw it inverted.
        out.clip = vec4<f32>(2.0, 2.0, 2.0, 1.0);
        return out;
    }
    let half_size = 0.5 * u.viewport.xy;
    let s0 = c0.xy / c0.w * half_size;
    let s1 = c1.xy / c1.w * half_size;
    var dir = s1 - s0;
    let len = length(dir);
    dir = select(vec2<f32>(1.0, 0.0), dir / max(len, 1e-6), len > 1e-6);
    let normal = vec2<f32>(-dir.y, dir.x);
    // Half width in pixels plus one pixel of feather for antialiasing.
    let half_width = 0.5 * mix(w0, w1, t) * u.viewport.z + 1.0;
    let c = select(c0, c1, t > 0.5);
    // Extend each end by the half width so consecutive segments join without gaps.
    let offset_px = normal * side * half_width + dir * (t * 2.0 - 1.0) * half_width;
    out.clip = vec4<f32>(c.xy + offset_px / half_size * c.w, c.z - 0.002 * c.w, c.w);
    out.color = color;
    out.across = vec2<f32>(side * half_width, half_width);
    return out;
}

fn curve_alpha(in: CurveOut) -> f32 {
    return clamp(in.across.y - abs(in.across.x), 0.0, 1.0);
}

@fragment
fn fs_curve_visible(in: CurveOut) -> @location(0) vec4<f32> {
    let a = in.color.a * curve_alpha(in);
    return vec4<f32>(in.color.rgb * a, a);
}

@fragment
fn fs_curve_hidden(in: CurveOut) -> @location(0) vec4<f32> {
    let a = in.color.a * curve_alpha(in) * 0.3;
    return vec4<f32>(in.color.rgb * a, a);
}
