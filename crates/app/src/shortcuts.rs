//! The keyboard shortcuts: what the keys pressed this frame ask for, in the order the app
//! handles them.

use egui::{Key, KeyboardShortcut, Modifiers};

use crate::command::Command;
use crate::tools::{Mode, ToolSet};

/// Consumes this frame's shortcuts in `ctx` (none while a text field has the keyboard):
/// the app's own, and those the tools take (see [`ToolSet::keys`]).
pub fn read(ctx: &egui::Context, tools: &ToolSet) -> Vec<Command> {
    let mut commands = Vec::new();
    if ctx.egui_wants_keyboard_input() {
        return commands;
    }
    let shortcut = |modifiers, key| KeyboardShortcut::new(modifiers, key);
    let any = |shortcuts: &[(Modifiers, Key)]| {
        ctx.input_mut(|i| {
            (shortcuts.iter())
                .any(|&(modifiers, key)| i.consume_shortcut(&shortcut(modifiers, key)))
        })
    };
    let command_shift = Modifiers::COMMAND | Modifiers::SHIFT;
    let app = [
        (
            &[(command_shift, Key::Z), (Modifiers::COMMAND, Key::Y)][..],
            Command::Redo,
        ),
        (&[(Modifiers::COMMAND, Key::Z)], Command::Undo),
        (&[(Modifiers::COMMAND, Key::O)], Command::Import),
        (&[(command_shift, Key::S)], Command::SaveSession),
        (
            &[(Modifiers::COMMAND, Key::S), (Modifiers::COMMAND, Key::E)],
            Command::Export,
        ),
        (&[(Modifiers::NONE, Key::Escape)], Command::Stop),
    ];
    for (keys, command) in app {
        if any(keys) {
            commands.push(command);
        }
    }
    let pressed = |key| any(&[(Modifiers::NONE, key)]);
    for (mode, key) in tools.keys() {
        if pressed(key) {
            commands.push(Command::ToolKey(mode, key));
        }
    }
    if pressed(Key::F) {
        commands.push(Command::FrameAll);
    }
    if pressed(Key::R) || pressed(Key::Home) {
        commands.push(Command::ResetView);
    }
    for mode in Mode::ALL {
        if pressed(mode.key()) {
            commands.push(Command::Mode(mode));
        }
    }
    for (key, command) in [
        (Key::W, Command::ToggleWireframe),
        (Key::G, Command::ToggleGrid),
        (Key::X, Command::ToggleSymmetry),
    ] {
        if pressed(key) {
            commands.push(command);
        }
    }
    if pressed(Key::H) || pressed(Key::F1) {
        commands.push(Command::ToggleHelp);
    }
    commands
}
