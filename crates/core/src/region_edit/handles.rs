//! Bujans' direct editing (§7): handles along the reference curve, each with a transform of
//! its own. The thesis says a dragged handle reaches only as far as its neighbouring handles,
//! and to the curve's end where it has none, but not how handles combine; here the
//! transform at a point of the curve between two handles is Alexa's blend of theirs,
//! `(1 − u) ⊙ A ⊕ u ⊙ B` with `u` the point's place between them by arclength (Bujans
//! Eq. 8.3), and beyond the outermost handle it is that handle's. A vertex takes the part
//! of its weight, `w ⊙ T`, of the transform at its nearest point of the curve, so one handle
//! is one transform for the whole region, and handles left as the identity pin the curve
//! where they sit.

use glam::{DMat4, DVec3};

use super::RegionError;
use super::transform::checked_log;
use crate::geometry::{Fractions, exp_affine};

/// A handle on the reference curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handle {
    /// Where it sits: 0 at the curve's first end, 1 at its last, by arclength.
    pub at: f64,
    /// Its transform (affine, orientation kept, less than half a turn).
    pub transform: DMat4,
}

/// How a region moves: for each vertex of the reference path, the fractions of the transform
/// the region vertices nearest to it take.
#[derive(Clone, Debug)]
pub struct Motion {
    fractions: Vec<Fractions>,
    /// Each path vertex's entry in `fractions`; empty when there is one transform for all.
    of_reference: Vec<u32>,
}

impl From<Fractions> for Motion {
    /// One transform for the whole region.
    fn from(fractions: Fractions) -> Self {
        Motion {
            fractions: vec![fractions],
            of_reference: Vec::new(),
        }
    }
}

impl Motion {
    /// The handles blended along a path whose vertices sit at `params` (by arclength, from 0
    /// to 1); a path vertex on a handle or beyond the outermost takes that handle's own
    /// fractions, exactly its transform.
    ///
    /// Errors: [`RegionError::BadHandles`], or a transform's refusal (see
    /// [`super::checked_transform`]).
    pub(super) fn blended(handles: &[Handle], params: &[f64]) -> Result<Motion, RegionError> {
        let handles = sorted(handles)?;
        let logs = handles
            .iter()
            .map(|h| checked_log(h.transform))
            .collect::<Result<Vec<_>, _>>()?;
        let mut fractions: Vec<Fractions> = handles
            .iter()
            .zip(&logs)
            .map(|(h, &log)| Fractions::with_log(h.transform, log))
            .collect();
        let of_reference = params
            .iter()
            .map(|&t| match place(&handles, t) {
                Place::On(i) => i as u32,
                Place::Between(i, u) => {
                    fractions.push(Fractions::from_log(logs[i] * (1.0 - u) + logs[i + 1] * u));
                    (fractions.len() - 1) as u32
                }
            })
            .collect();
        Ok(Motion {
            fractions,
            of_reference,
        })
    }

    /// The fractions the region vertices nearest to path vertex `k` take.
    pub(super) fn at(&self, k: u32) -> &Fractions {
        match self.of_reference.get(k as usize) {
            Some(&i) => &self.fractions[i as usize],
            None => &self.fractions[0],
        }
    }
}

/// The transform the reference curve takes at `at` under `handles`: where a new handle
/// placed there keeps the shape as it is.
///
/// Errors: as [`Motion::blended`].
pub fn blend_at(handles: &[Handle], at: f64) -> Result<DMat4, RegionError> {
    let handles = sorted(handles)?;
    let log = |h: &Handle| checked_log(h.transform);
    Ok(match place(&handles, at) {
        Place::On(i) => handles[i].transform,
        Place::Between(i, u) => {
            exp_affine(log(&handles[i])? * (1.0 - u) + log(&handles[i + 1])? * u)
        }
    })
}

/// `handles` in order along the curve.
///
/// Errors: [`RegionError::BadHandles`]: none, one off the curve, two at one place.
fn sorted(handles: &[Handle]) -> Result<Vec<Handle>, RegionError> {
    let mut handles = handles.to_vec();
    handles.sort_by(|a, b| a.at.total_cmp(&b.at));
    let on_curve = handles.iter().all(|h| (0.0..=1.0).contains(&h.at));
    if handles.is_empty() || !on_curve || handles.windows(2).any(|w| w[0].at == w[1].at) {
        return Err(RegionError::BadHandles);
    }
    Ok(handles)
}

/// Where a point of the curve lies among the handles.
enum Place {
    /// On handle `i` or beyond it, the outermost: it takes that handle's transform.
    On(usize),
    /// Between handles `i` and `i + 1`, at `u` in (0, 1) from the first.
    Between(usize, f64),
}

/// Where `t` lies among `handles` (sorted, not empty).
fn place(handles: &[Handle], t: f64) -> Place {
    let after = handles.partition_point(|h| h.at <= t);
    if after == 0 {
        return Place::On(0);
    }
    let before = after - 1;
    if after == handles.len() || handles[before].at == t {
        return Place::On(before);
    }
    let u = (t - handles[before].at) / (handles[after].at - handles[before].at);
    Place::Between(before, u)
}

/// The reference curve as placed on the model, with a frame at every point: where handles
/// sit and which way their axes point (the curve's tangent, the surface normal made
/// orthogonal to it, and their cross product), for a tool to draw and drag them.
#[derive(Clone, Debug, PartialEq)]
pub struct HandleRail {
    points: Vec<DVec3>,
    normals: Vec<DVec3>,
    params: Vec<f64>,
}

/// A handle's place and axes: tangent, normal, binormal (orthonormal, right-handed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandleFrame {
    /// Where the handle sits on the curve.
    pub origin: DVec3,
    /// The curve's tangent, the surface normal and the binormal there.
    pub axes: [DVec3; 3],
}

impl HandleRail {
    /// The rail through `points` (at least two) with surface normals `normals`, placed by
    /// arclength.
    pub(super) fn new(points: Vec<DVec3>, normals: Vec<DVec3>) -> Self {
        let mut along = 0.0;
        let mut params: Vec<f64> = std::iter::once(0.0)
            .chain(points.windows(2).map(|w| {
                along += w[0].distance(w[1]);
                along
            }))
            .collect();
        if along > 0.0 {
            params.iter_mut().for_each(|t| *t /= along);
        }
        HandleRail {
            points,
            normals,
            params,
        }
    }

    /// Where along the rail (0..1) its point nearest to `p` lies.
    pub fn nearest_param(&self, p: DVec3) -> f64 {
        let mut best = (f64::INFINITY, 0.0);
        for (k, w) in self.points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let ab = b - a;
            let t = ((p - a).dot(ab) / ab.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            let d = p.distance_squared(a + ab * t);
            if d < best.0 {
                let param = self.params[k] + t * (self.params[k + 1] - self.params[k]);
                best = (d, param);
            }
        }
        best.1
    }

    /// The curve's points, in order.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The frame at `at` (0 the first end, 1 the last, by arclength), between path vertices
    /// linearly.
    pub fn frame_at(&self, at: f64) -> HandleFrame {
        let n = self.points.len();
        let after = self
            .params
            .partition_point(|&t| t < at)
            .clamp(1, n.max(2) - 1);
        let (i, j) = (after - 1, after.min(n - 1));
        let span = self.params[j] - self.params[i];
        let u = if span > 0.0 {
            ((at - self.params[i]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let origin = self.points[i].lerp(self.points[j], u);
        let tangent = (self.points[j] - self.points[i]).normalize_or(DVec3::X);
        let normal = self.normals[i].lerp(self.normals[j], u);
        let normal =
            (normal - tangent * normal.dot(tangent)).normalize_or(tangent.any_orthonormal_vector());
        HandleFrame {
            origin,
            axes: [tangent, normal, tangent.cross(normal)],
        }
    }
}
