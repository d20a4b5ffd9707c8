//! Two-finger touch navigation, after the conventions of tablet sculpting apps.
//!
//! Nomad Sculpt and SculptGL tell a pinch from a drag by how far the fingers have moved
//! before deciding: once the distance between the fingers has changed by more than
//! [`PINCH_THRESHOLD`] points the gesture is a pinch (zoom about the fingers, and the
//! fingers' midpoint pans); if instead their midpoint has travelled [`DRAG_THRESHOLD`]
//! points first, it is a drag, which orbits while fingers draw and pans once a pen has
//! been seen. The decision holds until the fingers lift, so a drag never jitters into zoom.

use egui::{Pos2, Vec2};

/// Change of finger spread, in points, that makes a two-finger gesture a pinch.
pub const PINCH_THRESHOLD: f32 = 14.0;
/// Travel of the fingers' midpoint, in points, that makes a two-finger gesture a drag.
pub const DRAG_THRESHOLD: f32 = 8.0;

/// A camera motion asked for by the user.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NavAction {
    /// Turn about the target by a screen-space drag delta in points.
    Orbit(Vec2),
    /// Slide the view by a screen-space drag delta in points.
    Pan(Vec2),
    /// Multiply the camera distance by `factor` (below 1 comes closer).
    Zoom {
        /// Distance multiplier.
        factor: f32,
    },
}

/// What a two-finger drag (not a pinch) does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TwoFingerDrag {
    /// Orbit: while fingers draw, before any pen has been seen.
    Orbit,
    /// Pan: once a pen has been seen, one finger orbits and two pan.
    Pan,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    Undecided,
    Drag,
    Pinch,
}

/// State of one two-finger gesture, from the second touch down to a lift.
#[derive(Clone, Debug)]
pub struct TwoFingerGesture {
    ids: [i64; 2],
    start: [Pos2; 2],
    last: [Pos2; 2],
    mode: Mode,
    drag: TwoFingerDrag,
}

impl TwoFingerGesture {
    /// Starts a gesture with two touches at their current positions.
    pub fn new(ids: [i64; 2], positions: [Pos2; 2], drag: TwoFingerDrag) -> Self {
        Self {
            ids,
            start: positions,
            last: positions,
            mode: Mode::Undecided,
            drag,
        }
    }

    /// Whether this gesture follows the touch `id`.
    pub fn follows(&self, id: i64) -> bool {
        self.ids.contains(&id)
    }

    /// Where the two fingers are now.
    pub fn positions(&self) -> [Pos2; 2] {
        self.last
    }

    /// Moves touch `id` to `pos` and returns the camera motions this causes.
    pub fn update(&mut self, id: i64, pos: Pos2, out: &mut Vec<NavAction>) {
        let Some(slot) = self.ids.iter().position(|&i| i == id) else {
            return;
        };
        let before = self.last;
        self.last[slot] = pos;
        if self.mode == Mode::Undecided {
            self.mode = self.decide();
            if self.mode == Mode::Undecided {
                return;
            }
        }
        let midpoint_delta = midpoint(self.last) - midpoint(before);
        match self.mode {
            Mode::Undecided => {}
            Mode::Drag => out.push(match self.drag {
                TwoFingerDrag::Orbit => NavAction::Orbit(midpoint_delta),
                TwoFingerDrag::Pan => NavAction::Pan(midpoint_delta),
            }),
            Mode::Pinch => {
                let (spread_before, spread_now) = (spread(before), spread(self.last));
                if spread_before > 1.0 && spread_now > 1.0 {
                    out.push(NavAction::Zoom {
                        factor: spread_before / spread_now,
                    });
                }
                if midpoint_delta != Vec2::ZERO {
                    out.push(NavAction::Pan(midpoint_delta));
                }
            }
        }
    }

    fn decide(&self) -> Mode {
        let spread_change = (spread(self.last) - spread(self.start)).abs();
        let travel = (midpoint(self.last) - midpoint(self.start)).length();
        if spread_change > PINCH_THRESHOLD {
            Mode::Pinch
        } else if travel > DRAG_THRESHOLD {
            Mode::Drag
        } else {
            Mode::Undecided
        }
    }
}

fn spread(p: [Pos2; 2]) -> f32 {
    (p[0] - p[1]).length()
}

fn midpoint(p: [Pos2; 2]) -> Pos2 {
    p[0] + (p[1] - p[0]) * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::pos2;

    fn run(drag: TwoFingerDrag, a: [Pos2; 2], b: [Pos2; 2], steps: usize) -> Vec<NavAction> {
        let mut g = TwoFingerGesture::new([1, 2], a, drag);
        let mut out = Vec::new();
        for i in 1..=steps {
            let t = i as f32 / steps as f32;
            g.update(1, a[0] + (b[0] - a[0]) * t, &mut out);
            g.update(2, a[1] + (b[1] - a[1]) * t, &mut out);
        }
        out
    }

    #[test]
    fn spreading_fingers_zooms_in() {
        let out = run(
            TwoFingerDrag::Orbit,
            [pos2(400.0, 300.0), pos2(500.0, 300.0)],
            [pos2(300.0, 300.0), pos2(600.0, 300.0)],
            10,
        );
        let total: f32 = out
            .iter()
            .filter_map(|a| match a {
                NavAction::Zoom { factor } => Some(*factor),
                _ => None,
            })
            .product();
        assert!(out.iter().all(|a| !matches!(a, NavAction::Orbit(_))));
        // Zoom from the moment of decision: the product is at most 100/300 and well below 1.
        assert!(total < 0.5 && total > 0.3, "zoom factor {total}");
    }

    #[test]
    fn parallel_drag_orbits_before_a_pen_and_pans_after() {
        let (a, b) = (
            [pos2(400.0, 300.0), pos2(480.0, 300.0)],
            [pos2(400.0, 400.0), pos2(480.0, 400.0)],
        );
        let orbit = run(TwoFingerDrag::Orbit, a, b, 20);
        assert!(!orbit.is_empty());
        assert!(orbit.iter().all(|x| matches!(x, NavAction::Orbit(_))));
        let travelled: f32 = orbit
            .iter()
            .map(|x| match x {
                NavAction::Orbit(d) => d.y,
                _ => 0.0,
            })
            .sum();
        assert!(travelled > 80.0 && travelled <= 100.0, "{travelled}");
        let pan = run(TwoFingerDrag::Pan, a, b, 20);
        assert!(pan.iter().all(|x| matches!(x, NavAction::Pan(_))));
    }

    #[test]
    fn small_jitter_does_nothing() {
        let out = run(
            TwoFingerDrag::Orbit,
            [pos2(400.0, 300.0), pos2(500.0, 300.0)],
            [pos2(403.0, 302.0), pos2(502.0, 299.0)],
            5,
        );
        assert!(out.is_empty());
    }

    #[test]
    fn unknown_touch_is_ignored() {
        let mut g = TwoFingerGesture::new(
            [1, 2],
            [pos2(0.0, 0.0), pos2(50.0, 0.0)],
            TwoFingerDrag::Pan,
        );
        let mut out = Vec::new();
        g.update(7, pos2(500.0, 500.0), &mut out);
        assert!(out.is_empty());
        assert!(!g.follows(7) && g.follows(2));
    }
}
