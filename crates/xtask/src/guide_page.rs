//! The user guide as a page beside the app: `docs/guide.md` rendered to `dist/guide.html`,
//! which the app's help opens in a new tab, and which the service worker caches with the rest
//! of `dist/` so it opens offline too. One source for the guide: the repository shows the
//! Markdown, the page shows this.

use std::fs;
use std::path::Path;

use anyhow::Context as _;
use pulldown_cmark::{Options, Parser, html};

/// The guide's source, relative to the repository root.
const GUIDE_SOURCE: &str = "docs/guide.md";
/// Its page, relative to `dist/`.
pub const GUIDE_PAGE: &str = "guide.html";

/// Renders the guide into `dist`.
pub fn write_guide(root: &Path, dist: &Path) -> anyhow::Result<()> {
    let source = root.join(GUIDE_SOURCE);
    let markdown =
        fs::read_to_string(&source).with_context(|| format!("reading {}", source.display()))?;
    let page = dist.join(GUIDE_PAGE);
    fs::write(&page, guide_html(&markdown)).with_context(|| format!("writing {}", page.display()))
}

/// A whole HTML page for `markdown` (with GitHub's tables), readable on a phone and in the
/// app's dark colours.
pub fn guide_html(markdown: &str) -> String {
    let mut body = String::new();
    html::push_html(&mut body, Parser::new_ext(markdown, Options::ENABLE_TABLES));
    format!(
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>Sketchmesh user guide</title>\n<style>{STYLE}</style>\n</head>\n\
         <body>\n<main>\n{body}</main>\n</body>\n</html>\n"
    )
}

const STYLE: &str = "body{margin:0;background:#1b1b1b;color:#ddd;\
font:16px/1.55 system-ui,sans-serif}main{max-width:46em;margin:0 auto;padding:1em 1.2em 4em}\
h1,h2,h3{color:#fff;line-height:1.25}a{color:#8cf}code{background:#2c2c2c;padding:0 .25em;\
border-radius:3px}table{border-collapse:collapse;display:block;overflow-x:auto}\
th,td{border:1px solid #444;padding:.35em .6em;text-align:left;vertical-align:top}";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_guide_page_holds_its_headings_and_tables_as_html() {
        let page = guide_html("# Guide\n\n| key | tool |\n| --- | --- |\n| `S` | Sketch |\n");
        assert!(page.starts_with("<!doctype html>"), "{page}");
        assert!(page.contains("<h1>Guide</h1>"), "{page}");
        assert!(page.contains("<td><code>S</code></td>"), "{page}");
    }

    #[test]
    fn the_real_guide_renders_each_of_its_sections() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let markdown = fs::read_to_string(root.join(GUIDE_SOURCE)).unwrap();
        let page = guide_html(&markdown);
        for (heading, tag) in [("## ", "<h2>"), ("### ", "<h3>")] {
            let sections = markdown.lines().filter(|l| l.starts_with(heading)).count();
            assert!(
                sections >= 4,
                "the guide has {sections} `{heading}` sections"
            );
            assert_eq!(page.matches(tag).count(), sections, "{tag}");
        }
    }
}
