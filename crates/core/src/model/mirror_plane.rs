//! The plane a document is mirror-symmetric about: `n · x = d`, `n` a unit vector.

use glam::{DMat4, DVec3};
use serde::{Deserialize, Serialize};

/// A mirror plane `normal · x = offset`, `normal` of unit length. Written in files as
/// `[nx, ny, nz, d]`; its positive side is where `normal · x > offset`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "[f64; 4]", into = "[f64; 4]")]
pub struct MirrorPlane {
    normal: DVec3,
    offset: f64,
}

/// Which side of a [`MirrorPlane`] to keep or act on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// Where `normal · x > offset`.
    Positive,
    /// Where `normal · x < offset`.
    Negative,
}

impl Side {
    /// `1` on the positive side, `-1` on the negative one.
    pub fn sign(self) -> f64 {
        match self {
            Side::Positive => 1.0,
            Side::Negative => -1.0,
        }
    }
}

impl Default for MirrorPlane {
    /// The vertical plane through the world origin facing the first view: `x = 0`.
    fn default() -> Self {
        Self {
            normal: DVec3::X,
            offset: 0.0,
        }
    }
}

impl MirrorPlane {
    /// The plane `normal · x = offset` with `normal` made unit; `None` for a zero or
    /// non-finite normal or a non-finite offset.
    pub fn new(normal: DVec3, offset: f64) -> Option<Self> {
        let length = normal.length();
        (normal.is_finite() && length > 1e-12 && offset.is_finite()).then(|| Self {
            normal: normal / length,
            offset: offset / length,
        })
    }

    /// The plane through `point` with this `normal`.
    pub fn through(point: DVec3, normal: DVec3) -> Option<Self> {
        Self::new(normal, normal.dot(point))
    }

    /// The unit normal.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// `d` of `n · x = d`.
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// `n · p - d`: positive on the positive side.
    pub fn signed_distance(&self, p: DVec3) -> f64 {
        self.normal.dot(p) - self.offset
    }

    /// The side `p` lies on, `None` on the plane.
    pub fn side_of(&self, p: DVec3) -> Option<Side> {
        let s = self.signed_distance(p);
        (s != 0.0).then_some(if s > 0.0 {
            Side::Positive
        } else {
            Side::Negative
        })
    }

    /// The mirror image of a point.
    pub fn reflect(&self, p: DVec3) -> DVec3 {
        p - 2.0 * self.signed_distance(p) * self.normal
    }

    /// The mirror image of a direction.
    pub fn reflect_vector(&self, v: DVec3) -> DVec3 {
        v - 2.0 * self.normal.dot(v) * self.normal
    }

    /// The point of the plane nearest `p`.
    pub fn project(&self, p: DVec3) -> DVec3 {
        p - self.signed_distance(p) * self.normal
    }

    /// The plane carried by the affine `matrix` (moved, turned: the Arrange tool's handles
    /// on the plane); `None` when the matrix is singular or not finite.
    pub fn transformed(&self, matrix: DMat4) -> Option<Self> {
        let point = matrix.transform_point3(self.normal * self.offset);
        // Normals go by the inverse transpose, so a sheared or scaled plane stays a plane.
        let inverse = matrix.inverse();
        let normal = inverse.transpose().transform_vector3(self.normal);
        (inverse.is_finite() && point.is_finite())
            .then(|| Self::through(point, normal))
            .flatten()
    }

    /// The reflection as a 4×4 matrix (determinant −1), for the `transform` op.
    pub fn matrix(&self) -> DMat4 {
        let n = self.normal;
        let linear =
            glam::DMat3::IDENTITY - 2.0 * glam::DMat3::from_cols(n * n.x, n * n.y, n * n.z);
        DMat4::from_cols(
            linear.x_axis.extend(0.0),
            linear.y_axis.extend(0.0),
            linear.z_axis.extend(0.0),
            (2.0 * self.offset * n).extend(1.0),
        )
    }
}

impl TryFrom<[f64; 4]> for MirrorPlane {
    type Error = String;

    fn try_from([x, y, z, d]: [f64; 4]) -> Result<Self, String> {
        let normal = DVec3::new(x, y, z);
        if (normal.length() - 1.0).abs() > 1e-9 {
            return Err(format!(
                "a plane's normal [{x}, {y}, {z}] must be a unit vector"
            ));
        }
        if !(normal.is_finite() && d.is_finite()) {
            return Err(String::from("a plane's numbers must be finite"));
        }
        // Kept as written, not normalized again: a replay must mirror bit for bit.
        Ok(MirrorPlane { normal, offset: d })
    }
}

impl From<MirrorPlane> for [f64; 4] {
    fn from(plane: MirrorPlane) -> [f64; 4] {
        let n = plane.normal;
        [n.x, n.y, n.z, plane.offset]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_is_an_involution_and_the_matrix_agrees() {
        let plane = MirrorPlane::new(DVec3::new(1.0, 2.0, -0.5), 0.7).unwrap();
        let p = DVec3::new(0.3, -1.2, 2.5);
        let q = plane.reflect(p);
        assert!((plane.reflect(q) - p).length() < 1e-14);
        assert!((plane.signed_distance(q) + plane.signed_distance(p)).abs() < 1e-14);
        assert!((plane.matrix().transform_point3(p) - q).length() < 1e-14);
        assert!((plane.matrix().determinant() + 1.0).abs() < 1e-14);
        assert!(plane.signed_distance(plane.project(p)).abs() < 1e-14);
    }

    #[test]
    fn a_moved_and_turned_plane_carries_its_points() {
        let plane = MirrorPlane::new(DVec3::new(1.0, 0.3, 0.0), 0.4).unwrap();
        let matrix = DMat4::from_translation(DVec3::new(0.5, -1.0, 2.0))
            * DMat4::from_rotation_z(0.7)
            * DMat4::from_scale(DVec3::splat(1.5));
        let moved = plane.transformed(matrix).unwrap();
        for p in [DVec3::new(0.2, 0.7, -3.0), DVec3::new(-1.0, 2.0, 0.5)] {
            let on = plane.project(p);
            assert!(moved.signed_distance(matrix.transform_point3(on)).abs() < 1e-12);
        }
        let turned = (moved.normal()
            - DMat4::from_rotation_z(0.7).transform_vector3(plane.normal()))
        .length();
        assert!(turned < 1e-12, "the normal turns with the plane");
        assert!(plane.transformed(DMat4::ZERO).is_none());
    }

    #[test]
    fn files_hold_unit_normals_only() {
        let json = serde_json::to_string(&MirrorPlane::default()).unwrap();
        assert_eq!(json, "[1.0,0.0,0.0,0.0]");
        assert!(serde_json::from_str::<MirrorPlane>("[2.0,0.0,0.0,0.0]").is_err());
        assert!(serde_json::from_str::<MirrorPlane>("[0.0,1.0,0.0,0.5]").is_ok());
        let tilted = MirrorPlane::new(DVec3::new(1.0, -0.24389201267072605, 0.0), 0.3).unwrap();
        let json = serde_json::to_string(&tilted).unwrap();
        assert_eq!(serde_json::from_str::<MirrorPlane>(&json).unwrap(), tilted);
    }
}
