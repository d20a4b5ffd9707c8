//! Importing a glTF file as Sketchmesh models, sketches and point clouds.
//!
//! Each node instance with triangles becomes one model: its primitives are merged, vertices
//! with the same position are welded (glTF splits them at UV and normal seams, editing needs
//! them joined), and the result is made manifold ([`crate::mesh::make_manifold`]) when it is
//! not already. What the file said about the look (normals, UVs, colours, materials) is kept
//! per triangle corner in an [`Appearance`] so export can write it back. Line primitives
//! become sketches and point primitives point clouds. Nodes written by Sketchmesh bring back
//! their control curves (as chains of the mesh's vertices, see `curves.rs`) and their
//! sketches with pen pressure, from the node extras.

use std::collections::HashMap;
use std::sync::Arc;

use glam::DVec3;

use super::curves::{AttachedCurves, attach_curves};
use super::error::GltfError;
use super::extras::MirrorExtras;
use super::extras::{CLAY_MATERIAL_NAME, FINISH_MATERIAL_NAME};
use super::input::{ImportFile, ImportLimits};
use super::parse::parse;
use super::resources::{Buffers, load_buffers, resolve};
use super::scene::{NodeGeometry, Surface, read_nodes};
use super::weld::weld;
use crate::mesh::{FaceId, Mesh, RepairReport, TriSoup, make_manifold};
use crate::model::{
    AlphaMode, Appearance, AsImported, Finish, Image, Keyframe, Material, MirrorPlane, Model,
    PointCloud, SketchCurve, Texture, positions_hash, positions_hash_of,
};
use crate::symmetry::{Keep, are_twins_within, mirror_positions, mirrored_model, partners_within};

/// Pen pressure given to imported line primitives (the pressure of a mouse stroke).
const LINE_PRESSURE: f64 = 0.5;

/// What a file brought in.
#[derive(Clone, Debug, Default)]
pub struct Imported {
    /// One model per node instance with triangles.
    pub models: Vec<Model>,
    /// Line primitives, and Sketchmesh sketches.
    pub sketches: Vec<SketchCurve>,
    /// Point primitives.
    pub point_clouds: Vec<PointCloud>,
    /// Things the user may want to know (repairs made, textures left behind), as sentences.
    pub notes: Vec<String>,
    /// The symmetry plane of the Sketchmesh document the file was written from, if it had
    /// one; its symmetric models and mirror twins are made exact again (see [`restore_symmetry`]).
    pub symmetry: Option<MirrorPlane>,
}

/// Imports the default scene of `main` (.glb or .gltf); `others` are the files given with it
/// (a .gltf's .bin and images). Never fetches anything and never panics on bad input.
///
/// Errors: anything unreadable, inconsistent or over `limits`, as one sentence.
pub fn import_gltf(
    main: &ImportFile,
    others: &[ImportFile],
    limits: &ImportLimits,
) -> Result<Imported, GltfError> {
    let parsed = parse(main.bytes, limits)?;
    let buffers = load_buffers(&parsed.document, parsed.blob, others);
    let nodes = read_nodes(&parsed.document, &buffers, limits)?;
    let mut materials = MaterialCache::new(&parsed.document, &buffers, others);
    let mut imported = Imported::default();
    let mut mirrors = Vec::new();
    for node in nodes {
        add_node(node, &mut materials, &mut imported, &mut mirrors)?;
    }
    restore_symmetry(&mut imported, &mirrors);
    imported.notes.append(&mut materials.notes);
    if imported.models.is_empty()
        && imported.sketches.is_empty()
        && imported.point_clouds.is_empty()
    {
        return Err(GltfError::NothingToImport);
    }
    Ok(imported)
}

fn add_node(
    node: NodeGeometry,
    materials: &mut MaterialCache,
    imported: &mut Imported,
    mirrors: &mut Vec<Option<MirrorExtras>>,
) -> Result<(), GltfError> {
    let NodeGeometry {
        name,
        extras,
        mut surface,
        lines,
        points,
    } = node;
    let extras = extras.map(|extras| extras.sketchmesh);
    match &extras {
        // A Sketchmesh node's line strips are its sketches, kept exactly in the extras.
        Some(extras) if !extras.sketches.is_empty() => {
            imported
                .sketches
                .extend(extras.sketches.iter().map(|sketch| SketchCurve {
                    points: sketch.points.iter().map(|&p| DVec3::from(p)).collect(),
                    pressures: sketch.pressures.clone(),
                }));
        }
        _ => imported
            .sketches
            .extend(
                lines
                    .into_iter()
                    .filter(|l| l.len() >= 2)
                    .map(|points| SketchCurve {
                        pressures: vec![LINE_PRESSURE; points.len()],
                        points,
                    }),
            ),
    }
    imported
        .point_clouds
        .extend(points.into_iter().map(|points| PointCloud {
            positions: points.positions,
            colors: points.colors,
        }));
    if surface.triangles.is_empty() {
        return Ok(());
    }
    let model_name = name.clone().unwrap_or_else(|| String::from("unnamed node"));
    let is_sketchmesh = extras.is_some();
    let Welded {
        mut mesh,
        face_source,
        input,
    } = weld_and_repair(&mut surface, &model_name, &mut imported.notes)?;
    let keyframes = key_poses(&mesh, &surface, &face_source);
    if surface.skipped_keys > 0 {
        imported.notes.push(format!(
            "{model_name}'s animation has {} frames; {} of them, evenly spread, became key frames.",
            surface.key_times.len() + surface.skipped_keys,
            surface.key_times.len()
        ));
    }
    let mirror = extras.as_ref().and_then(|extras| extras.mirror.clone());
    let attached = extras
        .map(|extras| attach_curves(&mut mesh, &extras.curves))
        .unwrap_or_default();
    note_curves(&attached, &model_name, &mut imported.notes);
    let is_clay = is_sketchmesh
        && !surface.has_uvs
        && !surface.has_colors
        && distinct(&surface.face_materials).into_iter().all(|m| {
            m.and_then(|m| materials.get(m))
                .is_some_and(|m| m.name.as_deref() == Some(CLAY_MATERIAL_NAME))
        });
    let mesh_appearance = (!is_clay).then(|| {
        let hash = positions_hash(&mesh);
        Arc::new(appearance(
            mesh.triangles(),
            hash,
            &surface,
            &face_source,
            materials,
        ))
    });
    // A model coloured here comes back as its paint and finish, to paint on again.
    let coloured_here = (mesh_appearance.as_deref())
        .filter(|_| is_sketchmesh && input.is_none())
        .and_then(|look| colours_made_here(look, &mesh));
    let (mesh_appearance, colors, finish) = match coloured_here {
        Some((colors, finish)) => (None, colors, finish),
        None => (mesh_appearance, None, None),
    };
    let as_imported = input.map(|(soup, vertex_source)| {
        let appearance = (!is_clay).then(|| {
            let identity: Vec<(FaceId, bool)> = (0..soup.triangles.len())
                .map(|f| (FaceId(f as u32), false))
                .collect();
            let hash = positions_hash_of(&soup.positions);
            Arc::new(appearance(
                &soup.triangles,
                hash,
                &surface,
                &identity,
                materials,
            ))
        });
        Arc::new(AsImported {
            mesh_triangles: mesh.triangles().to_vec(),
            soup,
            vertex_source,
            appearance,
        })
    });
    mirrors.push(mirror);
    imported.models.push(Model {
        mesh,
        curves: attached.curves,
        name: if is_clay { None } else { name },
        appearance: mesh_appearance,
        as_imported,
        keyframes,
        colors: colors.map(Arc::new),
        finish,
    });
    Ok(())
}

/// How far, relative to a model's diagonal, a file's vertex may be from its partner's mirror
/// image: its positions are 32-bit floats.
const FILE_PAIRING: f64 = 1e-5;

/// Makes the symmetric models and mirror twins a Sketchmesh file names (`mirrors`, one per
/// model) exact again: a symmetric model's pairs meet halfway, a twin becomes the mirror
/// image of the model it pairs with. A model that no longer pairs up (edited elsewhere) is
/// left as it came; the plane is kept for the document.
fn restore_symmetry(imported: &mut Imported, mirrors: &[Option<MirrorExtras>]) {
    for (index, mirror) in mirrors.iter().enumerate() {
        let Some(MirrorExtras { plane, twin }) = mirror else {
            continue;
        };
        imported.symmetry = Some(*plane);
        match twin {
            Some(j) if *j > index && *j < imported.models.len() => {
                let (model, other) = (&imported.models[index], &imported.models[*j]);
                if are_twins_within(&model.mesh, &other.mesh, plane, FILE_PAIRING) {
                    imported.models[*j] = mirrored_model(model, plane);
                }
            }
            Some(_) => {}
            None => {
                let model = &mut imported.models[index];
                if let Some(pairs) = partners_within(&model.mesh, plane, FILE_PAIRING) {
                    let sides_from = model.mesh.positions().to_vec();
                    let positions = model.mesh.positions_mut();
                    mirror_positions(&sides_from, positions, &pairs, plane, Keep::Average);
                }
            }
        }
    }
}

/// The node's animated poses as key frames of `mesh`: each mesh vertex takes the position of
/// the surface vertex behind one of its corners.
fn key_poses(mesh: &Mesh, surface: &Surface, face_source: &[(FaceId, bool)]) -> Vec<Keyframe> {
    if surface.poses.is_empty() {
        return Vec::new();
    }
    let mut source = vec![0u32; mesh.n_vertices()];
    for (corners, &(from, flipped)) in mesh.triangles().iter().zip(face_source) {
        let t = surface.triangles[from.index()];
        let t = if flipped { [t[0], t[2], t[1]] } else { t };
        for (&v, s) in corners.iter().zip(t) {
            source[v as usize] = s;
        }
    }
    surface
        .key_times
        .iter()
        .zip(&surface.poses)
        .map(|(&time, pose)| Keyframe {
            time,
            positions: Arc::new(source.iter().map(|&s| pose[s as usize]).collect()),
        })
        .collect()
}

/// The distinct values of a list with few distinct values (per-face materials), in order.
fn distinct<T: Copy + PartialEq>(values: &[T]) -> Vec<T> {
    let mut seen = Vec::new();
    for &value in values {
        if seen.last() != Some(&value) && !seen.contains(&value) {
            seen.push(value);
        }
    }
    seen
}

/// A node's surface made a mesh.
struct Welded {
    mesh: Mesh,
    /// Per mesh face, the surface triangle it came from and whether it was flipped.
    face_source: Vec<(FaceId, bool)>,
    /// The welded input and, per mesh vertex, its input vertex: kept when the mesh had to
    /// be repaired from it.
    input: Option<(TriSoup, Vec<u32>)>,
}

/// Welds equal positions (consuming `surface.positions`) and makes the surface manifold.
fn weld_and_repair(
    surface: &mut Surface,
    name: &str,
    notes: &mut Vec<String>,
) -> Result<Welded, GltfError> {
    let (positions, welded_of) = weld(&surface.positions);
    // The welded copy is all that is needed from here on; free the original early.
    surface.positions = Vec::new();
    let mut welded = TriSoup {
        positions,
        triangles: surface
            .triangles
            .iter()
            .map(|t| t.map(|i| welded_of[i as usize]))
            .collect(),
    };
    welded.remove_unreferenced_vertices();
    if let Ok(mesh) = Mesh::from_soup(&welded) {
        let identity = mesh.faces().map(|f| (f, false)).collect();
        return Ok(Welded {
            mesh,
            face_source: identity,
            input: None,
        });
    }
    let repaired = make_manifold(&welded).map_err(|error| {
        GltfError::Parse(format!(
            "the triangles of {name} cannot be repaired: {error}"
        ))
    })?;
    notes.push(repair_note(name, &repaired.report));
    let vertex_source = repaired.vertex_source.iter().map(|v| v.0).collect();
    Ok(Welded {
        mesh: repaired.mesh,
        face_source: repaired.face_source,
        input: Some((welded, vertex_source)),
    })
}

/// "spot was not a clean manifold surface: 2 duplicate triangles were dropped and 1 vertex
/// was split.", naming only what the repair did.
fn repair_note(name: &str, report: &RepairReport) -> String {
    let count = |n: usize, what: &str| match n {
        1 => format!("1 {what}"),
        _ => format!("{n} {what}s"),
    };
    let was = |n: usize| if n == 1 { "was" } else { "were" };
    let done: Vec<String> = [
        (report.degenerate, "degenerate triangle", "dropped"),
        (report.duplicates, "duplicate triangle", "dropped"),
        (
            report.flipped,
            "triangle",
            "turned over to match the others",
        ),
        (report.split_vertices, "vertex", "split where surfaces met"),
        (report.detached, "triangle", "detached from the rest"),
    ]
    .into_iter()
    .filter(|&(n, _, _)| n > 0)
    .map(|(n, what, how)| format!("{} {} {how}", count(n, what), was(n)))
    .collect();
    let said = match done.as_slice() {
        [] => String::from("it was rebuilt"),
        [only] => only.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    };
    format!("{name} was not a clean manifold surface: {said}.")
}

/// Tells the user about curves that had to be moved onto the mesh or left out.
fn note_curves(attached: &AttachedCurves, name: &str, notes: &mut Vec<String>) {
    let (snapped, dropped) = (attached.snapped, attached.dropped);
    if snapped > 0 {
        notes.push(format!(
            "{} of {name} did not run through its vertices; {} moved onto the nearest ones.",
            curves(snapped),
            if snapped == 1 { "it was" } else { "they were" }
        ));
    }
    if dropped > 0 {
        notes.push(format!(
            "{} of {name} could not be placed on its surface and {} left out.",
            curves(dropped),
            if dropped == 1 { "was" } else { "were" }
        ));
    }
}

/// "1 control curve", "2 control curves".
fn curves(n: usize) -> String {
    match n {
        1 => String::from("1 control curve"),
        n => format!("{n} control curves"),
    }
}

/// A model's paint (one colour per vertex) and finish, each if it has one.
type ColouredHere = (Option<Vec<[f32; 3]>>, Option<Finish>);

/// The paint and finish of a model written by a Sketchmesh file, when its look is one this
/// app makes: one material of its own or clay, no texture, no UVs. `None` for any other
/// look, which stays an imported look.
fn colours_made_here(look: &Appearance, mesh: &Mesh) -> Option<ColouredHere> {
    let material = match distinct(&look.face_materials)[..] {
        [material] => material.and_then(|m| look.materials.get(m as usize)),
        _ => return None,
    };
    let name = material.and_then(|m| m.name.as_deref());
    let is_own = name.is_none_or(|n| [CLAY_MATERIAL_NAME, FINISH_MATERIAL_NAME].contains(&n));
    if look.uvs.is_some() || !is_own || material.is_some_and(|m| m.base_color_texture.is_some()) {
        return None;
    }
    let finish = material
        .filter(|m| m.name.as_deref() == Some(FINISH_MATERIAL_NAME))
        .map(|m| Finish {
            base_color: m.base_color,
            roughness: m.roughness,
            metalness: m.metallic,
        });
    let colors = look.colors.as_ref().map(|corners| {
        let mut colors = vec![[1.0; 3]; mesh.n_vertices()];
        for (&v, &[r, g, b, _]) in mesh.triangle_indices().iter().zip(corners) {
            colors[v as usize] = [r, g, b];
        }
        colors
    });
    Some((colors, finish))
}

/// Per-corner attributes and materials of the mesh faces, from the surface they came from.
fn appearance(
    triangles: &[[u32; 3]],
    positions_hash: u64,
    surface: &Surface,
    face_source: &[(FaceId, bool)],
    materials: &mut MaterialCache,
) -> Appearance {
    // The surface vertex behind each corner of the mesh, in mesh corner order.
    let corner_sources: Vec<u32> = face_source
        .iter()
        .flat_map(|&(source, flipped)| {
            let t = surface.triangles[source.index()];
            if flipped { [t[0], t[2], t[1]] } else { t }
        })
        .collect();
    fn per_corner<T: Copy>(has: bool, values: &[T], corner_sources: &[u32]) -> Option<Vec<T>> {
        has.then(|| corner_sources.iter().map(|&v| values[v as usize]).collect())
    }
    let mut model_materials = Vec::new();
    let mut local_of: HashMap<usize, u32> = HashMap::new();
    let face_materials = face_source
        .iter()
        .map(|&(source, _)| {
            let gltf_index = surface.face_materials[source.index()]?;
            let material = materials.get(gltf_index)?;
            Some(*local_of.entry(gltf_index).or_insert_with(|| {
                model_materials.push(material);
                (model_materials.len() - 1) as u32
            }))
        })
        .collect();
    Appearance {
        triangles: triangles.to_vec(),
        positions_hash,
        normals: per_corner(surface.has_normals, &surface.normals, &corner_sources),
        uvs: per_corner(surface.has_uvs, &surface.uvs, &corner_sources),
        colors: per_corner(surface.has_colors, &surface.colors, &corner_sources),
        face_materials,
        materials: model_materials,
    }
}

/// glTF materials converted once each, with their images shared between models.
struct MaterialCache<'d, 'a> {
    document: &'d gltf::Document,
    buffers: &'d Buffers<'a>,
    files: &'d [ImportFile<'a>],
    converted: HashMap<usize, Option<Material>>,
    images: HashMap<usize, Option<Arc<Image>>>,
    notes: Vec<String>,
}

impl<'d, 'a> MaterialCache<'d, 'a> {
    fn new(
        document: &'d gltf::Document,
        buffers: &'d Buffers<'a>,
        files: &'d [ImportFile<'a>],
    ) -> Self {
        Self {
            document,
            buffers,
            files,
            converted: HashMap::new(),
            images: HashMap::new(),
            notes: Vec::new(),
        }
    }

    fn get(&mut self, index: usize) -> Option<Material> {
        if let Some(material) = self.converted.get(&index) {
            return material.clone();
        }
        let material = self
            .document
            .materials()
            .nth(index)
            .map(|material| self.convert(&material));
        self.converted.insert(index, material.clone());
        material
    }

    fn convert(&mut self, material: &gltf::Material) -> Material {
        let pbr = material.pbr_metallic_roughness();
        let base_color_texture = pbr
            .base_color_texture()
            .filter(|info| info.tex_coord() == 0)
            .and_then(|info| self.texture(&info.texture()));
        Material {
            name: material.name().map(String::from),
            base_color: pbr.base_color_factor(),
            base_color_texture,
            metallic: pbr.metallic_factor(),
            roughness: pbr.roughness_factor(),
            emissive: material.emissive_factor(),
            double_sided: material.double_sided(),
            alpha_mode: match material.alpha_mode() {
                gltf::material::AlphaMode::Opaque => AlphaMode::Opaque,
                gltf::material::AlphaMode::Mask => {
                    AlphaMode::Mask(material.alpha_cutoff().unwrap_or(0.5))
                }
                gltf::material::AlphaMode::Blend => AlphaMode::Blend,
            },
        }
    }

    fn texture(&mut self, texture: &gltf::Texture) -> Option<Texture> {
        // A texture whose image comes from an extension (WebP, KTX2) has no valid source.
        let source = self
            .document
            .as_json()
            .textures
            .get(texture.index())?
            .source;
        if source.value() >= self.document.images().len() {
            return None;
        }
        let image = texture.source();
        let index = image.index();
        let image = match self.images.get(&index) {
            Some(image) => image.clone(),
            None => {
                let loaded = self.image(&image);
                self.images.insert(index, loaded.clone());
                loaded
            }
        }?;
        let sampler = texture.sampler();
        Some(Texture {
            image,
            mag_filter: sampler.mag_filter().map(|f| f.as_gl_enum()),
            min_filter: sampler.min_filter().map(|f| f.as_gl_enum()),
            wrap: [sampler.wrap_s().as_gl_enum(), sampler.wrap_t().as_gl_enum()],
        })
    }

    /// A PNG or JPEG image's bytes; other formats and missing files are left behind with a
    /// note (the model still imports).
    fn image(&mut self, image: &gltf::Image) -> Option<Arc<Image>> {
        let index = image.index();
        let (bytes, mime_type) = match image.source() {
            gltf::image::Source::View { view, mime_type } => {
                let buffer = self.buffers.get(view.buffer().index())?.as_ref().ok()?;
                let end = view.offset().checked_add(view.length())?;
                (
                    buffer.get(view.offset()..end)?.to_vec(),
                    mime_type.to_owned(),
                )
            }
            gltf::image::Source::Uri { uri, mime_type } => {
                match resolve(uri, "Image", index, self.files) {
                    Ok(bytes) => (
                        bytes.into_owned(),
                        mime_type.map_or_else(|| mime_from_uri(uri), String::from),
                    ),
                    Err(error) => {
                        self.notes
                            .push(format!("{error} The model imports without that texture."));
                        return None;
                    }
                }
            }
        };
        if !matches!(mime_type.as_str(), "image/png" | "image/jpeg") {
            self.notes.push(format!(
                "Image {index} is {mime_type}, which Sketchmesh does not carry; the model imports without it."
            ));
            return None;
        }
        Some(Arc::new(Image { mime_type, bytes }))
    }
}

fn mime_from_uri(uri: &str) -> String {
    let lower = uri.to_ascii_lowercase();
    if lower.ends_with(".png") || lower.starts_with("data:image/png") {
        String::from("image/png")
    } else if lower.ends_with(".jpg")
        || lower.ends_with(".jpeg")
        || lower.starts_with("data:image/jpeg")
    {
        String::from("image/jpeg")
    } else {
        String::from("an unknown image type")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_repair_note_names_only_what_was_done() {
        let report = |duplicates, split_vertices, detached| RepairReport {
            duplicates,
            split_vertices,
            detached,
            ..RepairReport::default()
        };
        assert_eq!(
            repair_note("tetra", &report(1, 0, 0)),
            "tetra was not a clean manifold surface: 1 duplicate triangle was dropped."
        );
        assert_eq!(
            repair_note("scan", &report(2, 1, 3)),
            "scan was not a clean manifold surface: 2 duplicate triangles were dropped, 1 vertex \
             was split where surfaces met and 3 triangles were detached from the rest."
        );
    }
}
