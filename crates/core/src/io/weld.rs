//! Welding vertices with bit-identical positions.

use glam::DVec3;
use rustc_hash::FxHashMap;

/// Merges positions that are bit-identical (−0 equals +0), keeping first-appearance order.
/// Returns the distinct positions and, for each input position, its index among them.
pub(crate) fn weld(positions: &[DVec3]) -> (Vec<DVec3>, Vec<u32>) {
    let mut distinct = Vec::new();
    // Keys are exact bit patterns from the file, so a fast non-cryptographic hash is fine.
    let mut index_of: FxHashMap<[u64; 3], u32> =
        FxHashMap::with_capacity_and_hasher(positions.len(), Default::default());
    let welded_of = positions
        .iter()
        .map(|&p| {
            // Adding +0.0 turns −0.0 into +0.0 and leaves everything else alone.
            let key = (p + DVec3::ZERO).to_array().map(f64::to_bits);
            *index_of.entry(key).or_insert_with(|| {
                distinct.push(p);
                (distinct.len() - 1) as u32
            })
        })
        .collect();
    (distinct, welded_of)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_positions_only() {
        let (distinct, welded_of) = weld(&[
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(-0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 1e-300),
            DVec3::X,
        ]);
        assert_eq!(distinct.len(), 3);
        assert_eq!(welded_of, vec![0, 1, 0, 2, 1]);
    }
}
