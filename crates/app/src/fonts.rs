//! The one typeface the interface draws with, and the tools' icons.
//!
//! egui's bundled set adds a monospace face (Hack, 148 kB of the gzipped wasm) and two emoji
//! faces (about 400 kB) beside Ubuntu Light. The page shows code only as key names in the
//! help panel, which read as well in Ubuntu Light, and of the emoji it needs only the
//! toolbar's icons, a 5 kB subset of Noto Emoji (`assets/tool-icons.txt`): the download stays
//! inside its budget, and the icons look the same on every device (the browser's own emoji
//! would be colour pictures on one tablet and line drawings on the next).

use std::sync::Arc;

use egui::{FontData, FontDefinitions, FontFamily, FontTweak};

const TEXT: &str = "Ubuntu-Light";
/// The tools' icons (`Mode::icon`), drawn with the text.
const TOOL_ICONS: &str = "tool-icons";
/// egui's few private-use icons (`egui::special_emojis`), a last resort for any family.
const ICONS: &str = "egui-icons";

/// Ubuntu Light for both families, the tool icons and egui's icons after it.
pub fn definitions() -> FontDefinitions {
    let mut fonts = FontDefinitions::empty();
    fonts.font_data.insert(
        TEXT.to_owned(),
        Arc::new(FontData::from_static(epaint_default_fonts::UBUNTU_LIGHT)),
    );
    fonts.font_data.insert(
        TOOL_ICONS.to_owned(),
        Arc::new(FontData::from_static(include_bytes!(
            "../assets/tool-icons.ttf"
        ))),
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
        fonts.families.insert(
            family,
            vec![TEXT.to_owned(), TOOL_ICONS.to_owned(), ICONS.to_owned()],
        );
    }
    fonts
}

#[cfg(test)]
mod tests {
    use crate::tools::Mode;

    #[test]
    fn every_tool_icon_is_in_the_fonts() {
        let ctx = egui::Context::default();
        ctx.set_fonts(super::definitions());
        // A pass loads the fonts; its texture deltas are for a renderer, and there is none.
        let mut output = ctx.run_ui(egui::RawInput::default(), |_| {});
        output.textures_delta.clear();
        let font = egui::FontId::proportional(14.0);
        let icons = Mode::ALL.map(|mode| (format!("{mode:?}"), mode.icon()));
        let (undo, redo) = crate::panels::toolbar::UNDO_REDO_ICONS;
        let arrows = [(String::from("undo"), undo), (String::from("redo"), redo)];
        for (what, icon) in icons.into_iter().chain(arrows) {
            let drawn = ctx.fonts_mut(|fonts| fonts.has_glyphs(&font, icon));
            assert!(drawn, "the {what} icon {icon} is not in the fonts");
        }
    }
}
