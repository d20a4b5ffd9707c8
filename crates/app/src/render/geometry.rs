//! GPU-ready arrays built from the document, once per document revision.
//!
//! A rebuild copies the arrays of every model that did not change since the last one (the
//! same `Arc`, not moved by a preview) instead of building them again: after an import of a
//! million triangles, an op on another model would otherwise spend a quarter of a second
//! (in the page) rebuilding the scan's arrays.
//!
//! Kept free of wgpu so it can be tested natively and shared (in an `Arc`) between the UI
//! thread and the paint callback. Only [`SceneGeometry::move_model`] runs per frame (while an
//! edit moves a model's vertices, as a pull's preview does): it rewrites one model's vertices
//! and curves in place, allocating nothing.

use std::borrow::Cow;
use std::collections::HashMap;
use std::ops::Range;

use bytemuck::{Pod, Zeroable};
use glam::DVec3;
use sketchmesh_core::document::{Document, Model};
use sketchmesh_core::model::Appearance;
use std::sync::Arc;

use crate::textures::{TextureImage, Textures};
use sketchmesh_core::geometry::{vertex_normals, vertex_normals_of};
use sketchmesh_core::mesh::{HalfedgeId, Mesh, VertexId};
use sketchmesh_core::paint::shown_colors;

/// A mesh vertex as the shaders read it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct MeshVertex {
    /// Position in world space.
    pub pos: [f32; 3],
    /// Unit normal.
    pub normal: [f32; 3],
    /// A region edit's fall-off weight at this vertex and the number of gray levels that
    /// show it (0 black: stays, 1 white: moves fully), or [`NO_SHADE`] for the model's own
    /// colour.
    pub shade: [f32; 2],
    /// The imported colour it is drawn with (linear RGBA), or [`CLAY`].
    pub color: [f32; 4],
    /// Its base-colour texture coordinate (0, 0 where the face has no texture).
    pub uv: [f32; 2],
}

/// A run of [`SceneGeometry::triangles`] drawn with one base-colour texture.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshDraw {
    /// The run, in indices (three per triangle).
    pub indices: Range<u32>,
    /// The texture, if the faces have one (decoded).
    pub texture: Option<Arc<TextureImage>>,
}

/// What a model's vertices (painted) or an imported model's triangle corners
/// (`3 * face + k`) bring to its drawing.
#[derive(Clone, Copy, Debug, Default)]
struct Corners<'a> {
    /// Linear RGBA per vertex: a model coloured here (paint, material), which is drawn in
    /// them and not in any imported look.
    vertex_colors: Option<&'a [[f32; 4]]>,
    /// Linear RGBA colours.
    colors: Option<&'a [[f32; 4]]>,
    /// The file's unit normals, while they still apply.
    normals: Option<&'a [[f32; 3]]>,
    /// Texture coordinates, with each face's texture (an index into the list, or
    /// [`NO_TEXTURE`]).
    textures: Option<FaceTextures<'a>>,
}

/// The decoded base-colour textures of a model's faces.
#[derive(Clone, Copy, Debug)]
struct FaceTextures<'a> {
    uvs: &'a [[f32; 2]],
    slots: &'a [u32],
    list: &'a [Arc<TextureImage>],
}

/// A face without a texture in [`FaceTextures::slots`].
const NO_TEXTURE: u32 = u32::MAX;

/// The textures of `look`'s faces that are decoded in `textures`: each face's slot in the
/// list, or `None` when no face shows one.
fn face_textures(
    look: &Appearance,
    textures: &Textures,
) -> Option<(Vec<u32>, Vec<Arc<TextureImage>>)> {
    look.uvs.as_ref()?;
    let mut list: Vec<Arc<TextureImage>> = Vec::new();
    let slots: Vec<u32> = (look.face_materials.iter())
        .map(|m| {
            let texture = m
                .and_then(|m| look.materials.get(m as usize))
                .and_then(|m| m.base_color_texture.as_ref())
                .and_then(|t| textures.get(&t.image));
            texture.map_or(NO_TEXTURE, |t| {
                let at = list.iter().position(|known| Arc::ptr_eq(known, &t));
                at.unwrap_or_else(|| {
                    list.push(t);
                    list.len() - 1
                }) as u32
            })
        })
        .collect();
    (!list.is_empty()).then_some((slots, list))
}

/// The smallest box holding `points`.
fn bounds_of(points: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let first = *points.first()?;
    Some(
        points
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))),
    )
}

/// [`MeshVertex::color`] of a vertex drawn as clay (alpha 0: no imported colour).
pub const CLAY: [f32; 4] = [0.0; 4];

/// [`MeshVertex::shade`] of a vertex drawn in the model's own colour.
pub const NO_SHADE: [f32; 2] = [-1.0, 0.0];

/// One segment of a thick curve: two end points with widths in points, and a colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct CurveSegment {
    /// Start in world space.
    pub p0: [f32; 3],
    /// Width at the start, in points.
    pub w0: f32,
    /// End in world space.
    pub p1: [f32; 3],
    /// Width at the end, in points.
    pub w1: f32,
    /// Straight (not premultiplied) RGBA.
    pub color: [f32; 4],
}

/// Ink colour of free sketches.
pub const SKETCH_COLOR: [f32; 4] = [0.95, 0.78, 0.32, 1.0];
/// Colour of smooth control curves (FiberMesh shows them blue).
pub const SMOOTH_CURVE_COLOR: [f32; 4] = [0.25, 0.55, 1.0, 1.0];
/// Colour of sharp control curves (red).
pub const SHARP_CURVE_COLOR: [f32; 4] = [0.95, 0.25, 0.2, 1.0];
/// Colour of imported points.
pub const POINT_COLOR: [f32; 4] = [0.75, 0.85, 0.95, 1.0];
/// Size of imported points in points.
pub const POINT_SIZE: f32 = 3.0;
/// Width of control curves in points.
pub const CONTROL_CURVE_WIDTH: f32 = 3.0;

/// Where one model's data sit in a [`SceneGeometry`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelRange {
    /// Its drawn vertices: one per mesh vertex, or more where corners of one vertex take
    /// different colours.
    pub vertices: Range<usize>,
    /// Its mesh's vertex count.
    pub mesh_vertices: usize,
    /// Its control curves' segments.
    pub curves: Range<usize>,
    /// Its triangle indices.
    triangles: Range<usize>,
    /// Its edge indices.
    edges: Range<usize>,
    /// Its own runs by texture, relative to `triangles.start` (in the scene's draws, runs
    /// without a texture are joined across models).
    draws: Vec<MeshDraw>,
    /// Its bounds.
    bounds: Option<(DVec3, DVec3)>,
    /// The model the arrays show, while they show it as it is (`None` once a preview moved
    /// or shaded them): a rebuild copies them when the document still holds this model.
    source: Option<Arc<Model>>,
}

/// Everything the scene pass draws that comes from the document.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneGeometry {
    /// Changes with every rebuild, so the GPU side knows when to upload.
    pub generation: u64,
    /// Changes with every [`SceneGeometry::move_model`], so the GPU side rewrites the vertex
    /// and curve buffers in place.
    pub motion: u64,
    /// Where each model's vertices and curve segments are, in document order.
    pub model_ranges: Vec<ModelRange>,
    /// All models' vertices, concatenated.
    pub vertices: Vec<MeshVertex>,
    /// For each of `vertices`, the index of the mesh vertex it draws, in its model.
    pub welded: Vec<u32>,
    /// `triangles` in runs by texture.
    pub draws: Vec<MeshDraw>,
    /// A shade per mesh vertex, kept between [`SceneGeometry::shade_model`] calls.
    shades: Vec<[f32; 2]>,
    /// Triangle indices into `vertices`.
    pub triangles: Vec<u32>,
    /// Edge indices (pairs) for the wireframe.
    pub edges: Vec<u32>,
    /// Thick curve segments.
    pub curves: Vec<CurveSegment>,
    /// Bounds of everything drawn, for framing.
    pub bounds: Option<(DVec3, DVec3)>,
}

/// A model with this many vertices has its normals computed in a frame before its arrays
/// (see [`NormalsAhead`]).
const AHEAD_MIN_VERTICES: usize = 100_000;

/// The vertex normals of the large models a rebuild will build anew, computed a frame
/// ahead of their arrays: for a million triangles landing in the page the normals are
/// 22–31 ms of a 50–64 ms build, which in two frames stays under 50 ms each.
#[derive(Default)]
pub struct NormalsAhead(Vec<(Arc<Model>, Vec<DVec3>)>);

impl NormalsAhead {
    /// The large models of `doc` that `previous` does not show and that have no normals
    /// here yet.
    fn wanted<'d>(
        &self,
        doc: &'d Document,
        previous: Option<&SceneGeometry>,
    ) -> impl Iterator<Item = &'d Arc<Model>> {
        let is_shown = move |m: &Arc<Model>| previous.is_some_and(|p| p.range_of(m).is_some());
        (doc.models.iter()).filter(move |m| {
            m.mesh.n_vertices() >= AHEAD_MIN_VERTICES && !is_shown(m) && self.of(m).is_none()
        })
    }

    /// Whether a rebuild of `doc` after `previous` wants normals computed ahead first (the
    /// arrays then wait for the frame after them).
    pub fn is_wanted(&self, doc: &Document, previous: Option<&SceneGeometry>) -> bool {
        self.wanted(doc, previous).next().is_some()
    }

    /// Computes the normals [`NormalsAhead::is_wanted`] asks for.
    pub fn compute(&mut self, doc: &Document, previous: Option<&SceneGeometry>) {
        let wanted: Vec<Arc<Model>> = self.wanted(doc, previous).cloned().collect();
        for model in wanted {
            let normals = vertex_normals(&model.mesh);
            self.0.push((model, normals));
        }
    }

    /// Whether no normals wait for their arrays.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The normals computed for `model`.
    fn of(&self, model: &Arc<Model>) -> Option<&[DVec3]> {
        (self.0.iter())
            .find(|(m, _)| Arc::ptr_eq(m, model))
            .map(|(_, normals)| &normals[..])
    }
}

impl SceneGeometry {
    /// Builds the arrays for `doc` as `generation`, with the textures decoded so far and
    /// the wireframe's edges if `with_edges` (a million triangles' edges are a quarter of the
    /// arrays' build, for a view that is off by default), copying from `previous` (built
    /// with the same textures and edges) the models it already shows.
    /// The normals of a large model come from `ahead` when it has them.
    pub fn build(
        doc: &Document,
        generation: u64,
        textures: &Textures,
        previous: Option<&SceneGeometry>,
        with_edges: bool,
        ahead: &NormalsAhead,
    ) -> Self {
        let mut scene = Self {
            generation,
            ..Self::default()
        };
        for shared in &doc.models {
            let built = previous.and_then(|previous| Some((previous, previous.range_of(shared)?)));
            if let Some((previous, range)) = built {
                scene.copy_model(previous, range);
                continue;
            }
            let model = shared.as_ref();
            let (vertices, curves) = (scene.vertices.len(), scene.curves.len());
            let (triangles, edges) = (scene.triangles.len(), scene.edges.len());
            let coloured_here = model.vertex_colors().is_some() || model.finish.is_some();
            let vertex_colors: Option<Vec<[f32; 4]>> = coloured_here.then(|| {
                let alpha = model.finish().base_color[3];
                (shown_colors(model).into_iter())
                    .map(|[r, g, b]| [r, g, b, alpha])
                    .collect()
            });
            let look = (model.appearance.as_deref())
                .filter(|a| !coloured_here && a.is_drawn() && a.fits(&model.mesh));
            let colors = look.and_then(|a| a.corner_colors());
            let normals =
                (look.filter(|a| a.normals_fit(&model.mesh))).and_then(|a| a.normals.as_deref());
            let faces = look.and_then(|a| face_textures(a, textures));
            let welded = match ahead.of(shared) {
                Some(normals) => Cow::Borrowed(normals),
                None => Cow::Owned(vertex_normals(&model.mesh)),
            };
            let draws = scene.add_mesh(
                &model.mesh,
                with_edges,
                &welded,
                Corners {
                    vertex_colors: vertex_colors.as_deref(),
                    colors: colors.as_deref(),
                    normals,
                    textures: look.zip(faces.as_ref()).and_then(|(a, (slots, list))| {
                        Some(FaceTextures {
                            uvs: a.uvs.as_deref()?,
                            slots,
                            list,
                        })
                    }),
                },
            );
            for curve in &model.curves {
                let color = if curve.is_sharp() {
                    SHARP_CURVE_COLOR
                } else {
                    SMOOTH_CURVE_COLOR
                };
                let points = curve.points(&model.mesh);
                let widths = vec![f64::from(CONTROL_CURVE_WIDTH); points.len()];
                scene.add_polyline(&points, &widths, curve.is_closed, color);
            }
            scene.model_ranges.push(ModelRange {
                vertices: vertices..scene.vertices.len(),
                mesh_vertices: model.mesh.n_vertices(),
                curves: curves..scene.curves.len(),
                triangles: triangles..scene.triangles.len(),
                edges: edges..scene.edges.len(),
                draws,
                bounds: bounds_of(model.mesh.positions()),
                source: Some(Arc::clone(shared)),
            });
            let bounds = scene.model_ranges.last().and_then(|range| range.bounds);
            scene.grow_to(bounds);
        }
        for sketch in &doc.sketches {
            let widths: Vec<f64> = sketch
                .pressures
                .iter()
                .map(|&p| pressure_width(p))
                .collect();
            scene.add_polyline(&sketch.points, &widths, false, SKETCH_COLOR);
        }
        for cloud in &doc.point_clouds {
            scene.add_points(&cloud.positions, cloud.colors.as_deref());
        }
        scene
    }

    /// The arrays of `model`, when these were built from it.
    fn range_of(&self, model: &Arc<Model>) -> Option<&ModelRange> {
        (self.model_ranges.iter())
            .find(|r| r.source.as_ref().is_some_and(|s| Arc::ptr_eq(s, model)))
    }

    /// Shows `model` (the model at `index` in the document this was built from) with its
    /// vertices at `positions`: rewrites its vertices, normals and control curves in place.
    /// `normals` is scratch space the caller keeps between frames.
    pub fn move_model(
        &mut self,
        index: usize,
        model: &Model,
        positions: &[DVec3],
        normals: &mut Vec<DVec3>,
    ) {
        let Some(range) = self.model_ranges.get(index).cloned() else {
            return;
        };
        if range.mesh_vertices != positions.len() {
            return;
        }
        vertex_normals_of(model.mesh.triangles(), positions, normals);
        self.model_ranges[index].source = None;
        let drawn = range.vertices.clone();
        for (vertex, &v) in self.vertices[drawn.clone()]
            .iter_mut()
            .zip(&self.welded[drawn])
        {
            vertex.pos = positions[v as usize].as_vec3().to_array();
            vertex.normal = normals[v as usize].as_vec3().to_array();
        }
        let mut segments = self.curves[range.curves].iter_mut();
        for curve in &model.curves {
            let n = curve.vertices.len();
            let n_segments = if curve.is_closed && n > 2 {
                n
            } else {
                n.saturating_sub(1)
            };
            let at = |k: usize| positions[curve.vertices[k % n].index()];
            for k in 0..n_segments {
                if let Some(segment) = segments.next() {
                    segment.p0 = at(k).as_vec3().to_array();
                    segment.p1 = at(k + 1).as_vec3().to_array();
                }
            }
        }
        self.motion += 1;
    }

    /// Draws model `index`'s fall-off: each of `vertices` in gray by its weight, rounded per
    /// pixel to one of `levels` evenly spaced levels (the thesis' gray levels), the rest of
    /// the model in its own colour. Allocates nothing: it runs with every drag frame's move.
    pub fn shade_model(
        &mut self,
        index: usize,
        vertices: &[VertexId],
        weights: &[f64],
        levels: usize,
    ) {
        let Some(range) = self.model_ranges.get(index).cloned() else {
            return;
        };
        self.model_ranges[index].source = None;
        self.shades.clear();
        self.shades.resize(range.mesh_vertices, NO_SHADE);
        for (v, &w) in vertices.iter().zip(weights) {
            if let Some(shade) = self.shades.get_mut(v.index()) {
                *shade = [w.clamp(0.0, 1.0) as f32, levels.max(2) as f32];
            }
        }
        let drawn = range.vertices;
        for (vertex, &v) in self.vertices[drawn.clone()]
            .iter_mut()
            .zip(&self.welded[drawn])
        {
            vertex.shade = self.shades[v as usize];
        }
        self.motion += 1;
    }

    /// A mesh, drawn as clay or in its corners' colours, with its corners' own normals
    /// where the file's still apply: a vertex whose corners differ is drawn once per colour
    /// and normal, so colours meet in crisp lines along material borders and a box keeps its
    /// edges, instead of blending across triangles.
    /// Returns its runs by texture, relative to its first triangle index.
    fn add_mesh(
        &mut self,
        mesh: &Mesh,
        with_edges: bool,
        normals: &[DVec3],
        corners: Corners<'_>,
    ) -> Vec<MeshDraw> {
        let (positions, triangles) = (mesh.positions(), mesh.triangle_indices());
        // Grown once (growing by pushes copied a million-triangle scan's arrays many times).
        self.vertices.reserve(positions.len());
        self.welded.reserve(positions.len());
        self.triangles.reserve(triangles.len());
        if with_edges {
            self.edges.reserve(triangles.len());
        }
        let base = self.vertices.len() as u32;
        let first = self.triangles.len();
        let vertex = |v: u32, normal: [f32; 3], color, uv| MeshVertex {
            pos: positions[v as usize].as_vec3().to_array(),
            normal,
            shade: NO_SHADE,
            color,
            uv,
        };
        let welded = |v: u32| normals[v as usize].as_vec3().to_array();
        // Faces in runs by texture, each run one draw; without textures, one run in order
        // (no list of a million faces to sort).
        let n_faces = triangles.len() / 3;
        let slot = |f: usize| corners.textures.map_or(NO_TEXTURE, |t| t.slots[f]);
        let faces: Option<Vec<usize>> = corners.textures.map(|_| {
            let mut faces: Vec<usize> = (0..n_faces).collect();
            faces.sort_by_key(|&f| slot(f));
            faces
        });
        let face_at = |i: usize| faces.as_ref().map_or(i, |faces| faces[i]);
        let varied = corners
            .colors
            .filter(|c| c.windows(2).any(|w| w[0] != w[1]));
        if varied.is_none() && corners.normals.is_none() && corners.textures.is_none() {
            let color = corners.colors.and_then(|c| c.first().copied());
            let color = color.unwrap_or(CLAY);
            for v in 0..positions.len() as u32 {
                let color = corners.vertex_colors.map_or(color, |c| c[v as usize]);
                self.vertices.push(vertex(v, welded(v), color, [0.0; 2]));
                self.welded.push(v);
            }
            self.triangles.extend(triangles.iter().map(|i| base + i));
        } else {
            type Key = (u32, [u32; 4], [u32; 3], [u32; 2]);
            let mut drawn: HashMap<Key, u32> = HashMap::new();
            for f in (0..n_faces).map(face_at) {
                for c in 3 * f..3 * f + 3 {
                    let v = triangles[c];
                    let color = corners.colors.map_or(CLAY, |colors| colors[c]);
                    let normal = corners.normals.map_or_else(|| welded(v), |n| n[c]);
                    let uv = match corners.textures {
                        Some(t) if t.slots[f] != NO_TEXTURE => t.uvs[c],
                        _ => [0.0; 2],
                    };
                    let key = (
                        v,
                        color.map(f32::to_bits),
                        normal.map(f32::to_bits),
                        uv.map(f32::to_bits),
                    );
                    let next = self.vertices.len() as u32;
                    let index = *drawn.entry(key).or_insert(next);
                    if index == next {
                        self.vertices.push(vertex(v, normal, color, uv));
                        self.welded.push(v);
                    }
                    self.triangles.push(index);
                }
            }
        }
        // Each edge once: by its boundary half-edge, or by the lower of its two half-edges
        // (a hash set of vertex pairs cost 0.3 s at a million triangles in the page).
        let drawn = if with_edges {
            &self.triangles[first..]
        } else {
            &[]
        };
        for (i, drawn) in drawn.chunks_exact(3).enumerate() {
            let f = face_at(i);
            for k in 0..3 {
                let h = HalfedgeId((3 * f + k) as u32);
                if mesh.twin(h).is_none_or(|twin| h < twin) {
                    self.edges.extend([drawn[k], drawn[(k + 1) % 3]]);
                }
            }
        }
        let first = first as u32;
        let runs: Vec<(u32, usize)> = match &faces {
            Some(faces) => (faces.chunk_by(|&a, &b| slot(a) == slot(b)))
                .map(|run| (slot(run[0]), run.len()))
                .collect(),
            None if n_faces > 0 => vec![(NO_TEXTURE, n_faces)],
            None => Vec::new(),
        };
        let mut own = Vec::new();
        let mut start = 0;
        for (slot, len) in runs {
            let end = start + 3 * len as u32;
            let texture = corners
                .textures
                .and_then(|t| t.list.get(slot as usize).cloned());
            self.add_draw(first + start..first + end, texture.clone());
            own.push(MeshDraw {
                indices: start..end,
                texture,
            });
            start = end;
        }
        own
    }

    /// Appends the arrays `previous` built for one model (`range`), their indices moved to
    /// where they now start.
    fn copy_model(&mut self, previous: &SceneGeometry, range: &ModelRange) {
        let (vertices, curves) = (self.vertices.len(), self.curves.len());
        let (triangles, edges) = (self.triangles.len(), self.edges.len());
        self.vertices
            .extend_from_slice(&previous.vertices[range.vertices.clone()]);
        self.welded
            .extend_from_slice(&previous.welded[range.vertices.clone()]);
        let shift = vertices as i64 - range.vertices.start as i64;
        for (to, from) in [
            (
                &mut self.triangles,
                &previous.triangles[range.triangles.clone()],
            ),
            (&mut self.edges, &previous.edges[range.edges.clone()]),
        ] {
            match shift {
                0 => to.extend_from_slice(from),
                _ => to.extend(from.iter().map(|&i| (i64::from(i) + shift) as u32)),
            }
        }
        for draw in &range.draws {
            let at = triangles as u32;
            self.add_draw(
                at + draw.indices.start..at + draw.indices.end,
                draw.texture.clone(),
            );
        }
        self.curves
            .extend_from_slice(&previous.curves[range.curves.clone()]);
        self.grow_to(range.bounds);
        self.model_ranges.push(ModelRange {
            vertices: vertices..self.vertices.len(),
            curves: curves..self.curves.len(),
            triangles: triangles..self.triangles.len(),
            edges: edges..self.edges.len(),
            ..range.clone()
        });
    }

    /// Adds a run of triangles, joining it to the last draw when both have no texture.
    fn add_draw(&mut self, indices: Range<u32>, texture: Option<Arc<TextureImage>>) {
        match self.draws.last_mut() {
            Some(last)
                if last.texture.is_none()
                    && texture.is_none()
                    && last.indices.end == indices.start =>
            {
                last.indices.end = indices.end;
            }
            _ => self.draws.push(MeshDraw { indices, texture }),
        }
    }

    fn add_polyline(&mut self, points: &[DVec3], widths: &[f64], closed: bool, color: [f32; 4]) {
        let n = points.len();
        let n_segments = if closed && n > 2 {
            n
        } else {
            n.saturating_sub(1)
        };
        for i in 0..n_segments {
            let j = (i + 1) % n;
            self.curves.push(CurveSegment {
                p0: points[i].as_vec3().to_array(),
                w0: widths[i] as f32,
                p1: points[j].as_vec3().to_array(),
                w1: widths[j] as f32,
                color,
            });
        }
        for p in points {
            self.grow_bounds(*p);
        }
    }

    /// Points as zero-length segments, which the curve shader draws as squares.
    fn add_points(&mut self, positions: &[DVec3], colors: Option<&[[f32; 4]]>) {
        for (k, p) in positions.iter().enumerate() {
            let p32 = p.as_vec3().to_array();
            self.curves.push(CurveSegment {
                p0: p32,
                w0: POINT_SIZE,
                p1: p32,
                w1: POINT_SIZE,
                color: colors
                    .and_then(|c| c.get(k))
                    .copied()
                    .unwrap_or(POINT_COLOR),
            });
            self.grow_bounds(*p);
        }
    }

    /// Grows the bounds to hold a model's.
    fn grow_to(&mut self, bounds: Option<(DVec3, DVec3)>) {
        if let Some((lo, hi)) = bounds {
            self.grow_bounds(lo);
            self.grow_bounds(hi);
        }
    }

    fn grow_bounds(&mut self, p: DVec3) {
        self.bounds = Some(match self.bounds {
            None => (p, p),
            Some((lo, hi)) => (lo.min(p), hi.max(p)),
        });
    }
}

/// Stroke width in points for a pen pressure, shared by the live stroke and stored sketches.
pub fn pressure_width(pressure: f64) -> f64 {
    1.5 + 6.0 * pressure.clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use sketchmesh_core::mesh::primitives::{grid, icosphere};

    fn model(mesh: Mesh) -> Arc<Model> {
        Arc::new(Model {
            mesh,
            ..Model::default()
        })
    }

    /// `doc`'s arrays with no texture decoded and no normals computed ahead.
    fn built(
        doc: &Document,
        generation: u64,
        previous: Option<&SceneGeometry>,
        with_edges: bool,
    ) -> SceneGeometry {
        let (textures, ahead) = (Textures::default(), NormalsAhead::default());
        SceneGeometry::build(doc, generation, &textures, previous, with_edges, &ahead)
    }

    fn document(models: Vec<Arc<Model>>) -> Document {
        Document {
            models,
            ..Document::default()
        }
    }

    #[test]
    fn a_large_new_model_has_its_normals_computed_a_frame_ahead() {
        let (large, small) = (model(icosphere(1.0, 7)), model(icosphere(1.0, 2)));
        assert!(large.mesh.n_vertices() >= AHEAD_MIN_VERTICES);
        let textures = Textures::default();
        let doc = document(vec![Arc::clone(&small), Arc::clone(&large)]);
        let mut ahead = NormalsAhead::default();
        assert!(
            ahead.is_wanted(&doc, None),
            "the large model's normals are wanted"
        );
        ahead.compute(&doc, None);
        assert!(!ahead.is_wanted(&doc, None), "once");
        assert!(ahead.of(&large).is_some() && ahead.of(&small).is_none());
        let ahead_built = SceneGeometry::build(&doc, 1, &textures, None, false, &ahead);
        assert_eq!(
            ahead_built,
            built(&doc, 1, None, false),
            "the same arrays, bit for bit"
        );
        // Shown already: nothing to compute ahead when the next document keeps it.
        let next = document(vec![large, model(icosphere(1.0, 1))]);
        assert!(!NormalsAhead::default().is_wanted(&next, Some(&ahead_built)));
    }

    #[test]
    fn each_edge_is_drawn_once() {
        let (sphere, sheet) = (icosphere(1.0, 2), grid(4, 3, 1.0));
        let doc = document(vec![model(sphere.clone()), model(sheet.clone())]);
        let scene = built(&doc, 1, None, true);
        // Without the wireframe, the same scene but its edges.
        let unwired = built(&doc, 1, None, false);
        assert!(unwired.edges.is_empty());
        assert_eq!(
            SceneGeometry {
                edges: Vec::new(),
                model_ranges: Vec::new(),
                ..scene.clone()
            },
            SceneGeometry {
                model_ranges: Vec::new(),
                ..unwired
            }
        );
        // Every edge of both, closed and open, once.
        assert_eq!(3 * sphere.n_faces() / 2, sphere.n_edges());
        assert_eq!(scene.edges.len() / 2, sphere.n_edges() + sheet.n_edges());
        let mut pairs: Vec<(u32, u32)> = (scene.edges.chunks_exact(2))
            .map(|e| (e[0].min(e[1]), e[0].max(e[1])))
            .collect();
        pairs.sort_unstable();
        pairs.dedup();
        assert_eq!(pairs.len(), scene.edges.len() / 2, "no edge twice");
    }

    #[test]
    fn a_rebuild_copies_unchanged_models_and_rebuilds_the_rest() {
        let (a, b, c) = (
            model(icosphere(1.0, 2)),
            model(grid(5, 5, 2.0)),
            model(icosphere(0.5, 1)),
        );
        let before = document(vec![a.clone(), b.clone()]);
        let mut previous = built(&before, 1, None, true);
        // A mark on b's first drawn vertex: if the rebuild copies b, the mark comes along.
        let b_first = previous.model_ranges[1].vertices.start;
        previous.vertices[b_first].uv = [7.0, 7.0];

        // a replaced by a smaller sphere (b's indices move), c appended.
        let a2 = model(icosphere(1.0, 1));
        let after = document(vec![a2, b.clone(), c]);
        let rebuilt = built(&after, 2, Some(&previous), true);
        let fresh = built(&after, 2, None, true);
        let b_now = rebuilt.model_ranges[1].vertices.start;
        assert_eq!(rebuilt.vertices[b_now].uv, [7.0, 7.0], "b was copied");
        let mut unmarked = rebuilt.clone();
        unmarked.vertices[b_now].uv = [0.0, 0.0];
        assert_eq!(unmarked, fresh, "the copy is what a build gives");

        // A model a preview moved is built again, not copied.
        let mut moved = fresh.clone();
        let positions: Vec<DVec3> = (b.mesh.positions().iter()).map(|p| *p + DVec3::Z).collect();
        moved.move_model(1, &b, &positions, &mut Vec::new());
        let again = built(&after, 3, Some(&moved), true);
        assert_eq!(again.vertices, fresh.vertices);
    }
}
