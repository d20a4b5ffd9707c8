//! Native input: egui's mouse events as [`PointerSample`]s.
//!
//! Native builds are desktop builds, so only the mouse matters here; pens and touch come
//! through [`super::web_pointer`] in the browser.

use super::{Phase, PointerKind, PointerSample, buttons};

/// Turns egui events into samples, keeping the held-button mask between frames.
#[derive(Debug, Default)]
pub struct EguiPointer {
    held: u16,
}

impl EguiPointer {
    /// Appends the samples for this frame's events.
    pub fn collect(&mut self, input: &egui::InputState, out: &mut Vec<PointerSample>) {
        for event in &input.events {
            let (pos, phase) = match event {
                egui::Event::PointerMoved(pos) => (*pos, Phase::Move),
                egui::Event::PointerButton {
                    pos,
                    button,
                    pressed,
                    ..
                } => {
                    let bit = match button {
                        egui::PointerButton::Primary => buttons::PRIMARY,
                        egui::PointerButton::Secondary => buttons::SECONDARY,
                        egui::PointerButton::Middle => buttons::MIDDLE,
                        _ => continue,
                    };
                    if *pressed {
                        self.held |= bit;
                        (*pos, Phase::Down)
                    } else {
                        self.held &= !bit;
                        (*pos, Phase::Up)
                    }
                }
                _ => continue,
            };
            out.push(PointerSample {
                id: 0,
                phase,
                pos_in_screen: pos,
                pressure: 0.5,
                kind: PointerKind::Mouse,
                buttons: self.held,
                contact: 0.0,
                time: input.time,
            });
        }
    }
}
