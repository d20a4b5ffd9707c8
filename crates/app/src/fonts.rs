//! The one typeface the interface draws with.
//!
//! egui's bundled set adds a monospace face (Hack, 148 kB of the gzipped wasm) and two emoji
//! faces (about 400 kB) beside Ubuntu Light. The page shows code only as key names in the
//! help panel, which read as well in Ubuntu Light, and needs no emoji: the tools' icons are
//! drawn (`crate::tools::icon`), so they look the same on every device and at any size.

use std::sync::Arc;

use egui::{FontData, FontDefinitions, FontFamily, FontTweak};

const TEXT: &str = "Ubuntu-Light";
/// egui's few private-use icons (`egui::special_emojis`), a last resort for any family.
const ICONS: &str = "egui-icons";

/// Ubuntu Light for both families, egui's icons after it.
pub fn definitions() -> FontDefinitions {
    let mut fonts = FontDefinitions::empty();
    fonts.font_data.insert(
        TEXT.to_owned(),
        Arc::new(FontData::from_static(epaint_default_fonts::UBUNTU_LIGHT)),
    );
    fonts.font_data.insert(
        ICONS.to_owned(),
        Arc::new(
            FontData::from_static(epaint_default_fonts::EGUI_ICONS).tweak(FontTweak {
                scale: 0.9,
                ..FontTweak::default()
            }),
        ),
    );
    for family in [FontFamily::Proportional, FontFamily::Monospace] {
        fonts
            .families
            .insert(family, vec![TEXT.to_owned(), ICONS.to_owned()]);
    }
    fonts
}
