//! Session files: the log of ops that rebuilds a document, as versioned JSON.
//!
//! The contract is written up in `docs/session-format.md`. Ops are parsed one by one so that
//! every error names the op's index (zero-based position in `"ops"`); unknown ops and unknown
//! fields are errors, never silently ignored.

use serde_json::Value;

use super::session_error::SessionError;
use super::{Editor, Op, Progress, Replay};
use crate::model::MirrorPlane;

/// The `"format"` value of a session file.
pub const SESSION_FORMAT: &str = "sketchmesh-session";
/// The session format version this build reads and writes.
pub const SESSION_VERSION: u64 = 1;

/// A replayable list of ops.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Session {
    /// The ops, in the order they were applied.
    pub ops: Vec<Op>,
}

impl Session {
    /// The session as JSON: one op per line, so files diff well.
    pub fn to_json(&self) -> String {
        let ops: Vec<String> = self.ops.iter().map(Op::to_json).collect();
        let mut json = String::new();
        session_pieces_of(ops.iter().map(String::as_str), |piece| {
            json.push_str(piece.text());
        });
        json
    }

    /// Parses a session file.
    pub fn from_json(json: &str) -> Result<Session, SessionError> {
        let value: Value = serde_json::from_str(json)?;
        Session::from_value(value)
    }

    /// Parses a session from a JSON value.
    pub fn from_value(value: Value) -> Result<Session, SessionError> {
        let Value::Object(mut root) = value else {
            return Err(format_error("the top level is not a JSON object"));
        };
        match root.remove("format") {
            Some(Value::String(format)) if format == SESSION_FORMAT => {}
            Some(other) => {
                return Err(format_error(&format!(
                    "\"format\" is {other}, expected \"{SESSION_FORMAT}\""
                )));
            }
            None => return Err(format_error("the \"format\" field is missing")),
        }
        match root.remove("version") {
            Some(version) if version.as_u64() == Some(SESSION_VERSION) => {}
            Some(version) => {
                return Err(SessionError::Version {
                    found: version.to_string(),
                    expected: SESSION_VERSION,
                });
            }
            None => return Err(format_error("the \"version\" field is missing")),
        }
        let ops = match root.remove("ops") {
            Some(Value::Array(ops)) => ops,
            Some(_) => return Err(format_error("\"ops\" is not an array")),
            None => return Err(format_error("the \"ops\" field is missing")),
        };
        if let Some(key) = root.keys().next() {
            return Err(format_error(&format!(
                "unknown field \"{key}\" at the top level"
            )));
        }
        let ops = ops
            .into_iter()
            .enumerate()
            .map(|(index, value)| {
                parse_op(value).map_err(|message| SessionError::Op { index, message })
            })
            .collect::<Result<Vec<Op>, SessionError>>()?;
        Ok(Session { ops })
    }
}

impl Editor {
    /// The ops applied so far as a [`Session`].
    pub fn session(&self) -> Session {
        Session {
            ops: self.ops().to_vec(),
        }
    }

    /// The ops applied so far as session JSON ([`Session::to_json`]), from the ops' JSON
    /// kept since they were first written.
    pub fn session_json(&self) -> String {
        let mut json = String::new();
        self.session_pieces(|piece| json.push_str(piece.text()));
        json
    }

    /// Calls `put` with each piece of [`Editor::session_json`], in order: the page hands an
    /// autosave to JavaScript piece by piece and converts each op's text once, not at every
    /// change (a session that imported a scan carries its file, tens of megabytes).
    pub fn session_pieces(&self, put: impl FnMut(SessionPiece<'_>)) {
        session_pieces_of(self.ops_json(), put);
    }

    /// Applies every op of a session to a new editor; the first refused op is an error. The
    /// steps are those of a [`Replay`] the page runs over frames.
    pub fn replay(session: &Session) -> Result<Editor, SessionError> {
        let mut replay = Replay::new(session.ops.clone());
        while replay.step()? != Progress::Done {}
        Ok(replay.into_editor())
    }

    /// Parses session JSON and replays it.
    pub fn replay_json(json: &str) -> Result<Editor, SessionError> {
        Editor::replay(&Session::from_json(json)?)
    }
}

fn format_error(message: &str) -> SessionError {
    SessionError::Format(message.to_owned())
}

/// A piece of a session file's text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SessionPiece<'a> {
    /// The file's text around its ops.
    Text(&'a str),
    /// The JSON of the op at this index of the session, on a line of its own.
    Op(usize, &'a str),
}

impl<'a> SessionPiece<'a> {
    /// The piece's text.
    pub fn text(self) -> &'a str {
        match self {
            SessionPiece::Text(text) | SessionPiece::Op(_, text) => text,
        }
    }
}

/// Calls `put` with each piece of a session file around ops already written as JSON, one
/// per line.
fn session_pieces_of<'a>(
    ops: impl Iterator<Item = &'a str>,
    mut put: impl FnMut(SessionPiece<'_>),
) {
    let head = format!(r#"{{"format":"{SESSION_FORMAT}","version":{SESSION_VERSION},"ops":["#);
    put(SessionPiece::Text(&head));
    let mut any = false;
    for (index, op) in ops.enumerate() {
        put(SessionPiece::Text(if any { ",\n" } else { "\n" }));
        put(SessionPiece::Op(index, op));
        any = true;
    }
    if any {
        put(SessionPiece::Text("\n"));
    }
    put(SessionPiece::Text("]}\n"));
}

/// Parses one op, with an error message fit to follow "op N: ".
fn parse_op(value: Value) -> Result<Op, String> {
    let Value::Object(object) = value else {
        return Err(format!(
            "expected an object such as {{\"op\": \"undo\"}}, found {value}"
        ));
    };
    let mut object = object;
    let mirror = match object.remove("mirror") {
        Some(plane) => Some(
            serde_json::from_value::<MirrorPlane>(plane)
                .map_err(|error| format!("\"mirror\" must be a plane [nx, ny, nz, d]: {error}"))?,
        ),
        None => None,
    };
    let op = parse_plain_op(object)?;
    let Some(plane) = mirror else {
        return Ok(op);
    };
    match op.clone().mirrored(plane) {
        Op::Mirrored(mirrored) => Ok(Op::Mirrored(mirrored)),
        _ => Err(format!("a \"{}\" op cannot carry \"mirror\"", op.name())),
    }
}

/// Parses one op without its `"mirror"` field.
fn parse_plain_op(object: serde_json::Map<String, Value>) -> Result<Op, String> {
    let name = match object.get("op") {
        Some(Value::String(name)) => name.clone(),
        Some(other) => return Err(format!("\"op\" must be a string, found {other}")),
        None => return Err(String::from("the \"op\" field is missing")),
    };
    if !Op::NAMES.contains(&name.as_str()) {
        return Err(format!(
            "unknown op \"{name}\" (known ops: {})",
            Op::NAMES.join(", ")
        ));
    }
    let keys: Vec<String> = object.keys().filter(|key| *key != "op").cloned().collect();
    let op: Op = serde_json::from_value(Value::Object(object))
        .map_err(|error| format!("in a \"{name}\" op: {error}"))?;
    // serde ignores extra fields of unit variants in internally tagged enums, and of the
    // flattened settings of `optimize` (which it writes in full); refuse them.
    let written = serde_json::to_value(&op).unwrap_or_default();
    let is_unknown = |key: &&String| match &op {
        Op::Optimize(_) => written.get(key.as_str()).is_none(),
        _ => op.is_bare(),
    };
    match keys.iter().find(is_unknown) {
        Some(key) => Err(format!("unknown field \"{key}\" in a \"{name}\" op")),
        None => Ok(op),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::document::{CommandError, StrokeInput};
    use glam::DVec3;

    /// The session example in docs/session-format.md (its last JSON block), so the docs
    /// cannot drift from the implementation.
    fn doc_example() -> String {
        let doc = include_str!("../../../../docs/session-format.md");
        let start = doc.rfind("```json\n").expect("the doc has a JSON example") + "```json\n".len();
        let length = doc[start..]
            .find("```")
            .expect("the example block is closed");
        doc[start..start + length].to_owned()
    }

    fn stroke_op(camera: Camera, stroke: Vec<[f64; 3]>) -> Op {
        Op::Stroke(StrokeInput {
            viewport: [800.0, 600.0],
            camera,
            stroke,
        })
    }

    #[test]
    fn doc_example_parses_replays_and_prints_back() {
        let example = doc_example();
        let session = Session::from_json(&example).unwrap();
        assert_eq!(session.ops.len(), 4);
        assert_eq!(session.ops[2], Op::Undo);
        assert_eq!(session.to_json(), example);
        let editor = Editor::replay(&session).unwrap();
        assert_eq!(editor.document().sketches.len(), 2);
        assert_eq!(editor.session_json(), example);
        // Its pieces, as the page's autosave joins them: the same text, each op once and in
        // order.
        let (mut joined, mut ops) = (String::new(), Vec::new());
        editor.session_pieces(|piece| {
            joined.push_str(piece.text());
            if let SessionPiece::Op(index, json) = piece {
                ops.push((index, json.to_owned()));
            }
        });
        assert_eq!(joined, example);
        let written: Vec<(usize, String)> =
            session.ops.iter().map(Op::to_json).enumerate().collect();
        assert_eq!(ops, written);
        // The second stroke was drawn looking down −X, so it lies in the plane x = 0.
        for point in &editor.document().sketches[1].points {
            assert!(point.x.abs() < 1e-12);
        }
    }

    /// Every op in [`Op::NAMES`] has a section of its own in docs/session-format.md: a
    /// heading of its "Ops" part that names it in backticks.
    #[test]
    fn every_op_is_documented() {
        let doc = include_str!("../../../../docs/session-format.md");
        let start = doc.find("\n## Ops\n").expect("the doc has an Ops part") + 1;
        let end = doc[start..]
            .find("\n## ")
            .map_or(doc.len(), |end| start + end);
        let headings: Vec<&str> = doc[start..end]
            .lines()
            .filter(|line| line.starts_with("### "))
            .collect();
        let missing: Vec<&str> = (Op::NAMES.iter().copied())
            .filter(|name| {
                let named = format!("`{name}`");
                !headings.iter().any(|heading| heading.contains(&named))
            })
            .collect();
        assert!(
            missing.is_empty(),
            "docs/session-format.md documents no op {missing:?}: give each a `### `name`` \
             section under \"## Ops\" that says its fields and what it does"
        );
    }

    #[test]
    fn empty_session() {
        let json = Editor::new().session_json();
        assert_eq!(
            json,
            "{\"format\":\"sketchmesh-session\",\"version\":1,\"ops\":[]}\n"
        );
        assert!(Editor::replay_json(&json).unwrap().document().is_empty());
    }

    #[test]
    fn replay_is_exact_for_any_float() {
        // Camera and pointer values as the app produces them: f32-derived coordinates and
        // trigonometric noise, which need 17 significant digits to round-trip.
        let angle = 0.7f64;
        let camera = Camera {
            eye: DVec3::new(
                4.0 * angle.sin(),
                1.234_567_890_123_456_7,
                4.0 * angle.cos(),
            ),
            target: DVec3::new(1e-17, -0.1, 0.3),
            up: DVec3::new(std::f64::consts::PI.sin(), 1.0, 0.0),
            fov_y_deg: 45.0,
            ortho_height: None,
        };
        let stroke: Vec<[f64; 3]> = (0..40)
            .map(|k| {
                let t = k as f64 * 0.37;
                [
                    f64::from(300.0f32 + 123.456f32 * (t as f32).cos()),
                    f64::from(250.0f32 + 77.7f32 * (t as f32).sin()),
                    f64::from(0.3f32 + 0.01f32 * k as f32),
                ]
            })
            .collect();
        let mut editor = Editor::new();
        editor.apply(stroke_op(camera, stroke.clone())).unwrap();
        editor.apply(stroke_op(Camera::default(), stroke)).unwrap();
        editor.undo().unwrap();
        let json = editor.session_json();
        let replayed = Editor::replay_json(&json).unwrap();
        // Needs serde_json's `float_roundtrip` feature: its default parser may be 1 ulp off.
        assert!(
            replayed.session() == editor.session(),
            "the JSON must round-trip f64 exactly"
        );
        assert_eq!(replayed.document(), editor.document());
        assert_eq!(replayed.can_redo(), editor.can_redo());
        assert_eq!(replayed.session_json(), json);
    }

    #[test]
    fn errors_name_the_op_index() {
        let undo = r#"{"op":"undo"}"#;
        let cases = [
            (r#"{"op":"frobnicate"}"#, "op 1: unknown op \"frobnicate\""),
            (
                r#"{"op":"undo","extra":1}"#,
                "op 1: unknown field \"extra\" in a \"undo\" op",
            ),
            (
                r#"{"op":"stroke","viewport":[8,6],"camera":{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":45},"stroke":[],"speed":2}"#,
                "op 1: in a \"stroke\" op: unknown field `speed`",
            ),
            (
                r#"{"op":"stroke","viewport":[8,6],"camera":{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":45,"zoom":1},"stroke":[]}"#,
                "op 1: in a \"stroke\" op: unknown field `zoom`",
            ),
            (r#"{"undo":true}"#, "op 1: the \"op\" field is missing"),
            ("3", "op 1: expected an object"),
        ];
        for (op, expected) in cases {
            let json =
                format!(r#"{{"format":"sketchmesh-session","version":1,"ops":[{undo},{op}]}}"#);
            let error = Session::from_json(&json).unwrap_err();
            assert!(
                matches!(error, SessionError::Op { index: 1, .. }),
                "{error:?}"
            );
            let message = error.to_string();
            assert!(message.starts_with(expected), "{message}");
        }
    }

    #[test]
    fn format_version_and_command_errors() {
        let wrong_format = r#"{"format":"other","version":1,"ops":[]}"#;
        assert!(matches!(
            Session::from_json(wrong_format),
            Err(SessionError::Format(_))
        ));
        let wrong_version = r#"{"format":"sketchmesh-session","version":2,"ops":[]}"#;
        let error = Session::from_json(wrong_version).unwrap_err();
        assert_eq!(
            error.to_string(),
            "The session has version 2, but this Sketchmesh reads version 1."
        );
        let optimize = |op: &str| {
            Session::from_json(&format!(
                r#"{{"format":"sketchmesh-session","version":1,"ops":[{op}]}}"#
            ))
        };
        let short = optimize(r#"{"op":"optimize","model":0,"mode":"smooth","scale":0.3}"#);
        let Op::Optimize(input) = &short.unwrap().ops[0] else {
            panic!("not an optimize op")
        };
        assert_eq!(
            (input.settings.scale, input.settings.tangent_plane),
            (0.3, false)
        );
        let typo = optimize(r#"{"op":"optimize","model":0,"scael":0.3}"#).unwrap_err();
        assert!(
            typo.to_string().contains("unknown field \"scael\""),
            "{typo}"
        );
        let extra = r#"{"format":"sketchmesh-session","version":1,"ops":[],"notes":""}"#;
        assert_eq!(
            Session::from_json(extra).unwrap_err().to_string(),
            "This is not a Sketchmesh session: unknown field \"notes\" at the top level."
        );
        assert!(matches!(
            Session::from_json("{"),
            Err(SessionError::Json(_))
        ));
        assert!(matches!(
            Session::from_json("[]"),
            Err(SessionError::Format(_))
        ));
        let refused = r#"{"format":"sketchmesh-session","version":1,"ops":[{"op":"undo"}]}"#;
        let error = Editor::replay_json(refused).unwrap_err();
        assert!(matches!(
            error,
            SessionError::Command {
                index: 0,
                source: CommandError::NothingToUndo
            }
        ));
        assert_eq!(error.to_string(), "op 0: Nothing to undo.");
    }
}
