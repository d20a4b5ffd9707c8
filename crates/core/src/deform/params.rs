//! Options of a Laplacian edit: how handles are fitted and how rotations are handled.

/// How handle points meet their targets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HandleFit {
    /// Handles land on their targets (up to round-off): vertex handles are fixed unknowns,
    /// points inside edges and faces hard constraints (see `exact_handles.rs`).
    Exact,
    /// Handles are pulled towards their targets by least-squares rows `weight · (Σ w_k x_k) =
    /// weight · target`, traded off against detail preservation. Each Laplacian row has unit
    /// weight on its own vertex, so `weight = 1` balances one handle against one vertex's
    /// detail; larger weights fit more closely.
    Soft {
        /// Weight of each handle row; positive.
        weight: f64,
    },
}

/// How the Laplacian coordinates (the details) follow the deformation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rotations {
    /// The linear, rotation-free edit: details keep their rest orientation. One
    /// back-substitution per call; bumps shear under large rotations.
    None,
    /// Per-vertex rotations of the details, from as-rigid-as-possible local steps: a first
    /// solve with the handles' rotation spread over the ROI, then each iteration fits a
    /// rotation per vertex, rotates its rest detail and back-substitutes again.
    Arap {
        /// Number of local/global iterations after the first solve (each costs one
        /// back-substitution).
        iterations: u32,
    },
}

/// Parameters of a [`LaplacianEdit`](super::LaplacianEdit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EditParams {
    /// How handles meet their targets.
    pub fit: HandleFit,
    /// Whether and how details rotate with the surface.
    pub rotations: Rotations,
}

impl EditParams {
    /// Rotation iterations used by [`EditParams::default`]: a 90 degree bend of a bumpy tube
    /// then keeps its bumps within 5.9 degrees of the normal, against 5.8 when run to
    /// convergence (see `tests/suite/deform.rs`). Each costs one back-substitution and a 3x3 fit
    /// per vertex.
    pub const DEFAULT_ARAP_ITERATIONS: u32 = 2;
}

impl Default for EditParams {
    /// Exact handles with [`EditParams::DEFAULT_ARAP_ITERATIONS`] ARAP iterations.
    fn default() -> Self {
        EditParams {
            fit: HandleFit::Exact,
            rotations: Rotations::Arap {
                iterations: EditParams::DEFAULT_ARAP_ITERATIONS,
            },
        }
    }
}
