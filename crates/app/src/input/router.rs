//! Decides, per pointer, whether a sample feeds the active tool or the camera.
//!
//! The rules follow tablet sculpting apps and tldraw's draw tool:
//! - mouse: left button uses the tool, right button orbits, middle button pans;
//! - pen: always uses the tool; the first pen sample switches on palm rejection;
//! - touch before any pen: one finger uses the tool, two fingers navigate
//!   ([`TwoFingerDrag::Orbit`]); a second finger landing mid-stroke cancels that stroke,
//!   since it was the start of a gesture, not a drawing;
//! - touch after a pen: touches never draw; one finger orbits, two pan and pinch;
//! - a palm: a touch whose contact is wider than [`PALM_CONTACT`] points, landing while a pen
//!   is near or was used in the last [`PALM_PEN_SECONDS`], is ignored from down to up: it
//!   neither draws nor moves the view.
//!
//! After a two-finger gesture, the remaining finger does nothing until every finger has
//! lifted, so lifting one finger a little early never leaves a stray stroke.

use std::collections::{BTreeMap, BTreeSet};

use egui::{Pos2, Vec2};

use super::gestures::{NavAction, TwoFingerDrag, TwoFingerGesture};
use super::taps::{TapCommand, TapDetector};
use super::{Phase, PointerKind, PointerSample, buttons};

/// A touch wider than this (points) near a pen is a resting palm.
pub const PALM_CONTACT: f32 = 20.0;
/// How long after the pen's last sample (down, moving or hovering) a wide touch is a palm.
pub const PALM_PEN_SECONDS: f64 = 1.0;
/// The longest time between two polls for a held finger to count as a long press: the
/// browser delivers touch events with frames, so after a slower frame a finger that looks
/// still may have moves on their way.
pub const LONG_PRESS_STEADY_SECONDS: f64 = 0.2;

/// An input for the active tool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ToolEvent {
    /// A stroke starts.
    Begin(PointerSample),
    /// The stroke's pointer moved.
    Move(PointerSample),
    /// The stroke ends normally.
    End(PointerSample),
    /// The stroke is abandoned; the tool must leave no trace.
    Cancel,
}

/// Two fingers on the view, for a tool that takes them (see
/// [`InputRouter::give_hands_to_tool`]) rather than the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hands {
    /// Two fingers came down here (screen points): a tool may take the gesture now.
    Down([Pos2; 2]),
    /// The tool's two fingers moved.
    Move([Pos2; 2]),
    /// A finger lifted: the tool's gesture ends.
    Up,
    /// The tool's gesture was abandoned.
    Cancel,
}

/// Where a sample went.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Routed {
    /// Two fingers, offered to the active tool or taken by it.
    Hands(Hands),
    /// To the active tool.
    Tool(ToolEvent),
    /// To the camera.
    Nav(NavAction),
    /// A multi-finger tap: undo or redo.
    Tap(TapCommand),
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Drag {
    Tool,
    Orbit,
    Pan,
}

/// Routing state across frames.
#[derive(Debug, Default)]
pub struct InputRouter {
    pen_seen: bool,
    /// Active drags by pointer id, with the last position.
    drags: BTreeMap<i64, (Drag, Pos2)>,
    /// Touches down, by id, with the last position.
    touches: BTreeMap<i64, Pos2>,
    two_finger: Option<TwoFingerGesture>,
    /// Whether the tool took the two-finger gesture (it gets [`Hands`] instead of the camera
    /// getting [`NavAction`]s).
    hands_to_tool: bool,
    /// Set after a two-finger gesture until all fingers lift.
    touches_spent: bool,
    taps: TapDetector,
    /// When the pen was last seen (down, moving or hovering), in seconds.
    pen_last_seen: Option<f64>,
    /// Touches taken for palms, ignored until they lift.
    palms: BTreeSet<i64>,
    /// Where the pen hovers, if it does.
    pen_hover: Option<Pos2>,
    /// When [`InputRouter::poll`] last ran.
    last_poll: f64,
    /// The kind of the last pointer seen.
    last_kind: Option<PointerKind>,
}

impl InputRouter {
    /// Whether a pen has been seen, so touch only navigates.
    pub fn pen_seen(&self) -> bool {
        self.pen_seen
    }

    /// The kind of pointer the user works with, as hints name it: the last one seen, except
    /// that a finger after a pen only moves the view, so the pen stays the one that draws.
    /// `None` before any pointer.
    pub fn device(&self) -> Option<PointerKind> {
        match self.last_kind {
            Some(PointerKind::Touch) if self.pen_seen => Some(PointerKind::Pen),
            kind => kind,
        }
    }

    /// Where the pen hovers over the view, when the browser reports it.
    pub fn pen_hover(&self) -> Option<Pos2> {
        self.pen_hover
    }

    /// Gives the two-finger gesture just offered ([`Hands::Down`]) to the tool: its moves go
    /// to the tool until a finger lifts.
    pub fn give_hands_to_tool(&mut self) {
        self.hands_to_tool = self.two_finger.is_some();
    }

    /// Whether any finger is on the screen.
    pub fn is_touching(&self) -> bool {
        !self.touches.is_empty()
    }

    /// Between samples, at `now` (the samples' clock): a finger held still long enough is a
    /// long press ([`TapCommand::LongPress`]), judged only while frames come quickly (see
    /// [`LONG_PRESS_STEADY_SECONDS`]). Its stroke goes on unless the app takes the touch
    /// ([`InputRouter::take_touch`]): a slow start of a stroke on empty canvas is not lost.
    pub fn poll(&mut self, now: f64, out: &mut Vec<Routed>) {
        let steady = now - std::mem::replace(&mut self.last_poll, now) <= LONG_PRESS_STEADY_SECONDS;
        if steady && let Some(at) = self.taps.long_press(now) {
            out.push(Routed::Tap(TapCommand::LongPress(at)));
        }
    }

    /// Takes the fingers down for the app (a long press that opened a menu): the strokes
    /// they began are cancelled, and they do nothing more until every finger lifts.
    pub fn take_touch(&mut self, out: &mut Vec<Routed>) {
        self.cancel_touch_strokes(out);
        self.drags.retain(|id, _| !self.touches.contains_key(id));
        self.touches_spent = true;
    }

    /// Routes one sample. `starts_in_viewport` says whether a `Down` lands on the 3D view
    /// rather than on a panel; samples of pointers that went down elsewhere are dropped.
    pub fn route(&mut self, s: &PointerSample, starts_in_viewport: bool, out: &mut Vec<Routed>) {
        self.last_kind = Some(s.kind);
        if s.kind == PointerKind::Pen {
            if !self.pen_seen {
                self.pen_seen = true;
                self.cancel_touch_strokes(out);
            }
            self.pen_last_seen = Some(s.time);
            let hovers = s.phase == Phase::Move && s.buttons == 0;
            self.pen_hover = hovers.then_some(s.pos_in_screen);
        }
        if s.kind == PointerKind::Touch && self.is_palm(s) {
            return;
        }
        match s.kind {
            PointerKind::Touch => self.route_touch(s, starts_in_viewport, out),
            PointerKind::Mouse | PointerKind::Pen => self.route_button(s, starts_in_viewport, out),
        }
    }

    fn route_button(&mut self, s: &PointerSample, starts_in_viewport: bool, out: &mut Vec<Routed>) {
        match s.phase {
            Phase::Down => {
                if !starts_in_viewport || self.drags.contains_key(&s.id) {
                    return;
                }
                let drag = if s.kind == PointerKind::Pen || s.buttons & buttons::PRIMARY != 0 {
                    Drag::Tool
                } else if s.buttons & buttons::SECONDARY != 0 {
                    Drag::Orbit
                } else {
                    Drag::Pan
                };
                if drag == Drag::Tool && self.tool_busy() {
                    return;
                }
                self.drags.insert(s.id, (drag, s.pos_in_screen));
                if drag == Drag::Tool {
                    out.push(Routed::Tool(ToolEvent::Begin(*s)));
                }
            }
            Phase::Move => self.continue_drag(s, out),
            Phase::Up | Phase::Cancel => self.end_drag(s, out),
        }
    }

    fn route_touch(&mut self, s: &PointerSample, starts_in_viewport: bool, out: &mut Vec<Routed>) {
        let starts_a_sequence = s.phase == Phase::Down && self.touches.is_empty();
        if (starts_in_viewport || !starts_a_sequence)
            && let Some(command) = self.taps.follow(s)
        {
            out.push(Routed::Tap(command));
        }
        match s.phase {
            Phase::Down => {
                if !starts_in_viewport && self.touches.is_empty() {
                    return;
                }
                self.touches.insert(s.id, s.pos_in_screen);
                self.touch_down(s, out);
            }
            Phase::Move => {
                if !self.touches.contains_key(&s.id) {
                    return;
                }
                self.touches.insert(s.id, s.pos_in_screen);
                if let Some(g) = self.two_finger.as_mut().filter(|g| g.follows(s.id)) {
                    let mut actions = Vec::new();
                    g.update(s.id, s.pos_in_screen, &mut actions);
                    if self.hands_to_tool {
                        out.push(Routed::Hands(Hands::Move(g.positions())));
                    } else {
                        out.extend(actions.into_iter().map(Routed::Nav));
                    }
                } else {
                    self.continue_drag(s, out);
                }
            }
            Phase::Up | Phase::Cancel => {
                if self.touches.remove(&s.id).is_none() {
                    return;
                }
                if self.two_finger.as_ref().is_some_and(|g| g.follows(s.id)) {
                    self.two_finger = None;
                    if std::mem::take(&mut self.hands_to_tool) {
                        let end = match s.phase {
                            Phase::Cancel => Hands::Cancel,
                            _ => Hands::Up,
                        };
                        out.push(Routed::Hands(end));
                    }
                }
                self.end_drag(s, out);
                if self.touches.is_empty() {
                    self.touches_spent = false;
                }
            }
        }
    }

    fn touch_down(&mut self, s: &PointerSample, out: &mut Vec<Routed>) {
        if self.touches_spent {
            return;
        }
        match self.touches.len() {
            1 if self.pen_seen => {
                self.drags.insert(s.id, (Drag::Orbit, s.pos_in_screen));
            }
            1 if !self.tool_busy() => {
                self.drags.insert(s.id, (Drag::Tool, s.pos_in_screen));
                out.push(Routed::Tool(ToolEvent::Begin(*s)));
            }
            2 => {
                self.cancel_touch_strokes(out);
                let touch_ids: Vec<i64> = self.touches.keys().copied().collect();
                for id in &touch_ids {
                    self.drags.remove(id);
                }
                let ids = [touch_ids[0], touch_ids[1]];
                let positions = [self.touches[&ids[0]], self.touches[&ids[1]]];
                let drag = if self.pen_seen {
                    TwoFingerDrag::Pan
                } else {
                    TwoFingerDrag::Orbit
                };
                self.two_finger = Some(TwoFingerGesture::new(ids, positions, drag));
                self.hands_to_tool = false;
                self.touches_spent = true;
                out.push(Routed::Hands(Hands::Down(positions)));
            }
            _ => {}
        }
    }

    fn continue_drag(&mut self, s: &PointerSample, out: &mut Vec<Routed>) {
        let Some((drag, last)) = self.drags.get_mut(&s.id) else {
            return;
        };
        let delta: Vec2 = s.pos_in_screen - *last;
        *last = s.pos_in_screen;
        out.push(match drag {
            Drag::Tool => Routed::Tool(ToolEvent::Move(*s)),
            Drag::Orbit => Routed::Nav(NavAction::Orbit(delta)),
            Drag::Pan => Routed::Nav(NavAction::Pan(delta)),
        });
    }

    fn end_drag(&mut self, s: &PointerSample, out: &mut Vec<Routed>) {
        if let Some((Drag::Tool, _)) = self.drags.remove(&s.id) {
            out.push(Routed::Tool(match s.phase {
                Phase::Cancel => ToolEvent::Cancel,
                _ => ToolEvent::End(*s),
            }));
        }
    }

    /// Whether touch sample `s` belongs to a palm (see the module's rules): a palm is known
    /// from its down, and forgotten when it lifts.
    fn is_palm(&mut self, s: &PointerSample) -> bool {
        let pen_near = self
            .pen_last_seen
            .is_some_and(|seen| s.time - seen <= PALM_PEN_SECONDS);
        if s.phase == Phase::Down && s.contact > PALM_CONTACT && pen_near {
            self.palms.insert(s.id);
        }
        match s.phase {
            Phase::Up | Phase::Cancel => self.palms.remove(&s.id),
            Phase::Down | Phase::Move => self.palms.contains(&s.id),
        }
    }

    fn tool_busy(&self) -> bool {
        self.drags.values().any(|(d, _)| *d == Drag::Tool)
    }

    /// A stroke begun by a finger is really the start of a gesture or a resting palm.
    fn cancel_touch_strokes(&mut self, out: &mut Vec<Routed>) {
        let touch_strokes: Vec<i64> = self
            .drags
            .iter()
            .filter(|(id, (d, _))| *d == Drag::Tool && self.touches.contains_key(id))
            .map(|(id, _)| *id)
            .collect();
        for id in touch_strokes {
            self.drags.remove(&id);
            out.push(Routed::Tool(ToolEvent::Cancel));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::pos2;

    fn sample(id: i64, kind: PointerKind, phase: Phase, x: f32, y: f32) -> PointerSample {
        PointerSample {
            id,
            phase,
            pos_in_screen: pos2(x, y),
            pressure: 0.5,
            kind,
            buttons: if matches!(phase, Phase::Up) {
                0
            } else {
                buttons::PRIMARY
            },
            contact: 0.0,
            time: 0.0,
        }
    }

    fn route_all(router: &mut InputRouter, samples: &[PointerSample]) -> Vec<Routed> {
        let mut out = Vec::new();
        for s in samples {
            router.route(s, true, &mut out);
        }
        out
    }

    fn one_finger_drag(id: i64) -> Vec<PointerSample> {
        let t = PointerKind::Touch;
        vec![
            sample(id, t, Phase::Down, 100.0, 100.0),
            sample(id, t, Phase::Move, 150.0, 120.0),
            sample(id, t, Phase::Up, 150.0, 120.0),
        ]
    }

    #[test]
    fn a_finger_held_still_is_a_long_press_and_once_taken_it_cancels_its_stroke_and_does_nothing() {
        let mut router = InputRouter::default();
        let touch = PointerKind::Touch;
        let down = sample(1, touch, Phase::Down, 100.0, 100.0);
        let out = route_all(&mut router, &[down]);
        assert!(matches!(out[0], Routed::Tool(ToolEvent::Begin(_))));
        let mut polled = Vec::new();
        router.poll(0.15, &mut polled);
        router.poll(0.3, &mut polled);
        assert!(polled.is_empty(), "too soon: {polled:?}");
        let wobble = PointerSample {
            time: 0.4,
            ..sample(1, touch, Phase::Move, 104.0, 102.0)
        };
        let out = route_all(&mut router, &[wobble]);
        assert!(matches!(out[..], [Routed::Tool(ToolEvent::Move(_))]));
        router.poll(0.45, &mut polled);
        // A slow frame: the finger may have moved meanwhile, so no long press yet.
        router.poll(0.75, &mut polled);
        assert!(polled.is_empty(), "after a slow frame: {polled:?}");
        router.poll(0.8, &mut polled);
        assert_eq!(
            polled,
            vec![Routed::Tap(TapCommand::LongPress(pos2(100.0, 100.0)))]
        );
        polled.clear();
        router.take_touch(&mut polled);
        assert_eq!(polled, vec![Routed::Tool(ToolEvent::Cancel)]);
        polled.clear();
        router.poll(0.9, &mut polled);
        assert!(polled.is_empty(), "once per press: {polled:?}");
        let after = [
            PointerSample {
                time: 1.0,
                ..sample(1, touch, Phase::Move, 160.0, 100.0)
            },
            PointerSample {
                time: 1.1,
                ..sample(1, touch, Phase::Up, 160.0, 100.0)
            },
        ];
        let out = route_all(&mut router, &after);
        assert!(out.is_empty(), "the held finger does nothing more: {out:?}");
        // A finger that moves is a stroke, never a long press.
        let stroke = [
            sample(2, touch, Phase::Down, 100.0, 100.0),
            PointerSample {
                time: 0.1,
                ..sample(2, touch, Phase::Move, 140.0, 100.0)
            },
        ];
        route_all(&mut router, &stroke);
        router.poll(1.95, &mut polled);
        router.poll(2.0, &mut polled);
        assert!(polled.is_empty(), "{polled:?}");
    }

    #[test]
    fn finger_draws_until_a_pen_is_seen_then_orbits() {
        let mut router = InputRouter::default();
        let out = route_all(&mut router, &one_finger_drag(1));
        assert!(matches!(out[0], Routed::Tool(ToolEvent::Begin(_))));
        assert!(matches!(out[2], Routed::Tool(ToolEvent::End(_))));

        let pen = PointerKind::Pen;
        route_all(
            &mut router,
            &[
                sample(9, pen, Phase::Down, 10.0, 10.0),
                sample(9, pen, Phase::Up, 10.0, 10.0),
            ],
        );
        assert!(router.pen_seen());
        let out = route_all(&mut router, &one_finger_drag(2));
        assert!(out.iter().all(|r| !matches!(r, Routed::Tool(_))), "{out:?}");
        assert_eq!(
            out,
            vec![Routed::Nav(NavAction::Orbit(egui::vec2(50.0, 20.0)))]
        );
        // The finger only turned the view: the pen is still what draws, and hints say so.
        assert_eq!(router.device(), Some(pen));
    }

    #[test]
    fn the_device_is_the_last_pointer_seen() {
        let mut router = InputRouter::default();
        assert_eq!(router.device(), None);
        route_all(&mut router, &one_finger_drag(2));
        assert_eq!(router.device(), Some(PointerKind::Touch));
        let mouse = PointerKind::Mouse;
        route_all(&mut router, &[sample(1, mouse, Phase::Move, 5.0, 5.0)]);
        assert_eq!(router.device(), Some(mouse));
    }

    #[test]
    fn a_wide_touch_near_the_pen_is_a_palm_and_does_nothing() {
        let mut router = InputRouter::default();
        let (pen, touch) = (PointerKind::Pen, PointerKind::Touch);
        let at = |s: PointerSample, time: f64, contact: f32| PointerSample { time, contact, ..s };
        let hover = PointerSample {
            buttons: 0,
            ..sample(9, pen, Phase::Move, 300.0, 300.0)
        };
        route_all(&mut router, &[at(hover, 0.0, 0.0)]);
        assert_eq!(
            router.pen_hover(),
            Some(pos2(300.0, 300.0)),
            "the pen hovers"
        );
        // The palm lands while the pen hovers, rests and shifts while the pen draws.
        let out = route_all(
            &mut router,
            &[
                at(sample(1, touch, Phase::Down, 500.0, 500.0), 0.2, 45.0),
                at(sample(9, pen, Phase::Down, 300.0, 300.0), 0.3, 0.0),
                at(sample(1, touch, Phase::Move, 540.0, 520.0), 0.4, 45.0),
                at(sample(9, pen, Phase::Move, 340.0, 310.0), 0.5, 0.0),
                at(sample(9, pen, Phase::Up, 340.0, 310.0), 0.6, 0.0),
                at(sample(1, touch, Phase::Up, 540.0, 520.0), 0.9, 45.0),
            ],
        );
        assert_eq!(router.pen_hover(), None, "no hover while the pen is down");
        assert!(
            out.iter().all(|r| matches!(r, Routed::Tool(_))),
            "only the pen's stroke: {out:?}"
        );
        assert_eq!(out.len(), 3);
        // A finger near the pen still navigates; a wide touch long after the pen does too.
        for (id, time, contact) in [(2, 1.0, 8.0), (3, 5.0, 45.0)] {
            let out = route_all(
                &mut router,
                &[
                    at(sample(id, touch, Phase::Down, 100.0, 100.0), time, contact),
                    at(sample(id, touch, Phase::Move, 150.0, 120.0), time, contact),
                    at(sample(id, touch, Phase::Up, 150.0, 120.0), time, contact),
                ],
            );
            assert_eq!(
                out,
                vec![Routed::Nav(NavAction::Orbit(egui::vec2(50.0, 20.0)))],
                "touch {id}"
            );
        }
    }

    #[test]
    fn the_pen_erases_with_its_eraser_end_or_barrel_button() {
        let pen = |buttons| PointerSample {
            buttons,
            ..sample(9, PointerKind::Pen, Phase::Down, 0.0, 0.0)
        };
        assert!(!pen(buttons::PRIMARY).is_eraser());
        assert!(pen(buttons::ERASER).is_eraser());
        assert!(pen(buttons::PRIMARY | buttons::SECONDARY).is_eraser());
        let mouse = PointerSample {
            buttons: buttons::SECONDARY,
            ..sample(1, PointerKind::Mouse, Phase::Down, 0.0, 0.0)
        };
        assert!(!mouse.is_eraser(), "a mouse's right button orbits");
    }

    #[test]
    fn a_two_finger_tap_undoes_and_leaves_no_stroke() {
        let mut router = InputRouter::default();
        let t = PointerKind::Touch;
        let out = route_all(
            &mut router,
            &[
                sample(1, t, Phase::Down, 100.0, 100.0),
                sample(2, t, Phase::Down, 200.0, 100.0),
                sample(2, t, Phase::Up, 200.0, 100.0),
                sample(1, t, Phase::Up, 100.0, 100.0),
            ],
        );
        assert_eq!(
            out,
            vec![
                Routed::Tool(ToolEvent::Begin(sample(1, t, Phase::Down, 100.0, 100.0))),
                Routed::Tool(ToolEvent::Cancel),
                Routed::Hands(Hands::Down([
                    egui::pos2(100.0, 100.0),
                    egui::pos2(200.0, 100.0)
                ])),
                Routed::Tap(TapCommand::Undo),
            ]
        );
    }

    #[test]
    fn second_finger_cancels_the_stroke_and_navigates() {
        let mut router = InputRouter::default();
        let t = PointerKind::Touch;
        let out = route_all(
            &mut router,
            &[
                sample(1, t, Phase::Down, 100.0, 100.0),
                sample(1, t, Phase::Move, 102.0, 100.0),
                sample(2, t, Phase::Down, 200.0, 100.0),
                sample(1, t, Phase::Move, 60.0, 100.0),
                sample(2, t, Phase::Move, 240.0, 100.0),
                sample(2, t, Phase::Up, 240.0, 100.0),
                sample(1, t, Phase::Move, 10.0, 10.0),
                sample(1, t, Phase::Up, 10.0, 10.0),
            ],
        );
        assert!(out.contains(&Routed::Tool(ToolEvent::Cancel)));
        assert!(
            out.iter()
                .any(|r| matches!(r, Routed::Nav(NavAction::Zoom { .. })))
        );
        // The finger left behind after the pinch neither draws nor ends a stroke.
        let after_cancel = out
            .iter()
            .skip_while(|r| **r != Routed::Tool(ToolEvent::Cancel))
            .skip(1);
        assert!(
            after_cancel
                .into_iter()
                .all(|r| matches!(r, Routed::Nav(_) | Routed::Hands(Hands::Down(_))))
        );
    }

    #[test]
    fn two_fingers_the_tool_takes_go_to_it_until_one_lifts() {
        let t = PointerKind::Touch;
        let mut router = InputRouter::default();
        let mut out = route_all(
            &mut router,
            &[
                sample(1, t, Phase::Down, 100.0, 100.0),
                sample(2, t, Phase::Down, 200.0, 100.0),
            ],
        );
        let down = [egui::pos2(100.0, 100.0), egui::pos2(200.0, 100.0)];
        assert_eq!(out.last(), Some(&Routed::Hands(Hands::Down(down))));
        router.give_hands_to_tool();
        out = route_all(
            &mut router,
            &[
                sample(1, t, Phase::Move, 90.0, 100.0),
                sample(2, t, Phase::Move, 230.0, 100.0),
                sample(2, t, Phase::Up, 230.0, 100.0),
                sample(1, t, Phase::Move, 50.0, 50.0),
                sample(1, t, Phase::Up, 50.0, 50.0),
            ],
        );
        let moved = [egui::pos2(90.0, 100.0), egui::pos2(230.0, 100.0)];
        assert_eq!(
            out,
            vec![
                Routed::Hands(Hands::Move([egui::pos2(90.0, 100.0), down[1]])),
                Routed::Hands(Hands::Move(moved)),
                Routed::Hands(Hands::Up),
            ],
            "no camera motion, and the finger left behind does nothing"
        );
        // The next two fingers, not taken, navigate.
        out = route_all(
            &mut router,
            &[
                sample(3, t, Phase::Down, 100.0, 100.0),
                sample(4, t, Phase::Down, 200.0, 100.0),
                sample(3, t, Phase::Move, 60.0, 100.0),
                sample(4, t, Phase::Move, 240.0, 100.0),
            ],
        );
        assert!(
            out.iter()
                .any(|r| matches!(r, Routed::Nav(NavAction::Zoom { .. })))
        );
        assert!(
            !out.iter()
                .any(|r| matches!(r, Routed::Hands(Hands::Move(_))))
        );
    }

    #[test]
    fn pen_arriving_cancels_a_palm_stroke() {
        let mut router = InputRouter::default();
        let out = route_all(
            &mut router,
            &[
                sample(1, PointerKind::Touch, Phase::Down, 100.0, 100.0),
                sample(5, PointerKind::Pen, Phase::Down, 300.0, 300.0),
            ],
        );
        assert_eq!(
            out[0],
            Routed::Tool(ToolEvent::Begin(sample(
                1,
                PointerKind::Touch,
                Phase::Down,
                100.0,
                100.0
            )))
        );
        assert_eq!(out[1], Routed::Tool(ToolEvent::Cancel));
        assert!(matches!(out[2], Routed::Tool(ToolEvent::Begin(s)) if s.kind == PointerKind::Pen));
    }

    #[test]
    fn mouse_buttons_choose_tool_orbit_pan() {
        let mut router = InputRouter::default();
        let m = PointerKind::Mouse;
        let mut right = sample(1, m, Phase::Down, 0.0, 0.0);
        right.buttons = buttons::SECONDARY;
        let mut middle = sample(1, m, Phase::Down, 0.0, 0.0);
        middle.buttons = buttons::MIDDLE;
        let out = route_all(
            &mut router,
            &[
                right,
                sample(1, m, Phase::Move, 5.0, 0.0),
                sample(1, m, Phase::Up, 5.0, 0.0),
            ],
        );
        assert_eq!(
            out,
            vec![Routed::Nav(NavAction::Orbit(egui::vec2(5.0, 0.0)))]
        );
        let out = route_all(
            &mut router,
            &[
                middle,
                sample(1, m, Phase::Move, 0.0, 7.0),
                sample(1, m, Phase::Up, 0.0, 7.0),
            ],
        );
        assert_eq!(out, vec![Routed::Nav(NavAction::Pan(egui::vec2(0.0, 7.0)))]);
    }

    #[test]
    fn press_on_a_panel_is_not_a_stroke() {
        let mut router = InputRouter::default();
        let mut out = Vec::new();
        for s in one_finger_drag(3) {
            router.route(&s, false, &mut out);
        }
        assert!(out.is_empty());
    }
}
