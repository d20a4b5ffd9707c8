//! Shared by `golden_sessions.rs` and `editor_properties.rs`: a bit-exact digest of a
//! document, readable summary numbers, and stroke generators for editor ops.
//!
//! [`digest`] is the one place that reads a document's contents; when the document's
//! layout changes (control curves stored differently, say), adapt that function only, and
//! keep it producing the same bytes for the same document so the recorded goldens stay
//! valid.

use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    AddCurveInput, CurveDeformInput, CurveTypeInput, Document, Edit, Editor, FileInput,
    HandleTarget, ImportInput, Model, Op, OversketchFit, OversketchInput, Progress, StrokeInput,
    model_op,
};
use sketchmesh_core::geometry::Bvh;
use sketchmesh_core::io::{decode_changed, decode_moved, encode_changed, encode_moved, write_glb};
use sketchmesh_core::mesh::Mesh;
use sketchmesh_core::oversketch::{ManualHandle, OversketchRoi};
use sketchmesh_core::silhouette::silhouettes;
use sketchmesh_core::volumetric::Falloff;

// ---------------------------------------------------------------------------------------
// Digest
// ---------------------------------------------------------------------------------------

/// FNV-1a, 64 bit.
#[derive(Clone, Copy, Debug)]
pub struct Fnv(u64);

impl Default for Fnv {
    fn default() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv {
    pub fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    pub fn u64(&mut self, value: u64) {
        self.bytes(&value.to_le_bytes());
    }
    pub fn len(&mut self, value: usize) {
        self.u64(value as u64);
    }
    pub fn f64(&mut self, value: f64) {
        self.u64(value.to_bits());
    }
    pub fn point(&mut self, p: DVec3) {
        self.f64(p.x);
        self.f64(p.y);
        self.f64(p.z);
    }
    pub fn tag(&mut self, tag: &str) {
        self.len(tag.len());
        self.bytes(tag.as_bytes());
    }
    pub fn finish(self) -> u64 {
        self.0
    }
}

/// Two digests of a document: `full` covers every number bit for bit, `topology` only the
/// integer structure (counts, triangles, curve chains and flags), so that a mismatch can
/// tell moved vertices from a changed mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Digest {
    pub full: u64,
    pub topology: u64,
}

/// The digest of a document. Covers, per model: every position (f64 bits), every
/// triangle, the name, and every control curve: its kind (sharp or smooth), its closed flag
/// and its vertex chain (its points are where its vertices are); per sketch its points and
/// pressures; per point cloud its positions and colours; then, when there are any, the
/// curve handles and the models' key frames.
///
/// The single function to adapt when the document's layout changes: it must keep feeding
/// the same bytes in the same order for the same document.
pub fn digest(document: &Document) -> Digest {
    let (mut full, mut topo) = (Fnv::default(), Fnv::default());
    for h in [&mut full, &mut topo] {
        h.tag("models");
        h.len(document.models.len());
    }
    for model in &document.models {
        let mesh = &model.mesh;
        for h in [&mut full, &mut topo] {
            h.tag("mesh");
            h.len(mesh.n_vertices());
            h.len(mesh.triangles().len());
            for t in mesh.triangles() {
                t.iter().for_each(|&v| h.u64(u64::from(v)));
            }
        }
        mesh.positions().iter().for_each(|&p| full.point(p));
        full.tag(model.name.as_deref().unwrap_or(""));
        for h in [&mut full, &mut topo] {
            h.tag("curves");
            h.len(model.curves.len());
        }
        for curve in &model.curves {
            for h in [&mut full, &mut topo] {
                h.tag(if curve.is_sharp() { "sharp" } else { "smooth" });
                h.u64(u64::from(curve.is_closed));
                h.len(curve.vertices.len());
                curve.vertices.iter().for_each(|v| h.u64(u64::from(v.0)));
            }
        }
    }
    for h in [&mut full, &mut topo] {
        h.tag("sketches");
        h.len(document.sketches.len());
    }
    for sketch in &document.sketches {
        for h in [&mut full, &mut topo] {
            h.len(sketch.points.len());
        }
        sketch.points.iter().for_each(|&p| full.point(p));
        sketch.pressures.iter().for_each(|&p| full.f64(p));
    }
    for h in [&mut full, &mut topo] {
        h.tag("point_clouds");
        h.len(document.point_clouds.len());
    }
    for cloud in &document.point_clouds {
        for h in [&mut full, &mut topo] {
            h.len(cloud.positions.len());
        }
        cloud.positions.iter().for_each(|&p| full.point(p));
        for colour in cloud.colors.iter().flatten() {
            colour.iter().for_each(|c| full.u64(u64::from(c.to_bits())));
        }
    }
    digest_handles(document, &mut full, &mut topo);
    digest_keyframes(document, &mut full, &mut topo);
    digest_colours(document, &mut full);
    // The plane only where a document has one, so the digests of the others stay as they were.
    if let Some(plane) = document.symmetry {
        full.tag("symmetry");
        <[f64; 4]>::from(plane).iter().for_each(|&x| full.f64(x));
    }
    Digest {
        full: full.finish(),
        topology: topo.finish(),
    }
}

/// Each painted model's colours and each model's material, fed only where a model has them,
/// so that the digests of documents without colour stay as they were.
fn digest_colours(document: &Document, full: &mut Fnv) {
    for (i, model) in document.models.iter().enumerate() {
        if let Some(colors) = model.vertex_colors() {
            full.tag("colours");
            full.len(i);
            colors
                .iter()
                .flatten()
                .for_each(|c| full.u64(u64::from(c.to_bits())));
        }
        if let Some(finish) = model.finish {
            full.tag("finish");
            full.len(i);
            let [r, g, b, a] = finish.base_color;
            [r, g, b, a, finish.roughness, finish.metalness]
                .iter()
                .for_each(|c| full.u64(u64::from(c.to_bits())));
        }
    }
}

/// Curve handles: each one's number, target, kind, links and (in `full`) its control
/// points, twists and scales. Fed only once a handle was made, so that documents without
/// handles digest as they did before handles were digested (their goldens stay valid).
fn digest_handles(document: &Document, full: &mut Fnv, topo: &mut Fnv) {
    if document.handles_made == 0 {
        return;
    }
    for h in [&mut *full, &mut *topo] {
        h.tag("handles");
        h.u64(u64::from(document.handles_made));
        h.len(document.handles.len());
    }
    for handle in &document.handles {
        let (target, index) = match handle.target {
            HandleTarget::Model(index) => ("model", index),
            HandleTarget::Cloud(index) => ("cloud", index),
        };
        for h in [&mut *full, &mut *topo] {
            h.u64(u64::from(handle.id));
            h.tag(target);
            h.len(index);
            h.tag(&format!("{:?}", handle.kind));
            h.u64(u64::from(handle.curve.is_rigid));
            h.len(handle.curve.points.len());
            h.len(handle.links.len());
            for &(point, other, their) in &handle.links {
                h.len(point);
                h.u64(u64::from(other));
                h.len(their);
            }
        }
        let curve = &handle.curve;
        curve.points.iter().for_each(|&p| full.point(p));
        curve.twist.iter().for_each(|&t| full.f64(t));
        curve.scale.iter().flatten().for_each(|&s| full.f64(s));
    }
}

/// Every model's key frames: their times and (in `full`) poses. Fed only when a model has
/// one, as [`digest_handles`] for the same reason.
fn digest_keyframes(document: &Document, full: &mut Fnv, topo: &mut Fnv) {
    if document.models.iter().all(|m| m.keyframes.is_empty()) {
        return;
    }
    for model in &document.models {
        for h in [&mut *full, &mut *topo] {
            h.tag("keyframes");
            h.len(model.keyframes.len());
        }
        for key in &model.keyframes {
            full.f64(key.time);
            topo.len(key.positions.len());
            key.positions.iter().for_each(|&p| full.point(p));
        }
    }
}

/// Readable numbers of one model, for diagnosing a mismatch.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelSummary {
    pub vertices: usize,
    pub faces: usize,
    pub curves: usize,
    pub diagonal: f64,
    pub centroid: DVec3,
}

pub fn summary(model: &Model) -> ModelSummary {
    let positions = model.mesh.positions();
    ModelSummary {
        vertices: positions.len(),
        faces: model.mesh.triangles().len(),
        curves: model.curves.len(),
        diagonal: diagonal(positions),
        centroid: positions.iter().sum::<DVec3>() / positions.len().max(1) as f64,
    }
}

pub fn diagonal(positions: &[DVec3]) -> f64 {
    let min = positions.iter().copied().fold(DVec3::INFINITY, DVec3::min);
    let max = positions
        .iter()
        .copied()
        .fold(DVec3::NEG_INFINITY, DVec3::max);
    if positions.is_empty() {
        0.0
    } else {
        min.distance(max)
    }
}

// ---------------------------------------------------------------------------------------
// Strokes and ops
// ---------------------------------------------------------------------------------------

pub fn samples(points: impl IntoIterator<Item = DVec2>) -> Vec<[f64; 3]> {
    points.into_iter().map(|p| [p.x, p.y, 0.5]).collect()
}

pub fn stroke_input(viewport: DVec2, camera: Camera, points: &[DVec2]) -> StrokeInput {
    StrokeInput {
        viewport: viewport.to_array(),
        camera,
        stroke: samples(points.iter().copied()),
    }
}

pub fn add_curve(
    viewport: DVec2,
    camera: Camera,
    points: &[DVec2],
    closed: bool,
    cross_section: bool,
) -> Op {
    Op::AddCurve(AddCurveInput {
        viewport: viewport.to_array(),
        camera,
        stroke: samples(points.iter().copied()),
        closed,
        cross_section,
    })
}

pub fn set_type(viewport: DVec2, camera: Camera, points: &[DVec2], sharp: bool) -> Op {
    Op::SetCurveType(CurveTypeInput {
        viewport: viewport.to_array(),
        camera,
        stroke: samples(points.iter().copied()),
        sharp,
    })
}

pub fn oversketch(
    viewport: DVec2,
    camera: Camera,
    points: &[DVec2],
    fit: OversketchFit,
    roi: OversketchRoi,
    handle: Option<ManualHandle>,
) -> Op {
    Op::Oversketch(OversketchInput {
        viewport: viewport.to_array(),
        camera,
        stroke: samples(points.iter().copied()),
        fit,
        roi,
        handle,
    })
}

/// An import op carrying the .glb of `document` (written by today's exporter; the op keeps
/// the bytes, so replays do not depend on the exporter).
pub fn import_document(name: &str, document: &Document) -> Op {
    Op::Import(ImportInput {
        files: vec![FileInput {
            name: name.to_owned(),
            data: Some(Arc::new(write_glb(document))),
        }],
        beside: false,
    })
}

pub fn import_mesh(name: &str, mesh: &Mesh) -> Op {
    let document = Document {
        models: vec![Arc::new(Model {
            mesh: mesh.clone(),
            ..Model::default()
        })],
        ..Document::default()
    };
    import_document(name, &document)
}

/// A limb's strokes on screen: a base loop of `radius` px around `centre`, and a silhouette
/// from its top out `reach` px to the right and back to its bottom (a half ellipse).
pub fn extrusion_points(centre: DVec2, radius: f64, reach: f64) -> (Vec<DVec2>, Vec<DVec2>) {
    let base: Vec<DVec2> = (0..=48)
        .map(|i| centre + radius * DVec2::from_angle(TAU * f64::from(i) / 48.0))
        .collect();
    let silhouette: Vec<DVec2> = (0..=60)
        .map(|i| {
            let a = std::f64::consts::PI * (f64::from(i) / 60.0 - 0.5);
            centre + DVec2::new(reach * a.cos(), radius * a.sin())
        })
        .collect();
    (base, silhouette)
}

/// Samples along the segment from `a` to `b`, about every 4 px.
pub fn segment(a: DVec2, b: DVec2) -> Vec<DVec2> {
    let n = (a.distance(b) / 4.0).ceil().max(1.0) as usize;
    (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect()
}

/// A closed outline `centre + r(t) (cos t, squash sin t)` turned by `turn`, with
/// `r(t) = radius (1 + Σ a cos(k t + φ))`, `n` segments (first point repeated at the end).
pub fn outline(
    centre: DVec2,
    radius: f64,
    waves: &[(usize, f64, f64)],
    squash: f64,
    turn: f64,
    n: usize,
) -> Vec<DVec2> {
    (0..=n)
        .map(|i| {
            let t = TAU * i as f64 / n as f64;
            let r = radius
                * (1.0
                    + waves
                        .iter()
                        .map(|&(k, a, phase)| a * (k as f64 * t + phase).cos())
                        .sum::<f64>());
            let p = r * DVec2::new(t.cos(), squash * t.sin());
            centre + DVec2::from_angle(turn).rotate(p)
        })
        .collect()
}

pub fn circle(centre: DVec2, radius: f64) -> Vec<DVec2> {
    outline(centre, radius, &[], 1.0, 0.0, 80)
}

/// Where `p` appears on screen.
pub fn screen(camera: &Camera, viewport: DVec2, p: DVec3) -> Option<DVec2> {
    camera
        .screen_from_world(p, viewport)
        .map(|s| s.truncate())
        .filter(|s| s.is_finite())
}

/// Screen polylines of the visible silhouettes (closed ones repeat their first point).
pub fn outlines(mesh: &Mesh, camera: &Camera, viewport: DVec2) -> Vec<Vec<DVec2>> {
    let bvh = Bvh::new(mesh);
    silhouettes(mesh, &bvh, camera, viewport)
        .iter()
        .map(|s| {
            let mut points: Vec<DVec2> = s.points.iter().map(|p| p.screen).collect();
            if s.closed && !points.is_empty() {
                points.push(points[0]);
            }
            points
        })
        .collect()
}

pub fn length(points: &[DVec2]) -> f64 {
    points.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// The longest silhouette, without the repeated point when closed; `None` when nothing
/// shows.
pub fn longest_outline(mesh: &Mesh, camera: &Camera, viewport: DVec2) -> Option<Vec<DVec2>> {
    let mut all = outlines(mesh, camera, viewport);
    all.sort_by(|a, b| length(b).total_cmp(&length(a)));
    let mut outline = all.into_iter().next()?;
    if outline.len() > 2 && outline.first() == outline.last() {
        outline.pop();
    }
    (outline.len() >= 8).then_some(outline)
}

/// A stroke over the part of `outline` around its extreme point in `direction`,
/// `half_span` points either side, pushed outward by `push · sin(π u)` px (0 at the ends),
/// smoothed and resampled every 1 px (as in `oversketch_pipeline.rs`).
pub fn pushed_stroke(
    outline: &[DVec2],
    direction: DVec2,
    half_span: usize,
    push: f64,
) -> Vec<DVec2> {
    let n = outline.len();
    let centroid = outline.iter().sum::<DVec2>() / n as f64;
    let extreme = (0..n)
        .max_by(|&a, &b| {
            outline[a]
                .dot(direction)
                .total_cmp(&outline[b].dot(direction))
        })
        .unwrap_or(0);
    let half_span = half_span.min(n.saturating_sub(1) / 2);
    let count = 2 * half_span + 1;
    let piece: Vec<DVec2> = (0..count)
        .map(|k| outline[(extreme + n + k - half_span) % n])
        .collect();
    let pushed: Vec<DVec2> = (0..count)
        .map(|k| {
            let before = piece[k.saturating_sub(1)];
            let after = piece[(k + 1).min(count - 1)];
            let mut normal = (after - before).perp().normalize_or_zero();
            if normal.dot(piece[k] - centroid) < 0.0 {
                normal = -normal;
            }
            let u = k as f64 / (count - 1).max(1) as f64;
            piece[k] + normal * push * (PI * u).sin()
        })
        .collect();
    resample(&smooth(&pushed, 4), 1.0)
}

/// Moving average over `half_window` points either side (fewer near the ends).
pub fn smooth(points: &[DVec2], half_window: usize) -> Vec<DVec2> {
    let n = points.len();
    (0..n)
        .map(|i| {
            let w = half_window.min(i).min(n - 1 - i);
            points[i - w..=i + w].iter().sum::<DVec2>() / (2 * w + 1) as f64
        })
        .collect()
}

pub fn resample(points: &[DVec2], spacing: f64) -> Vec<DVec2> {
    let mut out = vec![points[0]];
    for w in points.windows(2) {
        let steps = (w[0].distance(w[1]) / spacing).ceil().max(1.0) as usize;
        for k in 1..=steps {
            out.push(w[0].lerp(w[1], k as f64 / steps as f64));
        }
    }
    out
}

/// The meshes of a test file in `../shared/testdata/meshes`, as the import repairs them
/// (`None` as [`testdata`] says).
pub fn testdata_meshes(name: &str) -> Option<Vec<Mesh>> {
    let path = testdata()?.join("meshes").join(name);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let file = sketchmesh_core::io::ImportFile {
        name,
        bytes: &bytes,
    };
    let imported = sketchmesh_core::io::import_gltf(&file, &[], &Default::default())
        .unwrap_or_else(|e| panic!("{name} does not import: {e}"));
    Some(imported.models.into_iter().map(|m| m.mesh).collect())
}

/// The shared real test data (`../shared/testdata`): its path, or a loud failure when it is
/// missing, unless `SKETCHMESH_NO_TESTDATA=1` says that is expected (then `None`, and the
/// caller prints that it checks nothing).
pub fn testdata() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/testdata");
    if dir.is_dir() {
        return Some(dir);
    }
    let message = format!(
        "the shared test data is missing: {} does not exist",
        dir.display()
    );
    if std::env::var_os("SKETCHMESH_NO_TESTDATA").is_some() {
        eprintln!("WARNING: {message}; SKETCHMESH_NO_TESTDATA is set, so this test checks nothing");
        None
    } else {
        panic!("{message} (set SKETCHMESH_NO_TESTDATA=1 to skip on purpose)");
    }
}

/// Computes `edit`'s op as the page's worker does ([`model_op`] on the models it is handed,
/// the answer through the transfer buffer) and supplies it.
pub fn supply_elsewhere(edit: &mut Edit) {
    let (models, op) = edit.model_op_to_run().expect("an op computed elsewhere");
    let doc = Document {
        models: models.to_vec(),
        ..Document::default()
    };
    let changed = model_op(&doc, op)
        .map(|(index, model)| decode_changed(&encode_changed(index, &model)).expect("decodes"));
    edit.supply_model(changed);
    assert!(edit.model_op_to_run().is_none(), "computed once");
}

/// Ends `edit`'s gesture whose previews were computed elsewhere and commits it as the page
/// does: the committed op computed elsewhere by the worker's kept edit of the gesture
/// (`worker`), which must be the op computed whole, bit for bit; then finished on `editor`.
pub fn commit_elsewhere(mut edit: Edit, worker: Option<Edit>, editor: &mut Editor) {
    edit.end_gesture();
    let ended = edit.step().expect("the gesture ends");
    assert_eq!(ended, Progress::Working);
    let (models, commit) = edit
        .model_op_to_run()
        .expect("the commit computed elsewhere");
    let kept = Edit::finish_elsewhere(worker, models.to_vec(), commit).expect("the kept edit");
    let doc = Document {
        models: models.to_vec(),
        ..Document::default()
    };
    let computed = model_op(&doc, commit).expect("the op computed whole");
    assert!(
        kept == computed,
        "the kept edit's commit is the op computed whole"
    );
    edit.supply_model(Ok(kept));
    edit.finish(editor).expect("the commit lands");
}

/// Computes `edit`'s preview as the page's worker does (`worker` holds the worker's kept edit
/// of the gesture) and hands it over through the transfer buffer, as the page does. Returns
/// the version of the op the preview shows.
pub fn preview_elsewhere(edit: &mut Edit, worker: &mut Option<Edit>) -> usize {
    let (models, op, version) = edit
        .preview_to_run()
        .expect("a preview to compute elsewhere");
    let kept = Edit::preview_elsewhere(worker.take(), models.to_vec(), op.clone())
        .expect("the worker's preview");
    let bytes = encode_moved(version, kept.moved_model(), kept.limited_amount());
    *worker = Some(kept);
    edit.supply_preview(Ok(decode_moved(&bytes).expect("the buffer")));
    version
}

/// Samples every 4 px along the screen images of the world points `from` to `to`.
pub fn screen_line(camera: &Camera, viewport: DVec2, from: DVec3, to: DVec3) -> Vec<[f64; 3]> {
    let n = 60;
    (0..=n)
        .filter_map(|k| {
            let p = from.lerp(to, k as f64 / n as f64);
            camera
                .screen_from_world(p, viewport)
                .map(|s| [s.x, s.y, 0.5])
        })
        .collect()
}

/// A `curve_deform` of a capsule along x (radius 0.5, straight part 6 long, as
/// `volumetric.rs`'s and the `deform_and_keyframes` golden's): a curve along its front from x = −1.5 to 2.5,
/// redrawn from above with its right three quarters swung out toward +z round a quarter
/// circle, the capsule's left end (x < −2.2) lassoed to hold still.
pub fn quarter_bend() -> CurveDeformInput {
    let viewport = DVec2::new(1000.0, 800.0);
    let front = Camera {
        eye: DVec3::new(0.0, 0.0, 12.0),
        ..Camera::default()
    };
    // The curve runs along the capsule's front; its plane (normal along y) faces the view
    // from above, where the new curve is drawn: its right half swung out toward +z.
    let above = Camera {
        eye: DVec3::new(0.0, 12.0, 0.0),
        up: DVec3::NEG_Z,
        ..Camera::default()
    };
    let curve = screen_line(
        &front,
        viewport,
        DVec3::new(-1.5, 0.0, 0.5),
        DVec3::new(2.5, 0.0, 0.5),
    );
    let bent: Vec<DVec3> = (0..=40)
        .map(|k| {
            let s = k as f64 / 40.0;
            let angle = (s - 0.25).max(0.0) / 0.75 * 0.5 * PI;
            // A quarter circle after the first quarter, same length.
            if angle == 0.0 {
                DVec3::new(-1.5 + 4.0 * s, 0.0, 0.5)
            } else {
                let radius = 3.0 / (0.5 * PI);
                DVec3::new(
                    -0.5 + radius * angle.sin(),
                    0.0,
                    0.5 + radius * (1.0 - angle.cos()),
                )
            }
        })
        .collect();
    let stroke: Vec<[f64; 3]> = bent
        .iter()
        .filter_map(|&p| {
            above
                .screen_from_world(p, viewport)
                .map(|s| [s.x, s.y, 0.5])
        })
        .collect();
    let corner = |p: DVec3| {
        let s = front.screen_from_world(p, viewport).expect("in view");
        [s.x, s.y, 0.5]
    };
    let fixed = vec![
        corner(DVec3::new(-3.8, -0.8, 0.0)),
        corner(DVec3::new(-2.2, -0.8, 0.0)),
        corner(DVec3::new(-2.2, 0.8, 0.0)),
        corner(DVec3::new(-3.8, 0.8, 0.0)),
    ];
    CurveDeformInput {
        model: 0,
        viewport: viewport.to_array(),
        camera: front,
        curve,
        path: None,
        held: Vec::new(),
        stroke,
        stroke_camera: Some(above),
        plane: None,
        fixed: Some(fixed),
        falloff: Falloff::Linear,
        coarse: None,
    }
}
