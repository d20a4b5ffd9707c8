//! TEMPORARY STUB (identity) until the remesher lands.
#![allow(missing_docs)]
use super::Mesh;
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    pub vertices: Vec<u32>,
    pub closed: bool,
}
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RemeshParams {
    pub target_edge: f64,
    pub iterations: usize,
}
impl RemeshParams {
    pub fn keep_resolution(_mesh: &Mesh) -> RemeshParams {
        RemeshParams {
            target_edge: 1.0,
            iterations: 3,
        }
    }
}
#[derive(Clone, Debug)]
pub struct Remeshed {
    pub mesh: Mesh,
    pub chains: Vec<Chain>,
}
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RemeshError {
    #[error("stub")]
    Stub,
}
pub fn remesh(
    mesh: &Mesh,
    chains: &[Chain],
    _params: &RemeshParams,
) -> Result<Remeshed, RemeshError> {
    Ok(Remeshed {
        mesh: mesh.clone(),
        chains: chains.to_vec(),
    })
}
