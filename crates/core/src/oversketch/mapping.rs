//! Where the handle goes: each handle point moves to the stroke point at the same relative
//! arclength, like an elastic rope stretched along the stroke (SEED, Bao and Howard 2014,
//! Eqs. 4–5; SilSketch §5.4.3), and the ends blend back into the untouched silhouette
//! (SEED Eq. 6, with a smoother weight than its Eq. 7).
//!
//! Only screen positions are mapped; callers keep each handle point's depth, as both papers
//! do ("preserving the scale in depth leads to more intuitive results", Nealen §5.2).
//! Both polylines must run the same way: [`super::handle_points`] returns the handle in
//! the stroke's order.

use glam::DVec2;

use crate::curve::polyline::{
    closest_point, cumulative_lengths, point_at, relative_arclengths, segment_at,
};

/// Fraction of the handle's arclength, at each end, that blends from the silhouette to the
/// stroke (SEED's `ω = 0.2`).
pub const BLEND_WIDTH: f64 = 0.2;

/// Target screen positions for each handle point: the stroke point at the same relative
/// arclength `r = l(0, i) / l` (SEED Eqs. 4–5). The first and last handle points go to the
/// stroke's ends and the order is kept. A handle of zero length spreads by point index
/// instead. An empty stroke maps nothing.
pub fn map_to_stroke(handle: &[DVec2], stroke: &[DVec2]) -> Vec<DVec2> {
    if stroke.is_empty() {
        return Vec::new();
    }
    let stroke_cumulative = cumulative_lengths(stroke);
    let stroke_length = stroke_cumulative[stroke_cumulative.len() - 1];
    relative_arclengths(handle)
        .into_iter()
        .map(|r| point_at(stroke, &stroke_cumulative, r * stroke_length))
        .collect()
}

/// The target of a point `p` near the handle, as SilSketch places handle vertices
/// (§5.4.3, Fig. 5.10): `p` projects onto the handle at relative arclength `r` with signed
/// offset `d`; its target lies at `r` on the stroke, offset by `d` scaled by the stroke's
/// length over the handle's, along the stroke's normal there.
pub fn map_point_to_stroke(handle: &[DVec2], stroke: &[DVec2], p: DVec2) -> DVec2 {
    if handle.len() < 2 || stroke.len() < 2 {
        return stroke.first().copied().unwrap_or(p);
    }
    let handle_cumulative = cumulative_lengths(handle);
    let stroke_cumulative = cumulative_lengths(stroke);
    let handle_length = handle_cumulative[handle.len() - 1];
    let stroke_length = stroke_cumulative[stroke.len() - 1];
    if handle_length <= 0.0 || stroke_length <= 0.0 {
        return stroke[0];
    }
    let closest = closest_point(handle, &handle_cumulative, p);
    let (s, direction) = (closest.arclength, closest.direction);
    let offset = direction.perp_dot(p - point_at(handle, &handle_cumulative, s));
    let s_on_stroke = s / handle_length * stroke_length;
    let i = segment_at(&stroke_cumulative, s_on_stroke);
    let stroke_direction = (stroke[i + 1] - stroke[i])
        .try_normalize()
        .unwrap_or(direction);
    point_at(stroke, &stroke_cumulative, s_on_stroke)
        + offset * stroke_length / handle_length * stroke_direction.perp()
}

/// The blend weight at relative arclength `r`: 0 at the handle's ends, rising to 1 over
/// the first and last `width`, 1 in between. SEED (Eq. 7) rises as `√(r/ω)`, whose
/// infinite slope at the end bends the new outline sharply where it leaves the old one (a
/// created ellipse over-sketched 6 px above its outline: a 13° turn within 10 px); we rise
/// as the smoothstep `3t² − 2t³` of `t = r/ω`, which leaves the old outline along its
/// tangent.
pub fn blend_weight(r: f64, width: f64) -> f64 {
    let r = r.clamp(0.0, 1.0);
    if width <= 0.0 {
        return 1.0;
    }
    let t = (r.min(1.0 - r) / width).min(1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Blends mapped targets back into the handle at its ends (SEED Eq. 6):
/// `p'_i = f(r_i) p_i + (1 − f(r_i)) q_i` with `f` = [`blend_weight`] at the handle's
/// relative arclength `r_i`, `p_i` in `targets` and `q_i` in `handle`. The handle's end
/// points stay where they are, so the edit attaches to the rest of the silhouette.
pub fn blend_ends(handle: &[DVec2], targets: &[DVec2], width: f64) -> Vec<DVec2> {
    debug_assert_eq!(handle.len(), targets.len());
    relative_arclengths(handle)
        .into_iter()
        .zip(handle.iter().zip(targets))
        .map(|(r, (&q, &p))| q.lerp(p, blend_weight(r, width)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_follow_relative_arclength_exactly() {
        // Uneven handle spacing along a 10 px line; stroke an L of length 20.
        let handle = [0.0, 1.0, 2.5, 6.0, 10.0].map(|x| DVec2::new(x, 0.0));
        let stroke = [
            DVec2::new(0.0, 5.0),
            DVec2::new(10.0, 5.0),
            DVec2::new(10.0, 15.0),
        ];
        let targets = map_to_stroke(&handle, &stroke);
        let expected = [
            DVec2::new(0.0, 5.0),
            DVec2::new(2.0, 5.0),
            DVec2::new(5.0, 5.0),
            DVec2::new(10.0, 7.0),
            DVec2::new(10.0, 15.0),
        ];
        for (t, e) in targets.iter().zip(expected) {
            assert!(t.distance(e) < 1e-12, "{t} vs {e}");
        }
    }

    #[test]
    fn a_scaled_copy_keeps_the_handle_spacing() {
        // The elastic-rope property: a stroke that is the handle scaled by 3 about its
        // start maps each point to 3 times its position.
        let handle: Vec<DVec2> = (0..20)
            .map(|i| {
                let t = (i as f64 / 19.0).powi(2);
                DVec2::new(40.0 * t, 10.0 * (3.0 * t).sin())
            })
            .collect();
        let stroke: Vec<DVec2> = handle.iter().map(|&p| 3.0 * p).collect();
        for (t, q) in map_to_stroke(&handle, &stroke).iter().zip(&handle) {
            assert!(t.distance(3.0 * *q) < 1e-9);
        }
    }

    #[test]
    fn points_off_the_handle_keep_their_scaled_offset() {
        let handle = [DVec2::ZERO, DVec2::new(10.0, 0.0)];
        // The stroke is twice as long and runs down the screen.
        let stroke = [DVec2::new(100.0, 0.0), DVec2::new(100.0, 20.0)];
        let target = map_point_to_stroke(&handle, &stroke, DVec2::new(2.5, 1.0));
        // r = 0.25, offset +1 on the handle's left (its perp is +y); the stroke's perp is -x.
        assert!(target.distance(DVec2::new(98.0, 5.0)) < 1e-12, "{target}");
    }

    #[test]
    fn blend_weight_is_zero_at_the_ends_one_inside_and_continuous() {
        assert_eq!(blend_weight(0.0, BLEND_WIDTH), 0.0);
        assert_eq!(blend_weight(1.0, BLEND_WIDTH), 0.0);
        assert_eq!(blend_weight(0.5, BLEND_WIDTH), 1.0);
        assert!((blend_weight(0.1, BLEND_WIDTH) - 0.5).abs() < 1e-12);
        assert!((blend_weight(0.05, BLEND_WIDTH) - 0.15625).abs() < 1e-12);
        // Leaves the end flat: no kink where the old outline goes on.
        assert!(blend_weight(1e-4, BLEND_WIDTH) < 1e-6);
        for edge in [BLEND_WIDTH, 1.0 - BLEND_WIDTH] {
            let jump = (blend_weight(edge - 1e-9, BLEND_WIDTH)
                - blend_weight(edge + 1e-9, BLEND_WIDTH))
            .abs();
            assert!(jump < 1e-6);
        }
        let mut previous = 0.0;
        for k in 0..=50 {
            let f = blend_weight(k as f64 / 100.0, BLEND_WIDTH);
            assert!(f >= previous);
            previous = f;
        }
    }

    #[test]
    fn blended_ends_stay_on_the_silhouette() {
        let handle: Vec<DVec2> = (0..=10).map(|i| DVec2::new(i as f64, 0.0)).collect();
        let stroke = [DVec2::new(0.0, 4.0), DVec2::new(10.0, 4.0)];
        let blended = blend_ends(&handle, &map_to_stroke(&handle, &stroke), BLEND_WIDTH);
        assert_eq!(blended[0], handle[0]);
        assert_eq!(blended[10], handle[10]);
        assert!((blended[5].y - 4.0).abs() < 1e-12);
        // r = 0.1: halfway in the blend zone, weight 0.5.
        assert!((blended[1].y - 2.0).abs() < 1e-12);
        assert!(blended.iter().all(|p| p.x >= 0.0 && p.x <= 10.0));
    }
}
