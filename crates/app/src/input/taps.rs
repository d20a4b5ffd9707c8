//! Taps, the shortcuts of tablet drawing apps (Procreate, Nomad, Concepts): two fingers
//! tapped together undo, three redo, one finger tapped twice frames everything, and one
//! finger held still for [`LONG_PRESS_SECONDS`] asks for a model's context actions.
//!
//! A tap is a touch sequence, from the first finger down to the last one up, that lasts at
//! most [`TAP_SECONDS`] and in which no finger moves more than [`TAP_TRAVEL`] points from
//! where it went down; the most fingers down at once say which tap it was. The fingers
//! also start a two-finger gesture (navigation) meanwhile, but one that moved less than the
//! gestures' thresholds did nothing, and the stroke the first finger began is cancelled
//! when the second lands, so a tap leaves no trace but its command.

use std::collections::BTreeMap;

use egui::Pos2;

use super::{Phase, PointerSample};

/// Longest tap, first finger down to last finger up, in seconds.
pub const TAP_SECONDS: f64 = 0.25;
/// Farthest a finger of a tap may move, in points.
pub const TAP_TRAVEL: f32 = 10.0;
/// Longest time from the end of a one-finger tap to the end of the next for a double tap,
/// in seconds.
pub const DOUBLE_TAP_SECONDS: f64 = 0.4;
/// Farthest the second tap of a double tap may land from the first, in points.
pub const DOUBLE_TAP_REACH: f32 = 30.0;
/// How long one finger held still (within [`TAP_TRAVEL`]) is a long press, in seconds.
pub const LONG_PRESS_SECONDS: f64 = 0.5;

/// What a tap asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TapCommand {
    /// Two fingers: undo.
    Undo,
    /// Three fingers: redo.
    Redo,
    /// One finger, twice, here: frame everything (if it is not on a model).
    DoubleTap(Pos2),
    /// One finger held still here: the context actions of the model under it.
    LongPress(Pos2),
}

/// The touch sequence in progress, if any.
#[derive(Debug, Default)]
pub struct TapDetector {
    /// Where each finger down went down.
    down: BTreeMap<i64, Pos2>,
    /// When the sequence's first finger went down.
    started: f64,
    /// When the first poll after that saw the finger down (the samples' clock).
    first_polled: Option<f64>,
    /// The most fingers down at once.
    most: usize,
    /// Whether the sequence is still a tap.
    is_tap: bool,
    /// When and where the last one-finger tap ended, until a double tap uses it.
    single: Option<(f64, Pos2)>,
}

impl TapDetector {
    /// Follows one touch sample; returns the command when it ends a tap.
    pub fn follow(&mut self, s: &PointerSample) -> Option<TapCommand> {
        match s.phase {
            Phase::Down => {
                if self.down.is_empty() {
                    *self = TapDetector {
                        started: s.time,
                        is_tap: true,
                        single: self.single,
                        ..TapDetector::default()
                    };
                }
                self.down.insert(s.id, s.pos_in_screen);
                self.most = self.most.max(self.down.len());
                None
            }
            Phase::Move => {
                let moved = self
                    .down
                    .get(&s.id)
                    .is_some_and(|start| start.distance(s.pos_in_screen) > TAP_TRAVEL);
                if moved {
                    self.is_tap = false;
                }
                None
            }
            Phase::Up | Phase::Cancel => {
                self.down.remove(&s.id)?;
                if s.phase == Phase::Cancel || s.time - self.started > TAP_SECONDS {
                    self.is_tap = false;
                }
                if !self.down.is_empty() {
                    return None;
                }
                let was_tap = std::mem::take(&mut self.is_tap);
                // Anything but a one-finger tap between two taps makes them no double tap.
                if !was_tap || self.most != 1 {
                    self.single = None;
                }
                if !was_tap {
                    return None;
                }
                match self.most {
                    1 => self.single_tap(s.time, s.pos_in_screen),
                    2 => Some(TapCommand::Undo),
                    3 => Some(TapCommand::Redo),
                    _ => None,
                }
            }
        }
    }
}

impl TapDetector {
    /// At `now` (the samples' clock), the place of the one finger held still since
    /// [`LONG_PRESS_SECONDS`], once per touch sequence; the sequence is then no tap.
    ///
    /// The hold counts from the later of the finger's time stamp and the first poll that saw
    /// it: a busy page may deliver a touch long after its stamp, and the lift that follows
    /// it later still, so a quick tap delivered late must not look held.
    pub fn long_press(&mut self, now: f64) -> Option<Pos2> {
        let held = self.down.len() == 1 && self.most == 1 && self.is_tap;
        if !held {
            return None;
        }
        let seen = *self.first_polled.get_or_insert(now);
        if now - self.started.max(seen) < LONG_PRESS_SECONDS {
            return None;
        }
        self.is_tap = false;
        self.single = None;
        self.down.values().next().copied()
    }

    /// A one-finger tap ended at `time` at `at`: the second of a double tap, or the first.
    fn single_tap(&mut self, time: f64, at: Pos2) -> Option<TapCommand> {
        let is_second = self.single.take().is_some_and(|(then, there)| {
            time - then <= DOUBLE_TAP_SECONDS && there.distance(at) <= DOUBLE_TAP_REACH
        });
        if is_second {
            return Some(TapCommand::DoubleTap(at));
        }
        self.single = Some((time, at));
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::PointerKind;

    fn touch(id: i64, phase: Phase, x: f32, time: f64) -> PointerSample {
        PointerSample {
            id,
            phase,
            pos_in_screen: egui::pos2(x, 100.0),
            pressure: 0.5,
            kind: PointerKind::Touch,
            buttons: 0,
            contact: 0.0,
            time,
        }
    }

    fn run(samples: &[PointerSample]) -> Vec<TapCommand> {
        let mut taps = TapDetector::default();
        samples.iter().filter_map(|s| taps.follow(s)).collect()
    }

    #[test]
    fn one_finger_twice_at_one_place_is_a_double_tap() {
        let tap = |x: f32, t: f64| {
            [
                touch(1, Phase::Down, x, t),
                touch(1, Phase::Up, x, t + 0.08),
            ]
        };
        let twice: Vec<PointerSample> = [tap(100.0, 0.0), tap(110.0, 0.3)].concat();
        assert_eq!(
            run(&twice),
            [TapCommand::DoubleTap(egui::pos2(110.0, 100.0))]
        );
        let slow: Vec<PointerSample> = [tap(100.0, 0.0), tap(100.0, 0.6)].concat();
        assert_eq!(run(&slow), [], "too slow");
        let apart: Vec<PointerSample> = [tap(100.0, 0.0), tap(180.0, 0.3)].concat();
        assert_eq!(run(&apart), [], "too far apart");
        // Three taps: one double tap, and the third starts afresh.
        let thrice: Vec<PointerSample> =
            [tap(100.0, 0.0), tap(100.0, 0.3), tap(100.0, 0.6)].concat();
        assert_eq!(run(&thrice).len(), 1);
        // A drag between two taps is no double tap.
        let dragged = [
            tap(100.0, 0.0).to_vec(),
            vec![
                touch(1, Phase::Down, 100.0, 0.1),
                touch(1, Phase::Move, 160.0, 0.15),
                touch(1, Phase::Up, 160.0, 0.2),
            ],
            tap(100.0, 0.3).to_vec(),
        ]
        .concat();
        assert_eq!(run(&dragged), [], "{dragged:?}");
    }

    #[test]
    fn a_quick_tap_delivered_late_is_no_long_press() {
        let mut taps = TapDetector::default();
        // Stamped at 0, seen by the page's polls only from 0.45 on, its lift still to come.
        taps.follow(&touch(1, Phase::Down, 100.0, 0.0));
        assert_eq!(taps.long_press(0.45), None);
        assert_eq!(taps.long_press(0.7), None, "0.25 s after it was seen");
        assert_eq!(taps.follow(&touch(1, Phase::Up, 100.0, 0.06)), None);
        // Held for real: a long press half a second after the page saw it.
        taps.follow(&touch(2, Phase::Down, 100.0, 1.0));
        assert_eq!(taps.long_press(1.02), None);
        assert_eq!(taps.long_press(1.53), Some(egui::pos2(100.0, 100.0)));
    }

    #[test]
    fn two_fingers_undo_and_three_redo() {
        let two = [
            touch(1, Phase::Down, 100.0, 0.0),
            touch(2, Phase::Down, 200.0, 0.02),
            touch(1, Phase::Move, 103.0, 0.05),
            touch(2, Phase::Up, 200.0, 0.12),
            touch(1, Phase::Up, 103.0, 0.14),
        ];
        assert_eq!(run(&two), [TapCommand::Undo]);
        let three = [
            touch(1, Phase::Down, 100.0, 0.0),
            touch(2, Phase::Down, 200.0, 0.01),
            touch(3, Phase::Down, 300.0, 0.02),
            touch(1, Phase::Up, 100.0, 0.1),
            touch(2, Phase::Up, 200.0, 0.1),
            touch(3, Phase::Up, 300.0, 0.11),
        ];
        assert_eq!(run(&three), [TapCommand::Redo]);
    }

    #[test]
    fn slow_moving_or_single_touches_are_not_taps() {
        let slow = [
            touch(1, Phase::Down, 100.0, 0.0),
            touch(2, Phase::Down, 200.0, 0.02),
            touch(2, Phase::Up, 200.0, 0.3),
            touch(1, Phase::Up, 100.0, 0.31),
        ];
        assert_eq!(run(&slow), []);
        let pinch = [
            touch(1, Phase::Down, 100.0, 0.0),
            touch(2, Phase::Down, 200.0, 0.02),
            touch(2, Phase::Move, 230.0, 0.05),
            touch(2, Phase::Up, 230.0, 0.1),
            touch(1, Phase::Up, 100.0, 0.12),
        ];
        assert_eq!(run(&pinch), []);
        let one = [
            touch(1, Phase::Down, 100.0, 0.0),
            touch(1, Phase::Up, 100.0, 0.05),
        ];
        assert_eq!(run(&one), []);
        // A tap after a slow sequence still counts: each sequence starts afresh.
        let mut samples = slow.to_vec();
        samples.extend([
            touch(3, Phase::Down, 100.0, 1.0),
            touch(4, Phase::Down, 150.0, 1.01),
            touch(3, Phase::Up, 100.0, 1.1),
            touch(4, Phase::Up, 150.0, 1.1),
        ]);
        assert_eq!(run(&samples), [TapCommand::Undo]);
    }
}
