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

#[cfg(test)]
mod tests {
    /// The signs the toolbar writes as text (its menus') are in the fonts.
    #[test]
    fn the_toolbar_signs_are_in_the_fonts() {
        let ctx = egui::Context::default();
        ctx.set_fonts(super::definitions());
        // A pass loads the fonts; its texture deltas are for a renderer, and there is none.
        let mut output = ctx.run_ui(egui::RawInput::default(), |_| {});
        output.textures_delta.clear();
        let font = egui::FontId::proportional(14.0);
        for sign in crate::panels::toolbar::SIGNS {
            let drawn = ctx.fonts_mut(|fonts| fonts.has_glyphs(&font, sign));
            assert!(drawn, "the sign {sign} is not in the fonts");
        }
    }
}
