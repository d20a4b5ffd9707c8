//! An import's result as one flat buffer, to move it from the wasm instance that computed it
//! (the page's worker) to the one that shows it.
//!
//! Why not serde: the buffer is decoded on the page's main thread, where every millisecond is
//! a frame's. A million-triangle import is about 60 MB of arrays; element-wise formats
//! (postcard, bincode) decode them one number at a time, several times slower than the
//! bulk copies used here, which run at memory speed: each array is copied once, from wherever
//! the buffer is ([`TransferSource`]: in the page, still in JavaScript's memory) straight
//! into its place.
//!
//! Not a file format: both ends are the same build of this crate (the page loads one wasm
//! file into both instances), so the layout is whatever this file writes, in the machine's
//! byte order, with no version. A buffer that is cut short or inconsistent is still refused
//! with a [`TransferError`], never trusted into a broken mesh.

use std::sync::Arc;

use bytemuck::Pod;
use glam::DVec3;

use super::import::Imported;
use crate::mesh::{Mesh, MeshParts, TriSoup, VertexId};
use crate::model::{
    AlphaMode, Appearance, AsImported, Finish, Image, Keyframe, Material, MirrorPlane, Model,
    PointCloud, SketchCurve, Texture,
};
use crate::model::{ControlCurve, CurveKind};

/// A buffer that does not decode: cut short, or arrays that do not fit together.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("The worker's result could not be read ({0}).")]
pub struct TransferError(&'static str);

/// `imported` as one buffer for [`decode_imported`].
pub fn encode_imported(imported: &Imported) -> Vec<u8> {
    let mut out = Writer::default();
    out.models(&imported.models.iter().collect::<Vec<_>>());
    out.seq(&imported.sketches, |out, sketch| {
        out.pods(&sketch.points);
        out.pods(&sketch.pressures);
    });
    out.seq(&imported.point_clouds, |out, cloud| {
        out.pods(&cloud.positions);
        out.option(cloud.colors.as_deref(), Writer::pods);
    });
    out.seq(&imported.notes, |out, note| out.text(note));
    let plane = imported.symmetry.map(<[f64; 4]>::from);
    out.option(plane.as_ref().map(|p| &p[..]), Writer::pods);
    out.bytes
}

/// The import [`encode_imported`] wrote.
///
/// Errors: [`TransferError`] when the buffer is not one it wrote.
pub fn decode_imported(bytes: &(impl TransferSource + ?Sized)) -> Result<Imported, TransferError> {
    decode_imported_unchecked(bytes)?.checked()
}

/// An import decoded whose meshes are not checked yet ([`UncheckedImport::checked`]):
/// [`decode_imported`] in two halves, which the page takes in two frames (for a million
/// triangles the arrays' copy and their check are each about half of the landing's first
/// frame).
#[derive(Debug)]
pub struct UncheckedImport(Imported);

impl UncheckedImport {
    /// The import, once its meshes' arrays are checked to fit together.
    ///
    /// Errors: [`TransferError`] when they do not.
    pub fn checked(self) -> Result<Imported, TransferError> {
        check_meshes(&self.0.models)?;
        Ok(self.0)
    }
}

/// The first half of [`decode_imported`]: every array copied out, the meshes not checked.
///
/// Errors: [`TransferError`] when the buffer is not one [`encode_imported`] wrote.
pub fn decode_imported_unchecked(
    bytes: &(impl TransferSource + ?Sized),
) -> Result<UncheckedImport, TransferError> {
    let mut input = Reader::new(bytes);
    let imported = Imported {
        models: input.models()?,
        sketches: input.seq(|input| {
            Ok(SketchCurve {
                points: input.pods()?,
                pressures: input.pods()?,
            })
        })?,
        point_clouds: input.seq(|input| {
            Ok(PointCloud {
                positions: input.pods()?,
                colors: input.option(Reader::pods)?,
            })
        })?,
        notes: input.seq(Reader::text)?,
        symmetry: match input.option(Reader::pods::<f64>)? {
            Some(numbers) => Some(
                <[f64; 4]>::try_from(numbers)
                    .ok()
                    .and_then(|plane| MirrorPlane::try_from(plane).ok())
                    .ok_or(TransferError("a symmetry plane that is not one"))?,
            ),
            None => None,
        },
    };
    input.end()?;
    Ok(UncheckedImport(imported))
}

/// Whether the meshes of `models`, decoded unchecked, fit together.
///
/// Errors: [`TransferError`] for the first that does not.
fn check_meshes(models: &[Model]) -> Result<(), TransferError> {
    match models.iter().all(|model| model.mesh.parts_fit()) {
        true => Ok(()),
        false => Err(TransferError("a mesh whose arrays do not fit")),
    }
}

/// A document's models as one buffer for [`decode_models`]: what the page's worker needs to
/// compute an op that changes one model from the models alone.
pub fn encode_models(models: &[&Model]) -> Vec<u8> {
    let mut out = Writer::default();
    out.models(models);
    out.bytes
}

/// The models [`encode_models`] wrote.
///
/// Errors: [`TransferError`] when the buffer is not one it wrote.
pub fn decode_models(bytes: &(impl TransferSource + ?Sized)) -> Result<Vec<Model>, TransferError> {
    let mut input = Reader::new(bytes);
    let models = input.models()?;
    input.end()?;
    check_meshes(&models)?;
    Ok(models)
}

/// What an op that changes one model made of it elsewhere (the model's index, its next
/// version) as one buffer for [`decode_changed`].
pub fn encode_changed(index: usize, model: &Model) -> Vec<u8> {
    let mut out = Writer::default();
    out.count(index);
    out.models(&[model]);
    out.bytes
}

/// The changed model [`encode_changed`] wrote.
///
/// Errors: [`TransferError`] when the buffer is not one it wrote.
pub fn decode_changed(
    bytes: &(impl TransferSource + ?Sized),
) -> Result<(usize, Model), TransferError> {
    let mut input = Reader::new(bytes);
    let index = input.count()?;
    let models = input.models()?;
    input.end()?;
    check_meshes(&models)?;
    let model = models.into_iter().next();
    Ok((index, model.ok_or(TransferError("no model"))?))
}

/// A gesture's preview computed elsewhere (the page's worker), as [`decode_moved`] reads it.
#[derive(Clone, Debug, PartialEq)]
pub struct Previewed {
    /// The version of the gesture's op it was computed for.
    pub version: usize,
    /// The moved model's index and where its vertices are drawn; `None` while there is
    /// nothing to show yet (a curve of fewer than two samples).
    pub moved: Option<(usize, Vec<DVec3>)>,
    /// The amount shown when the one asked for was cut back (a feature that would fold the
    /// surface over).
    pub limited: Option<f64>,
}

/// A gesture's preview computed elsewhere (see [`Previewed`]) as one buffer for
/// [`decode_moved`]; the positions are written from where they are, not copied first.
pub fn encode_moved(
    version: usize,
    moved: Option<(usize, &[DVec3])>,
    limited: Option<f64>,
) -> Vec<u8> {
    let mut out = Writer::default();
    out.count(version);
    out.option(moved.as_ref(), |out, &(index, positions)| {
        out.count(index);
        out.pods(positions);
    });
    out.option(limited.as_ref(), |out, &amount| out.pod(amount));
    out.bytes
}

/// The preview [`encode_moved`] wrote.
///
/// Errors: [`TransferError`] when the buffer is not one it wrote.
pub fn decode_moved(bytes: &(impl TransferSource + ?Sized)) -> Result<Previewed, TransferError> {
    let mut input = Reader::new(bytes);
    let previewed = Previewed {
        version: input.count()?,
        moved: input.option(|input| Ok((input.count()?, input.pods()?)))?,
        limited: input.option(Reader::pod)?,
    };
    input.end()?;
    Ok(previewed)
}

/// Bytes a buffer is decoded from: a slice, or in the page the buffer the worker sent, which
/// is never copied whole (each array is copied out of it into its place).
pub trait TransferSource {
    /// How many bytes there are.
    fn size(&self) -> usize;
    /// Fills `into` with the bytes from `at` on (the range is within [`TransferSource::size`]).
    fn copy_out(&self, at: usize, into: &mut [u8]);
}

impl TransferSource for [u8] {
    fn size(&self) -> usize {
        self.len()
    }

    fn copy_out(&self, at: usize, into: &mut [u8]) {
        into.copy_from_slice(&self[at..at + into.len()]);
    }
}

impl TransferSource for Vec<u8> {
    fn size(&self) -> usize {
        self.len()
    }

    fn copy_out(&self, at: usize, into: &mut [u8]) {
        self.as_slice().copy_out(at, into);
    }
}

#[derive(Default)]
struct Writer {
    bytes: Vec<u8>,
    /// The images written, in order: a texture is written as its index here.
    images: Vec<Arc<Image>>,
}

impl Writer {
    fn count(&mut self, n: usize) {
        self.bytes.extend_from_slice(&(n as u64).to_ne_bytes());
    }

    fn pod<T: Pod>(&mut self, value: T) {
        self.bytes.extend_from_slice(bytemuck::bytes_of(&value));
    }

    fn pods<T: Pod>(&mut self, values: &[T]) {
        self.count(values.len());
        self.bytes.extend_from_slice(bytemuck::cast_slice(values));
    }

    fn text(&mut self, text: &str) {
        self.pods(text.as_bytes());
    }

    fn seq<T>(&mut self, items: &[T], mut each: impl FnMut(&mut Self, &T)) {
        self.count(items.len());
        for item in items {
            each(self, item);
        }
    }

    /// The image table, then `models`. Images go once, before the models, in a table the
    /// materials refer to: the importer shares one image between materials, models and
    /// their looks as imported, and the page decodes and uploads each shared image once.
    fn models(&mut self, models: &[&Model]) {
        for material in (models.iter())
            .flat_map(|m| {
                [
                    m.appearance.as_deref(),
                    m.as_imported.as_ref().and_then(|a| a.appearance.as_deref()),
                ]
            })
            .flatten()
            .flat_map(|a| &a.materials)
        {
            if let Some(texture) = &material.base_color_texture
                && !(self.images.iter()).any(|known| Arc::ptr_eq(known, &texture.image))
            {
                self.images.push(Arc::clone(&texture.image));
            }
        }
        self.seq(&self.images.clone(), |out, image| {
            out.text(&image.mime_type);
            out.pods(&image.bytes);
        });
        self.seq(models, |out, model| out.model(model));
    }

    fn option<T: ?Sized>(&mut self, value: Option<&T>, each: impl FnOnce(&mut Self, &T)) {
        self.pod(u8::from(value.is_some()));
        if let Some(value) = value {
            each(self, value);
        }
    }

    fn model(&mut self, model: &Model) {
        self.mesh(&model.mesh);
        self.seq(&model.curves, |out, curve| {
            let vertices: Vec<u32> = curve.vertices.iter().map(|v| v.0).collect();
            out.pods(&vertices);
            out.pod(u8::from(curve.is_closed));
            out.pod(u8::from(curve.kind == CurveKind::Sharp));
        });
        self.option(model.name.as_deref(), Self::text);
        let triangles = model.mesh.triangles();
        self.option(model.appearance.as_deref(), |out, appearance| {
            out.appearance(appearance, triangles);
        });
        self.option(model.as_imported.as_deref(), |out, as_imported| {
            let soup = &as_imported.soup.triangles;
            out.pods(&as_imported.soup.positions);
            out.pods(soup);
            out.pods(&as_imported.vertex_source);
            out.triangles_like(&as_imported.mesh_triangles, triangles);
            out.option(as_imported.appearance.as_deref(), |out, appearance| {
                out.appearance(appearance, soup);
            });
        });
        self.seq(&model.keyframes, |out, keyframe| {
            out.pod(keyframe.time);
            out.pods(&keyframe.positions);
        });
        self.option(model.colors.as_deref(), |out, colors| out.pods(colors));
        let finish = model.finish.map(|f| {
            let [r, g, b, a] = f.base_color;
            [r, g, b, a, f.roughness, f.metalness]
        });
        self.option(finish.as_ref().map(|f| &f[..]), Writer::pods);
    }

    fn mesh(&mut self, mesh: &Mesh) {
        let parts = mesh.parts();
        self.pods(parts.positions);
        self.pods(parts.triangles);
        self.pods(parts.twin);
        self.pods(parts.vertex_halfedge);
        self.pod(parts.n_dead_vertices);
        self.pod(parts.n_dead_faces);
    }

    /// `triangles`, or only a flag when they are `like` (a look's copy of its mesh's
    /// triangles: 12 MB at a million triangles the page's frame need not copy in).
    fn triangles_like(&mut self, triangles: &[[u32; 3]], like: &[[u32; 3]]) {
        let same = triangles == like;
        self.pod(u8::from(same));
        if !same {
            self.pods(triangles);
        }
    }

    /// `appearance`, whose triangles are likely `like`.
    fn appearance(&mut self, appearance: &Appearance, like: &[[u32; 3]]) {
        self.triangles_like(&appearance.triangles, like);
        self.pod(appearance.positions_hash);
        self.option(appearance.normals.as_deref(), Self::pods);
        self.option(appearance.uvs.as_deref(), Self::pods);
        self.option(appearance.colors.as_deref(), Self::pods);
        let face_materials: Vec<u32> = (appearance.face_materials.iter())
            .map(|m| m.unwrap_or(u32::MAX))
            .collect();
        self.pods(&face_materials);
        self.seq(&appearance.materials, Self::material);
    }

    fn material(&mut self, material: &Material) {
        self.option(material.name.as_deref(), Self::text);
        self.pod(material.base_color);
        self.option(material.base_color_texture.as_ref(), |out, texture| {
            let index = (out.images.iter()).position(|known| Arc::ptr_eq(known, &texture.image));
            out.pod(index.map_or(u64::MAX, |i| i as u64));
            out.pod(texture.mag_filter.unwrap_or(u32::MAX));
            out.pod(texture.min_filter.unwrap_or(u32::MAX));
            out.pod(texture.wrap);
        });
        self.pod(material.metallic);
        self.pod(material.roughness);
        self.pod(material.emissive);
        self.pod(u8::from(material.double_sided));
        let (mode, cutoff) = match material.alpha_mode {
            AlphaMode::Opaque => (0u8, 0.0),
            AlphaMode::Mask(cutoff) => (1, cutoff),
            AlphaMode::Blend => (2, 0.0),
        };
        self.pod(mode);
        self.pod(cutoff);
    }
}

struct Reader<'a, S: TransferSource + ?Sized> {
    source: &'a S,
    /// Where the next read starts.
    at: usize,
    /// The image table, read first.
    images: Vec<Arc<Image>>,
}

impl<'a, S: TransferSource + ?Sized> Reader<'a, S> {
    fn new(source: &'a S) -> Self {
        Reader {
            source,
            at: 0,
            images: Vec::new(),
        }
    }

    /// The bytes not read yet.
    fn left(&self) -> usize {
        self.source.size() - self.at
    }

    /// What [`Writer::models`] wrote: the image table, then the models.
    fn models(&mut self) -> Result<Vec<Model>, TransferError> {
        self.images = self.seq(|input| {
            Ok(Arc::new(Image {
                mime_type: input.text()?,
                bytes: input.pods()?,
            }))
        })?;
        self.seq(Reader::model)
    }

    /// Refuses bytes after the end.
    fn end(&self) -> Result<(), TransferError> {
        if self.left() == 0 {
            Ok(())
        } else {
            Err(TransferError("bytes left over"))
        }
    }

    /// Fills `into` with the next bytes.
    fn read_into(&mut self, into: &mut [u8]) -> Result<(), TransferError> {
        if into.len() > self.left() {
            return Err(TransferError("cut short"));
        }
        self.source.copy_out(self.at, into);
        self.at += into.len();
        Ok(())
    }

    fn count(&mut self) -> Result<usize, TransferError> {
        let n: u64 = self.pod()?;
        usize::try_from(n).map_err(|_| TransferError("a length out of range"))
    }

    fn pod<T: Pod>(&mut self) -> Result<T, TransferError> {
        let mut value = T::zeroed();
        self.read_into(bytemuck::bytes_of_mut(&mut value))?;
        Ok(value)
    }

    fn pods<T: Pod>(&mut self) -> Result<Vec<T>, TransferError> {
        let n = self.count()?;
        let size = n
            .checked_mul(size_of::<T>())
            .ok_or(TransferError("a length out of range"))?;
        if size > self.left() {
            return Err(TransferError("cut short"));
        }
        // Zeroed memory fresh from the allocator is not written twice: the copy is the one
        // pass over the array.
        let mut values = bytemuck::zeroed_vec::<T>(n);
        self.read_into(bytemuck::cast_slice_mut(&mut values))?;
        Ok(values)
    }

    fn flag(&mut self) -> Result<bool, TransferError> {
        match self.pod::<u8>()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => Err(TransferError("a flag that is neither 0 nor 1")),
        }
    }

    fn text(&mut self) -> Result<String, TransferError> {
        String::from_utf8(self.pods()?).map_err(|_| TransferError("text that is not UTF-8"))
    }

    fn seq<T>(
        &mut self,
        mut each: impl FnMut(&mut Self) -> Result<T, TransferError>,
    ) -> Result<Vec<T>, TransferError> {
        let n = self.count()?;
        // No more room than the bytes left could fill, so a corrupt count cannot reserve
        // gigabytes.
        let mut items = Vec::with_capacity(n.min(self.left() / size_of::<T>().max(1)));
        for _ in 0..n {
            items.push(each(self)?);
        }
        Ok(items)
    }

    fn option<T>(
        &mut self,
        each: impl FnOnce(&mut Self) -> Result<T, TransferError>,
    ) -> Result<Option<T>, TransferError> {
        self.flag()?.then(|| each(self)).transpose()
    }

    fn model(&mut self) -> Result<Model, TransferError> {
        let mesh = self.mesh()?;
        let curves = self.seq(|input| {
            let vertices: Vec<u32> = input.pods()?;
            Ok(ControlCurve {
                vertices: vertices.into_iter().map(VertexId).collect(),
                is_closed: input.flag()?,
                kind: if input.flag()? {
                    CurveKind::Sharp
                } else {
                    CurveKind::Smooth
                },
            })
        })?;
        let n = mesh.n_vertices();
        if (curves.iter().flat_map(|c| &c.vertices)).any(|v| v.index() >= n) {
            return Err(TransferError("a curve off its mesh"));
        }
        let triangles = mesh.triangles();
        let name = self.option(Self::text)?;
        let appearance = self.option(|input| input.appearance(triangles))?;
        let as_imported = self.option(|input| {
            let positions = input.pods()?;
            let soup: Vec<[u32; 3]> = input.pods()?;
            let vertex_source = input.pods()?;
            let mesh_triangles = input.triangles_like(triangles)?;
            let appearance = input.option(|input| input.appearance(&soup))?;
            Ok(AsImported {
                soup: TriSoup {
                    positions,
                    triangles: soup,
                },
                vertex_source,
                mesh_triangles,
                appearance: appearance.map(Arc::new),
            })
        })?;
        let keyframes = self.seq(|input| {
            Ok(Keyframe {
                time: input.pod()?,
                positions: Arc::new(input.pods()?),
            })
        })?;
        let colors = self.option(|input| input.pods::<[f32; 3]>())?;
        let finish = self.option(|input| {
            let [r, g, b, a, roughness, metalness] = <[f32; 6]>::try_from(input.pods::<f32>()?)
                .map_err(|_| TransferError("a finish of the wrong length"))?;
            Ok(Finish {
                base_color: [r, g, b, a],
                roughness,
                metalness,
            })
        })?;
        Ok(Model {
            mesh,
            curves,
            name,
            appearance: appearance.map(Arc::new),
            as_imported: as_imported.map(Arc::new),
            keyframes,
            colors: colors.map(Arc::new),
            finish,
        })
    }

    fn mesh(&mut self) -> Result<Mesh, TransferError> {
        let parts = MeshParts {
            positions: self.pods::<DVec3>()?,
            triangles: self.pods()?,
            twin: self.pods()?,
            vertex_halfedge: self.pods()?,
            n_dead_vertices: self.pod()?,
            n_dead_faces: self.pod()?,
        };
        // Checked once the whole buffer is read (see `check_meshes`).
        Ok(Mesh::from_parts_unchecked(parts))
    }

    /// What [`Writer::triangles_like`] wrote.
    fn triangles_like(&mut self, like: &[[u32; 3]]) -> Result<Vec<[u32; 3]>, TransferError> {
        if self.flag()? {
            Ok(like.to_vec())
        } else {
            self.pods()
        }
    }

    fn appearance(&mut self, like: &[[u32; 3]]) -> Result<Appearance, TransferError> {
        Ok(Appearance {
            triangles: self.triangles_like(like)?,
            positions_hash: self.pod()?,
            normals: self.option(Self::pods)?,
            uvs: self.option(Self::pods)?,
            colors: self.option(Self::pods)?,
            face_materials: (self.pods::<u32>()?.into_iter())
                .map(|m| (m != u32::MAX).then_some(m))
                .collect(),
            materials: self.seq(Self::material)?,
        })
    }

    fn material(&mut self) -> Result<Material, TransferError> {
        let optional = |code: u32| (code != u32::MAX).then_some(code);
        Ok(Material {
            name: self.option(Self::text)?,
            base_color: self.pod()?,
            base_color_texture: self.option(|input| {
                let index = usize::try_from(input.pod::<u64>()?).ok();
                let image = index.and_then(|i| input.images.get(i));
                Ok(Texture {
                    image: Arc::clone(image.ok_or(TransferError("an image not in the table"))?),
                    mag_filter: optional(input.pod()?),
                    min_filter: optional(input.pod()?),
                    wrap: input.pod()?,
                })
            })?,
            metallic: self.pod()?,
            roughness: self.pod()?,
            emissive: self.pod()?,
            double_sided: self.flag()?,
            alpha_mode: match (self.pod::<u8>()?, self.pod::<f32>()?) {
                (0, _) => AlphaMode::Opaque,
                (1, cutoff) => AlphaMode::Mask(cutoff),
                (2, _) => AlphaMode::Blend,
                _ => return Err(TransferError("an unknown alpha mode")),
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    /// An import of one model on `mesh`.
    fn import_of(mesh: Mesh) -> Imported {
        Imported {
            models: vec![Model {
                mesh,
                ..Model::default()
            }],
            ..Imported::default()
        }
    }

    /// `mesh` with its first half-edge its own twin: arrays that do not fit.
    fn broken(mesh: &Mesh) -> Mesh {
        let parts = mesh.parts();
        let mut twin = parts.twin.to_vec();
        twin[0] = 0;
        Mesh::from_parts_unchecked(MeshParts {
            positions: parts.positions.to_vec(),
            triangles: parts.triangles.to_vec(),
            twin,
            vertex_halfedge: parts.vertex_halfedge.to_vec(),
            n_dead_vertices: parts.n_dead_vertices,
            n_dead_faces: parts.n_dead_faces,
        })
    }

    #[test]
    fn an_import_decodes_in_two_halves_and_the_second_refuses_arrays_that_do_not_fit() {
        let good = import_of(primitives::icosphere(1.0, 1));
        let bytes = encode_imported(&good);
        let unchecked = decode_imported_unchecked(&bytes[..]).unwrap();
        assert_eq!(unchecked.checked().unwrap().models, good.models);
        let bad = import_of(broken(&good.models[0].mesh));
        let bytes = encode_imported(&bad);
        let unchecked = decode_imported_unchecked(&bytes[..]).expect("the first half reads it");
        assert!(unchecked.checked().is_err());
        assert!(decode_imported(&bytes[..]).is_err());
        // The other decoders check their meshes too.
        assert!(decode_models(&encode_models(&[&bad.models[0]])[..]).is_err());
        assert!(decode_changed(&encode_changed(0, &bad.models[0])[..]).is_err());
    }
}
