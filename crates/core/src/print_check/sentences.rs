//! The print check in plain words, as the app's export panel and `sketchmesh check` say it.

use super::PrintCheck;
use crate::unit::Unit;

impl PrintCheck {
    /// One sentence per finding, in order: closed and manifold, self-intersections, the
    /// thinnest wall, the size; lengths in `unit`. For example "Not closed: 2 holes (their
    /// edges are shown).", "Thinnest wall 0.41 mm, under the 1 mm minimum, at 120 vertices.",
    /// "Size 82.1 × 40.0 × 51.3 mm.".
    pub fn sentences(&self, unit: Unit) -> Vec<String> {
        if self.models.is_empty() {
            return vec![String::from(
                "There is nothing to print: no model has triangles.",
            )];
        }
        let mut out = Vec::new();
        let n_repaired = self.models.iter().filter(|m| m.is_repaired).count();
        let bad_edges: usize = self.models.iter().map(|m| m.file_non_manifold_edges).sum();
        out.push(match (self.n_holes(), n_repaired) {
            (0, 0) => String::from("Closed and manifold."),
            (0, _) => String::from("Closed, and manifold as repaired on import."),
            (1, _) => String::from("Not closed: 1 hole (its edges are shown)."),
            (n, _) => format!("Not closed: {n} holes (their edges are shown)."),
        });
        if n_repaired > 0 {
            out.push(format!(
                "The imported file was not manifold ({}); the check and the STL use the surface it was repaired into.",
                count(bad_edges, "edge with more than two triangles or a turned one", "edges with more than two triangles or turned ones")
            ));
        }
        let n_places = self.n_crossing_places();
        out.push(match n_places {
            0 => String::from("The surface does not cross itself."),
            1 => String::from("1 place where the surface crosses itself (shown)."),
            n => format!("{n} places where the surface crosses itself (shown)."),
        });
        out.push(self.wall_sentence(unit));
        if let Some((lo, hi)) = self.bounds() {
            let size = (hi - lo).to_array().map(|x| unit.from_metres(x));
            let decimals = decimals(size.iter().copied().fold(0.0, f64::max), 3);
            let [x, y, z] = size.map(|x| format!("{x:.decimals$}"));
            out.push(format!("Size {x} × {y} × {z} {unit}."));
        }
        out
    }

    fn wall_sentence(&self, unit: Unit) -> String {
        let min_wall = unit.from_metres(self.min_wall);
        // "1 mm", "0.5 mm": the user's number, without the zeros of a fixed format.
        let mut min_wall = format!("{:.*}", decimals(min_wall, 2), min_wall);
        if min_wall.contains('.') {
            min_wall = min_wall
                .trim_end_matches('0')
                .trim_end_matches('.')
                .to_owned();
        }
        let Some(thinnest) = self.thinnest() else {
            return String::from(
                "The walls could not be measured: no ray from inside met the surface again.",
            );
        };
        let thin: usize = self
            .models
            .iter()
            .map(|m| m.thickness.thin_vertices.len())
            .sum();
        let thinnest = unit.from_metres(thinnest);
        let thinnest = format!("{thinnest:.*}", decimals(thinnest, 2));
        let sampled: usize = self.models.iter().map(|m| m.thickness.n_sampled).sum();
        let vertices: usize = self
            .models
            .iter()
            .map(|m| m.thickness.per_vertex.len())
            .sum();
        let sampled = if sampled < vertices {
            format!(" (measured at {sampled} of {vertices} vertices)")
        } else {
            String::new()
        };
        let at = count(thin, "vertex", "vertices");
        if self.thinnest().is_some_and(|t| t < self.min_wall) {
            format!(
                "Thinnest wall {thinnest} {unit}, under the {min_wall} {unit} minimum, at {at}{sampled}."
            )
        } else if thin > 0 {
            format!(
                "Thinnest wall {thinnest} {unit}, above the {min_wall} {unit} minimum{sampled}; {at} in creases or small details read thinner (shown)."
            )
        } else {
            format!(
                "Thinnest wall {thinnest} {unit}, above the {min_wall} {unit} minimum{sampled}."
            )
        }
    }
}

/// "1 vertex", "120 vertices".
fn count(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

/// Decimals that show `x` with about `digits` significant digits (none after the point for
/// large numbers).
fn decimals(x: f64, digits: i32) -> usize {
    if x <= 0.0 || !x.is_finite() {
        return 1;
    }
    (digits - 1 - x.log10().floor() as i32).max(0) as usize
}
