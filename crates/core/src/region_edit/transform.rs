//! The transforms a region may move by: finite, affine, keeping orientation and short of
//! half a turn, so that every fraction of one is defined (Alexa's log and exp).

use glam::{DMat4, DVec4};

use super::RegionError;
use crate::geometry::{Fractions, log_affine};

/// The fractions of a transform given column by column, as an op holds it.
///
/// Errors: a transform that is not finite, not affine, mirrors or flattens, or turns by half
/// a turn (no fraction of it is defined).
pub fn checked_transform(columns: &[f64; 16]) -> Result<Fractions, RegionError> {
    let matrix = DMat4::from_cols_array(columns);
    Ok(Fractions::with_log(matrix, checked_log(matrix)?))
}

/// The logarithm of a transform a region may move by.
///
/// Errors: as [`checked_transform`].
pub(super) fn checked_log(matrix: DMat4) -> Result<DMat4, RegionError> {
    if !matrix.is_finite() {
        return Err(RegionError::TransformNotFinite);
    }
    if matrix.row(3) != DVec4::W {
        return Err(RegionError::TransformNotAffine);
    }
    if matrix.determinant() <= 0.0 {
        return Err(RegionError::TransformMirrors);
    }
    log_affine(matrix).ok_or(RegionError::TransformTurnsHalfWay)
}
