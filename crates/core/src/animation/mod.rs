//! Key-framed animation of a model: key poses, in-betweens by Laplacian-coordinate
//! interpolation (Zhou et al. 2005, §4.2), and the samples an export bakes.

mod key_blend;
mod timeline;

pub use key_blend::KeyBlend;
pub use timeline::{SAMPLES_PER_SECOND, Timeline};
