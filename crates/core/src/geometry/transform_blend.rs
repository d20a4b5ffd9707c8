//! Fractions and sums of affine transforms: Alexa's "Linear combination of transformations"
//! (SIGGRAPH 2002), as Bujans' region editor blends its edits (§8): `s ⊙ A = exp(s log A)`
//! is the part `s` of `A`, and `A ⊕ B = exp(log A + log B)` adds two. Half of a transform
//! applied twice is the whole of it, which a linear blend of matrices is not (a blended
//! rotation shrinks).
//!
//! The logarithm is real and unique for an affine map with a positive determinant whose
//! linear part has no eigenvalue on the negative real axis: a turn of less than half a turn,
//! positive scales, no mirror. It is computed by inverse scaling and squaring (square roots
//! by the Denman–Beavers iteration until the matrix is near the identity, then the series
//! of `2 atanh((A − I)(A + I)⁻¹)`), and the exponential by scaling and squaring a Taylor
//! series; both as Alexa's paper does, in `f64`.

use glam::{DMat4, DVec3, DVec4};

/// Square roots are taken until `‖A − I‖₁` is below this: the atanh series then gains more
/// than 1.7 digits a term.
const NEAR_IDENTITY: f64 = 0.25;
/// At most this many square roots: `A^(1/2^40)` is the identity to within `f64` for any
/// map whose logarithm is finite.
const MAX_ROOTS: u32 = 40;
/// The Denman–Beavers iteration converges quadratically; this many steps mean it does not
/// (an eigenvalue on the negative real axis: a half turn or a mirror).
const MAX_ROOT_STEPS: u32 = 100;
/// A series (atanh, exp) stops once a term is this small next to the sum.
const SERIES_TOLERANCE: f64 = 1e-18;
/// How near the characteristic polynomial of a linear part of determinant 1 may come to 0
/// at a negative maximum: a turn within about 0.01° of half a turn has no logarithm that
/// rounding leaves meaningful (its axis is lost).
const HALF_TURN_MARGIN: f64 = 1e-7;
/// Sample weights kept by [`Fractions`]: `w ⊙ T` for `w = k / FRACTION_SAMPLES`.
const FRACTION_SAMPLES: usize = 256;
/// Every this many samples of [`Fractions`] is an exponential of its own.
const SAMPLE_STRIDE: usize = 16;
/// Taylor terms of `exp(δ log T)` for the small rest `|δ| ≤ 1 / (2 FRACTION_SAMPLES)`
/// between a weight and its nearest sample: `(δ ‖log T‖)⁷ / 7!` is below `f64`'s precision
/// for any turn and any scale between 1/50 and 50.
const REST_TERMS: u32 = 7;

/// `log A` for an affine `A`, or `None` when it has no real logarithm (a determinant that is
/// not positive, a half turn, a value that is not finite).
pub fn log_affine(a: DMat4) -> Option<DMat4> {
    if !is_finite(a) || a.determinant() <= 0.0 || turns_half_way(a) {
        return None;
    }
    let mut root = a;
    let mut roots = 0;
    while norm1(root - DMat4::IDENTITY) > NEAR_IDENTITY {
        if roots == MAX_ROOTS {
            return None;
        }
        root = square_root(root)?;
        roots += 1;
    }
    // log R = 2 atanh(Y) = 2 (Y + Y³/3 + Y⁵/5 + …), Y = (R − I)(R + I)⁻¹.
    let y = (root - DMat4::IDENTITY) * (root + DMat4::IDENTITY).inverse();
    let y2 = y * y;
    let mut power = y;
    let mut sum = y;
    for k in 1..200 {
        power = y2 * power;
        let term = power * (1.0 / f64::from(2 * k + 1));
        sum += term;
        if norm1(term) <= SERIES_TOLERANCE * norm1(sum) {
            break;
        }
    }
    let log = sum * (2.0 * 2f64.powi(roots as i32));
    is_finite(log).then(|| affine_part(log))
}

/// `exp X`, by scaling and squaring.
pub fn exp_affine(x: DMat4) -> DMat4 {
    let norm = norm1(x);
    let squarings = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let scaled = x * 0.5f64.powi(squarings);
    let mut term = DMat4::IDENTITY;
    let mut sum = DMat4::IDENTITY;
    for k in 1..40 {
        term = term * scaled * (1.0 / f64::from(k));
        sum += term;
        if norm1(term) <= SERIES_TOLERANCE * norm1(sum) {
            break;
        }
    }
    for _ in 0..squarings {
        sum = sum * sum;
    }
    sum
}

/// `s ⊙ A = exp(s log A)`: the part `s` of `A` (`2 ⊙ A` is `A` applied twice); `None`
/// when `A` has no real logarithm.
pub fn fraction(s: f64, a: DMat4) -> Option<DMat4> {
    log_affine(a).map(|log| exp_affine(log * s))
}

/// `A ⊕ B = exp(log A + log B)`: commutative, and `A B` when `A` and `B` commute; `None`
/// when either has no real logarithm.
pub fn sum(a: DMat4, b: DMat4) -> Option<DMat4> {
    Some(exp_affine(log_affine(a)? + log_affine(b)?))
}

/// `w ⊙ T` for one transform and any weight in [0, 1], quick enough for every vertex of a
/// region in every drag frame: `exp(w log T) = exp(k/N log T) exp(δ log T)`, the first
/// factor from a table of `N + 1` samples and the second a few Taylor terms of a tiny `δ`,
/// exact to `f64`'s precision (the two factors commute). Weight 0 leaves a point as it is and
/// weight 1 applies `T` itself, bit for bit.
#[derive(Clone, Debug)]
pub struct Fractions {
    transform: DMat4,
    log: DMat4,
    samples: Vec<DMat4>,
}

impl Fractions {
    /// The fractions of `transform`; `None` when it has no real logarithm.
    pub fn new(transform: DMat4) -> Option<Self> {
        Some(Fractions::with_log(transform, log_affine(transform)?))
    }

    /// The fractions of `exp log` (a blend of logarithms, as handles make).
    pub fn from_log(log: DMat4) -> Self {
        Fractions::with_log(exp_affine(log), log)
    }

    /// The table for `transform` and its logarithm `log` (the caller's word that it is):
    /// every [`SAMPLE_STRIDE`]-th sample an exponential, the ones between it times a short
    /// power (the factors commute), so a table costs a few dozen exponentials and a region
    /// with many handles builds many.
    pub(crate) fn with_log(transform: DMat4, log: DMat4) -> Self {
        let exp_at = |k: usize| exp_affine(log * (k as f64 / FRACTION_SAMPLES as f64));
        let short: Vec<DMat4> = (0..SAMPLE_STRIDE).map(exp_at).collect();
        let long: Vec<DMat4> = (0..FRACTION_SAMPLES / SAMPLE_STRIDE)
            .map(|j| exp_at(j * SAMPLE_STRIDE))
            .collect();
        let samples = (0..=FRACTION_SAMPLES)
            .map(|k| match (k, k % SAMPLE_STRIDE) {
                (0, _) => DMat4::IDENTITY,
                (FRACTION_SAMPLES, _) => transform,
                (_, 0) => long[k / SAMPLE_STRIDE],
                (_, r) => long[k / SAMPLE_STRIDE] * short[r],
            })
            .collect();
        Fractions {
            transform,
            log,
            samples,
        }
    }

    /// The whole transform.
    pub fn transform(&self) -> DMat4 {
        self.transform
    }

    /// `(w ⊙ T) p`, `w` clamped to [0, 1].
    pub fn apply(&self, w: f64, p: DVec3) -> DVec3 {
        let w = w.clamp(0.0, 1.0);
        if w == 0.0 {
            return p;
        }
        let n = FRACTION_SAMPLES as f64;
        let k = (w * n).round();
        let rest = w - k / n;
        let sample = self.samples[k as usize];
        if rest == 0.0 {
            return sample.transform_point3(p);
        }
        // exp(δX) (p, 1) = Σ δᵐ Xᵐ (p, 1) / m!, with X (p, 1) = (L p + u, 0) and
        // X (v, 0) = (L v, 0).
        let mut term = self.log.transform_point3(p) * rest;
        let mut moved = p + term;
        for m in 2..=REST_TERMS {
            term = self.log.transform_vector3(term) * (rest / f64::from(m));
            moved += term;
        }
        sample.transform_point3(moved)
    }
}

/// One square root of an affine map by the Denman–Beavers iteration; `None` when it does not
/// converge. It stops once a step changes the root less than the one before it did while
/// both are at the level of rounding.
fn square_root(a: DMat4) -> Option<DMat4> {
    let (mut y, mut z) = (a, DMat4::IDENTITY);
    let mut last_change = f64::INFINITY;
    for _ in 0..MAX_ROOT_STEPS {
        let next_y = (y + z.inverse()) * 0.5;
        let next_z = (z + y.inverse()) * 0.5;
        let change = norm1(next_y - y);
        (y, z) = (next_y, next_z);
        if !is_finite(y) {
            return None;
        }
        let at_rounding = change <= 1e-12 * norm1(y);
        if change <= 1e-15 * norm1(y) || (at_rounding && change >= last_change) {
            return Some(affine_part(y));
        }
        last_change = change;
    }
    None
}

/// Whether the linear part of `a` has an eigenvalue on (or within rounding of) the negative
/// real axis, where no real logarithm exists: a half turn, or two negative scales. With the
/// part scaled to determinant 1, that is where its characteristic polynomial, negative at 0,
/// comes up to 0 at a maximum left of 0.
fn turns_half_way(a: DMat4) -> bool {
    let linear = glam::DMat3::from_mat4(a);
    let linear = linear * linear.determinant().cbrt().recip();
    let trace = linear.x_axis.x + linear.y_axis.y + linear.z_axis.z;
    // The sum of the principal 2 × 2 minors.
    let minors = linear.x_axis.x * linear.y_axis.y - linear.y_axis.x * linear.x_axis.y
        + linear.x_axis.x * linear.z_axis.z
        - linear.z_axis.x * linear.x_axis.z
        + linear.y_axis.y * linear.z_axis.z
        - linear.z_axis.y * linear.y_axis.z;
    let polynomial = |l: f64| ((l - trace) * l + minors) * l - 1.0;
    let discriminant = trace * trace - 3.0 * minors;
    if discriminant < 0.0 {
        return false;
    }
    // The polynomial's maximum is at the smaller critical point.
    let at = (trace - discriminant.sqrt()) / 3.0;
    at < 0.0 && polynomial(at) > -HALF_TURN_MARGIN
}

/// The matrix with its bottom row set to that of an affine map (`exp` of its result) or
/// of its logarithm: clears the rounding there.
fn affine_part(m: DMat4) -> DMat4 {
    let mut m = m;
    let last = if m.w_axis.w.abs() > 0.5 { 1.0 } else { 0.0 };
    m.x_axis.w = 0.0;
    m.y_axis.w = 0.0;
    m.z_axis.w = 0.0;
    m.w_axis.w = last;
    m
}

/// The largest column sum of absolute values.
fn norm1(m: DMat4) -> f64 {
    [m.x_axis, m.y_axis, m.z_axis, m.w_axis]
        .iter()
        .map(|c: &DVec4| c.abs().element_sum())
        .fold(0.0, f64::max)
}

fn is_finite(m: DMat4) -> bool {
    m.to_cols_array().iter().all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::*;

    fn close(a: DMat4, b: DMat4, tolerance: f64) -> bool {
        norm1(a - b) <= tolerance
    }

    /// A turn about an oblique axis by `degrees`, a non-uniform scale and a move.
    fn affine(degrees: f64) -> DMat4 {
        DMat4::from_translation(DVec3::new(0.3, -1.2, 2.0))
            * DMat4::from_quat(DQuat::from_axis_angle(
                DVec3::new(1.0, 2.0, -0.5).normalize(),
                degrees.to_radians(),
            ))
            * DMat4::from_scale(DVec3::new(1.5, 0.7, 1.1))
    }

    #[test]
    fn log_and_exp_round_trip_turns_up_to_179_degrees() {
        for degrees in [0.0, 1e-6, 10.0, 90.0, 135.0, 170.0, 178.0, 179.0] {
            let turn = DMat4::from_quat(DQuat::from_axis_angle(
                DVec3::new(0.2, -1.0, 0.4).normalize(),
                f64::to_radians(degrees),
            ));
            let log = log_affine(turn).unwrap();
            // The logarithm of a turn is the skew matrix of its axis times its angle.
            let angle = DVec3::new(log.y_axis.z, log.z_axis.x, log.x_axis.y).length();
            assert!(
                (angle - f64::to_radians(degrees)).abs() < 1e-9,
                "{degrees}°: {angle}"
            );
            assert!(close(exp_affine(log), turn, 1e-9), "{degrees}°");
            // Moved and scaled evenly, any turn short of half a turn keeps its logarithm.
            let general = DMat4::from_translation(DVec3::new(0.3, -1.2, 2.0))
                * turn
                * DMat4::from_scale(DVec3::splat(1.3));
            assert!(close(
                exp_affine(log_affine(general).unwrap()),
                general,
                1e-9
            ));
        }
    }

    #[test]
    fn fractions_add_up() {
        let a = affine(120.0);
        let half = fraction(0.5, a).unwrap();
        assert!(close(half * half, a, 1e-9), "half twice is the whole");
        assert!(close(fraction(2.0, a).unwrap(), a * a, 1e-9), "2 ⊙ A = A A");
        assert!(close(fraction(0.0, a).unwrap(), DMat4::IDENTITY, 1e-12));
        assert!(close(fraction(1.0, a).unwrap(), a, 1e-9));
        let b = affine(-40.0);
        assert!(
            close(sum(a, b).unwrap(), sum(b, a).unwrap(), 1e-12),
            "⊕ commutes"
        );
        let c = fraction(0.3, a).unwrap();
        assert!(
            close(sum(a, c).unwrap(), a * c, 1e-9),
            "A ⊕ B = A B when they commute"
        );
    }

    #[test]
    fn no_logarithm_for_a_mirror_a_half_turn_or_a_collapse() {
        // A turn near half a turn scaled unevenly has two negative eigenvalues.
        assert!(log_affine(affine(179.0)).is_none());
        let mirror = DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0));
        let half_turn = DMat4::from_rotation_z(std::f64::consts::PI);
        let flat = DMat4::from_scale(DVec3::new(1.0, 1.0, 0.0));
        let nan = DMat4::from_translation(DVec3::new(f64::NAN, 0.0, 0.0));
        for m in [mirror, half_turn, flat, nan] {
            assert!(log_affine(m).is_none(), "{m:?}");
            assert!(Fractions::new(m).is_none());
        }
    }

    #[test]
    fn fractions_of_points_match_the_exponential() {
        let t = affine(150.0);
        let fractions = Fractions::new(t).unwrap();
        let log = log_affine(t).unwrap();
        let p = DVec3::new(0.4, -0.9, 1.3);
        assert_eq!(fractions.apply(0.0, p), p, "weight 0 leaves the point");
        assert_eq!(
            fractions.apply(1.0, p),
            t.transform_point3(p),
            "weight 1 is T itself"
        );
        for w in [1e-9, 0.001_3, 0.25, 0.5, 0.618_033, 0.999] {
            let exact = exp_affine(log * w).transform_point3(p);
            assert!(fractions.apply(w, p).distance(exact) < 1e-12, "{w}");
        }
        let twice = fractions.apply(0.5, fractions.apply(0.5, p));
        assert!(twice.distance(t.transform_point3(p)) < 1e-9, "half twice");
    }
}
