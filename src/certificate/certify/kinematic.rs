//! The Farkas alternatives of the kinematic LP for a state without a mechanism: one for the
//! whole pattern, else one per choice of one sliding sense per section.

use crate::certificate::format::{ContactKind, KinematicFarkas};

/// Farkas certificates for every one-sense choice of a pattern whose contacts have the
/// keys (angle, kind, section): first `one` on the whole pattern, else on each choice of
/// one sliding sense per section where both are listed (indices of the left-out contacts).
pub(super) fn farkas_cover<S: PartialEq>(
    keys: &[(f64, ContactKind, S)],
    one: impl Fn(Vec<usize>) -> Option<KinematicFarkas>,
) -> Vec<KinematicFarkas> {
    if let Some(f) = one(Vec::new()) {
        return vec![f];
    }
    // sections with both senses: (index of S+, index of S−)
    let both: Vec<(usize, usize)> = (0..keys.len())
        .filter(|&i| keys[i].1 == ContactKind::SlidePlus)
        .filter_map(|i| {
            (0..keys.len())
                .find(|&k| {
                    keys[k].1 == ContactKind::SlideMinus
                        && keys[k].0 == keys[i].0
                        && keys[k].2 == keys[i].2
                })
                .map(|k| (i, k))
        })
        .collect();
    if both.is_empty() || both.len() > 8 {
        return Vec::new();
    }
    (0..1usize << both.len())
        .filter_map(|choice| {
            let drop: Vec<usize> = both
                .iter()
                .enumerate()
                .map(|(b, &(p, m))| if choice >> b & 1 == 0 { m } else { p })
                .collect();
            one(drop)
        })
        .collect()
}
