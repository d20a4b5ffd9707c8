//! The examples the page offers (`web/examples/`, listed in `index.json`): each is a session
//! the editor replays without a refusal, in which every op changes the document (a step that
//! changed nothing would play as a pause), with a caption per op and its thumbnail beside it.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a test failure.

use std::path::PathBuf;

use serde_json::Value;
use sketchmesh_core::document::{Editor, Session};

fn examples_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../web/examples")
}

#[test]
fn every_example_replays_and_each_of_its_ops_changes_the_document() {
    let dir = examples_dir();
    let index: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("index.json")).unwrap()).unwrap();
    let examples = index["examples"].as_array().unwrap();
    assert!(examples.len() >= 3, "at least three examples");
    let mut tools_used = Vec::new();
    for example in examples {
        let name = example["name"].as_str().unwrap();
        for field in ["title", "description"] {
            let text = example[field].as_str().unwrap_or_default();
            assert!(!text.is_empty(), "{name} has a {field}");
        }
        let thumbnail = dir.join(example["thumbnail"].as_str().unwrap());
        let png = std::fs::read(&thumbnail).unwrap();
        assert_eq!(&png[1..4], b"PNG", "{name}'s thumbnail is a PNG");
        let text = std::fs::read_to_string(dir.join(example["session"].as_str().unwrap())).unwrap();
        assert!(
            text.len() < 120_000,
            "{name} is small: {} bytes",
            text.len()
        );
        let session = Session::from_json(&text).unwrap();
        let captions = example["captions"].as_array().unwrap();
        assert_eq!(
            captions.len(),
            session.ops.len(),
            "{name}: a caption per op"
        );
        let mut editor = Editor::new();
        for (k, op) in session.ops.iter().enumerate() {
            let before = editor.document().clone();
            let kind = op.name();
            editor
                .apply(op.clone())
                .unwrap_or_else(|e| panic!("{name}: op {k} ({kind}) is refused: {e}"));
            assert_ne!(
                editor.document(),
                &before,
                "{name}: op {k} ({kind}) changes nothing"
            );
            tools_used.push(kind);
        }
        let replayed = Editor::replay(&session).unwrap();
        assert_eq!(
            replayed.document(),
            editor.document(),
            "{name}: replay is the same"
        );
    }
    // What the examples are there to show.
    for kind in [
        "create",
        "extrude",
        "pull",
        "curve_deform",
        "keyframe",
        "import",
        "curve_handle",
        "handle_edit",
        "region_edit",
    ] {
        assert!(tools_used.contains(&kind), "no example uses {kind}");
    }
}
