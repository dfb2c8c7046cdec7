//! Operations on a family's patterns (contacts with their row tags).

use super::traits::Tagged;
use crate::contact::{Contact, Location};

/// A discrete pattern carried over to the continuum: contacts of one kind and tag at
/// adjacent joints (spacing `h`) become one contact — the group's first contact that stays
/// where it is (`fixed`: a springing, the section of a point load) or else an interior
/// tangency contact with a free angle at the group's mean angle. The groups come in the
/// order of (kind, tag, β).
pub fn merge_adjacent<T: Copy + Ord>(
    pattern: &[Tagged<T>],
    h: f64,
    fixed: impl Fn(&Tagged<T>) -> bool,
) -> Vec<Tagged<T>> {
    let mut sorted = pattern.to_vec();
    sorted.sort_by(|a, b| {
        (a.0.kind, a.1)
            .cmp(&(b.0.kind, b.1))
            .then(a.0.beta.total_cmp(&b.0.beta))
    });
    let mut merged: Vec<Tagged<T>> = Vec::new();
    let mut group: Vec<Tagged<T>> = Vec::new();
    let flush = |group: &mut Vec<Tagged<T>>, out: &mut Vec<Tagged<T>>| {
        let Some(first) = group.first() else {
            return;
        };
        out.push(group.iter().copied().find(&fixed).unwrap_or((
            Contact {
                beta: group.iter().map(|c| c.0.beta).sum::<f64>() / group.len() as f64,
                kind: first.0.kind,
                at: Location::Interior,
                free: true,
            },
            first.1,
        )));
        group.clear();
    };
    for c in sorted {
        let joins = group.last().is_some_and(|l| {
            l.0.kind == c.0.kind && l.1 == c.1 && (c.0.beta - l.0.beta).abs() <= ADJACENT * h
        });
        if !joins {
            flush(&mut group, &mut merged);
        }
        group.push(c);
    }
    flush(&mut group, &mut merged);
    merged
}

/// Two contacts of one kind are adjacent joints of a discretisation of spacing h when they
/// are at most this many spacings apart.
const ADJACENT: f64 = 1.5;
