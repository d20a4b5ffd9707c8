//! Why an optimization was refused, as sentences for the user.

use thiserror::Error;

use crate::solve::SolveError;

/// A refused mesh optimization.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum OptimizeError {
    /// The scale `s` is not a positive number.
    #[error("the scale must be a positive number, not {0}")]
    InvalidScale(f64),
    /// Nothing to optimize.
    #[error("the model has no triangles to optimize")]
    Empty,
    /// The region to optimize holds no vertex of the model.
    #[error(
        "the lasso or the painted area holds no vertex of the model that faces you; draw it \
         around or over part of the model"
    )]
    EmptyRegion,
    /// The sparse factorization failed.
    #[error("the optimization could not be solved: {0}")]
    Solve(#[from] SolveError),
    /// The solve gave NaN or infinite positions.
    #[error("the optimization gave positions that are not numbers; the model is unchanged")]
    NotFinite,
}
