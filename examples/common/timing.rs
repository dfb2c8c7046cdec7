//! The median wall time of a closure, shared by the speed examples.

use std::time::Instant;

/// The median of `reps` timed runs of `f` (at least one), in seconds.
pub fn median<F: FnMut()>(mut f: F, reps: usize) -> f64 {
    let mut t: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}
