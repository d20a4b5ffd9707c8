//! Over-sketch matching scenarios: a table of silhouettes and strokes with the handle each
//! must produce, plus the handle-to-stroke mapping on a matched handle.

use glam::DVec2;
use sketchmesh_core::oversketch::{
    Match, MatchParams, handle_points, map_to_stroke, match_stroke, simplify_stroke,
};

/// Points on a circle of `radius` about `center` from `from` to `to` degrees (screen
/// coordinates, so positive angles turn downwards), `n` segments.
fn arc(center: DVec2, radius: f64, from: f64, to: f64, n: usize) -> Vec<DVec2> {
    (0..=n)
        .map(|k| {
            let t = (from + (to - from) * k as f64 / n as f64).to_radians();
            center + radius * DVec2::from_angle(t)
        })
        .collect()
}

/// A straight polyline from `a` to `b` with `n` segments.
fn line(a: DVec2, b: DVec2, n: usize) -> Vec<DVec2> {
    (0..=n).map(|k| a.lerp(b, k as f64 / n as f64)).collect()
}

/// An ear: the upper half of a circle (pointing up the screen), dense as a traced pixel
/// path, rounded to whole pixels.
fn pixel_ear(center: DVec2, radius: f64) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::new();
    for p in arc(center, radius, 180.0, 360.0, 400) {
        let p = p.round();
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    out
}

/// An outline with two ears on one polyline: flat, ear, flat, ear, flat.
fn two_ear_outline() -> Vec<DVec2> {
    let mut out = line(DVec2::new(0.0, 300.0), DVec2::new(140.0, 300.0), 35);
    out.extend(
        arc(DVec2::new(200.0, 300.0), 60.0, 180.0, 360.0, 60)
            .into_iter()
            .skip(1),
    );
    out.extend(
        line(DVec2::new(260.0, 300.0), DVec2::new(440.0, 300.0), 45)
            .into_iter()
            .skip(1),
    );
    out.extend(
        arc(DVec2::new(500.0, 300.0), 60.0, 180.0, 360.0, 60)
            .into_iter()
            .skip(1),
    );
    out.extend(
        line(DVec2::new(560.0, 300.0), DVec2::new(700.0, 300.0), 35)
            .into_iter()
            .skip(1),
    );
    out
}

fn circle() -> Vec<DVec2> {
    // Closed, starting on the right, so a right-side handle crosses the seam.
    arc(DVec2::new(400.0, 300.0), 150.0, 0.0, 360.0, 400)
}

/// A hand-drawn-like version of `points`: densely resampled with a little wobble.
fn drawn(points: &[DVec2]) -> Vec<DVec2> {
    let mut out = Vec::new();
    for w in points.windows(2) {
        for k in 0..4 {
            let p = w[0].lerp(w[1], k as f64 / 4.0);
            let i = out.len() as f64;
            out.push(p + 0.4 * DVec2::new((0.7 * i).sin(), (1.3 * i).cos()));
        }
    }
    out.extend(points.last());
    out
}

enum Expect {
    Nothing,
    Pick {
        /// `None` when either silhouette is fine (a tie).
        silhouette: Option<usize>,
        confident: bool,
        /// `(start, end)` fractional indices the handle must have, within `tolerance`.
        ends: Option<(f64, f64, f64)>,
    },
}

struct Case {
    name: &'static str,
    silhouettes: Vec<Vec<DVec2>>,
    stroke: Vec<DVec2>,
    params: MatchParams,
    expect: Expect,
}

fn cases() -> Vec<Case> {
    let default = MatchParams::default();
    let ears = vec![
        pixel_ear(DVec2::new(200.0, 300.0), 60.0),
        pixel_ear(DVec2::new(500.0, 300.0), 60.0),
    ];
    // The bump-shaped stroke, and a straight silhouette 10 px below its ends against the
    // same bump 45 px below (its nearest points are 18.6 px from the stroke's ends).
    let bump = arc(DVec2::new(340.0, 200.0), 40.0, 180.0, 360.0, 40);
    let straight_and_bump = vec![
        line(DVec2::new(200.0, 210.0), DVec2::new(480.0, 210.0), 100),
        arc(DVec2::new(340.0, 245.0), 40.0, 180.0, 360.0, 60),
    ];
    let parallel = vec![
        line(DVec2::new(100.0, 200.0), DVec2::new(500.0, 200.0), 200),
        line(DVec2::new(100.0, 240.0), DVec2::new(500.0, 240.0), 200),
    ];
    let pick = |silhouette, confident| Expect::Pick {
        silhouette: Some(silhouette),
        confident,
        ends: None,
    };
    // The circle has 400 segments of 0.9°; -30° is index 366.67, +30° is 33.33 past the seam.
    let (right_start, right_end) = (400.0 - 400.0 / 12.0, 400.0 + 400.0 / 12.0);
    vec![
        Case {
            name: "stroke over the right ear picks it",
            silhouettes: ears.clone(),
            stroke: drawn(&arc(DVec2::new(500.0, 300.0), 72.0, 200.0, 340.0, 30)),
            params: default,
            expect: pick(1, true),
        },
        Case {
            name: "stroke over the left ear picks it",
            silhouettes: ears.clone(),
            stroke: drawn(&arc(DVec2::new(200.0, 300.0), 75.0, 190.0, 300.0, 30)),
            params: default,
            expect: pick(0, true),
        },
        Case {
            name: "right ear of a single outline",
            silhouettes: vec![two_ear_outline()],
            stroke: drawn(&arc(DVec2::new(500.0, 300.0), 80.0, 190.0, 350.0, 30)),
            params: default,
            // Ear 2 spans indices 140..200 of the outline: 190° and 350° are 10° in.
            expect: Expect::Pick {
                silhouette: Some(0),
                confident: true,
                ends: Some((140.0 + 10.0 / 3.0, 200.0 - 10.0 / 3.0, 2.0)),
            },
        },
        Case {
            name: "circle's right side, across the seam",
            silhouettes: vec![circle()],
            stroke: drawn(&arc(DVec2::new(400.0, 300.0), 165.0, -30.0, 30.0, 30)),
            params: default,
            expect: Expect::Pick {
                silhouette: Some(0),
                confident: true,
                ends: Some((right_start, right_end, 1.5)),
            },
        },
        Case {
            name: "circle's right side drawn the other way",
            silhouettes: vec![circle()],
            stroke: drawn(&arc(DVec2::new(400.0, 300.0), 165.0, 30.0, -30.0, 30)),
            params: default,
            expect: Expect::Pick {
                silhouette: Some(0),
                confident: true,
                ends: Some((right_end, right_start, 1.5)),
            },
        },
        Case {
            name: "a bump picks the farther bump over the nearer line",
            silhouettes: straight_and_bump.clone(),
            stroke: drawn(&bump),
            params: default,
            expect: pick(1, true),
        },
        Case {
            name: "without the shape term the nearer line wins",
            silhouettes: straight_and_bump,
            stroke: drawn(&bump),
            params: MatchParams {
                weight_shape: 0.0,
                ..default
            },
            expect: pick(0, true),
        },
        Case {
            name: "stroke near one of two parallel lines",
            silhouettes: parallel.clone(),
            stroke: drawn(&line(
                DVec2::new(200.0, 205.0),
                DVec2::new(400.0, 205.0),
                20,
            )),
            params: default,
            expect: pick(0, true),
        },
        Case {
            name: "stroke midway between two parallel lines is not confident",
            silhouettes: parallel.clone(),
            stroke: drawn(&line(
                DVec2::new(200.0, 220.0),
                DVec2::new(400.0, 220.0),
                20,
            )),
            params: default,
            expect: Expect::Pick {
                silhouette: None,
                confident: false,
                ends: None,
            },
        },
        Case {
            name: "stroke 60 px from a line is not confident",
            silhouettes: vec![parallel[0].clone()],
            stroke: drawn(&line(
                DVec2::new(200.0, 140.0),
                DVec2::new(400.0, 140.0),
                20,
            )),
            params: default,
            expect: pick(0, false),
        },
        Case {
            name: "stroke far from every silhouette matches nothing",
            silhouettes: ears,
            stroke: drawn(&line(
                DVec2::new(100.0, 600.0),
                DVec2::new(300.0, 620.0),
                20,
            )),
            params: default,
            expect: Expect::Nothing,
        },
    ]
}

/// Distance between fractional indices, modulo `period` when the silhouette is closed.
fn index_gap(a: f64, b: f64, period: Option<f64>) -> f64 {
    match period {
        Some(p) => {
            let d = (a - b).rem_euclid(p);
            d.min(p - d)
        }
        None => (a - b).abs(),
    }
}

#[test]
fn scripted_strokes_pick_the_expected_handle() {
    for case in cases() {
        let silhouettes: Vec<&[DVec2]> = case.silhouettes.iter().map(Vec::as_slice).collect();
        let found = match_stroke(&case.stroke, &silhouettes, &case.params);
        match (case.expect, found) {
            (Expect::Nothing, None) => {}
            (
                Expect::Pick {
                    silhouette,
                    confident,
                    ends,
                },
                Some(m),
            ) => {
                if let Some(silhouette) = silhouette {
                    assert_eq!(m.silhouette, silhouette, "{}: {m:?}", case.name);
                }
                assert_eq!(m.confident, confident, "{}: {m:?}", case.name);
                assert!(m.score > 0.0 && m.score <= 1.0);
                if let Some((start, end, tolerance)) = ends {
                    let points = &case.silhouettes[m.silhouette];
                    let period = (points[0] == points[points.len() - 1])
                        .then_some((points.len() - 1) as f64);
                    let gaps = (
                        index_gap(m.start, start, period),
                        index_gap(m.end, end, period),
                    );
                    assert!(
                        gaps.0 <= tolerance && gaps.1 <= tolerance,
                        "{}: {m:?}, gaps {gaps:?}",
                        case.name
                    );
                    // The handle runs the stroke's way.
                    assert_eq!(m.start < m.end, start < end, "{}", case.name);
                }
            }
            (_, found) => panic!("{}: unexpected {found:?}", case.name),
        }
    }
}

#[test]
fn matched_handle_maps_onto_the_stroke_in_order() {
    let silhouette = circle();
    let stroke = drawn(&arc(DVec2::new(400.0, 300.0), 180.0, -40.0, 40.0, 40));
    let Some(Match { start, end, .. }) =
        match_stroke(&stroke, &[&silhouette], &MatchParams::default())
    else {
        panic!("no match");
    };
    let handle: Vec<DVec2> = handle_points(&silhouette, start, end)
        .into_iter()
        .map(|(_, p)| p)
        .collect();
    assert!(handle.len() > 80, "{} handle points", handle.len());
    let targets = map_to_stroke(&handle, &stroke);
    assert_eq!(targets[0], stroke[0]);
    assert_eq!(targets[targets.len() - 1], stroke[stroke.len() - 1]);
    // Along the stroke, which sweeps -40°..40° about the centre, targets keep their order.
    let angles: Vec<f64> = targets
        .iter()
        .map(|t| {
            let d = *t - DVec2::new(400.0, 300.0);
            d.y.atan2(d.x)
        })
        .collect();
    assert!(angles.windows(2).all(|w| w[1] > w[0]));
}

#[test]
fn simplified_stroke_is_what_matching_compares() {
    // Simplification keeps the stroke's ends, which matching uses for proximity.
    let stroke = drawn(&arc(DVec2::new(0.0, 0.0), 100.0, 0.0, 90.0, 30));
    let simple = simplify_stroke(&stroke);
    assert_eq!(simple[0], stroke[0]);
    assert_eq!(simple[simple.len() - 1], stroke[stroke.len() - 1]);
    assert!(simple.len() < stroke.len() / 3);
}
