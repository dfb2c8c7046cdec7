//! A small deterministic generator (64-bit LCG) shared by the campaign examples, so that a
//! run can be repeated from its seed.

/// The generator's state.
pub struct Rng(pub u64);

impl Rng {
    /// A uniform number in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A uniform number in [a, b).
    #[allow(dead_code)] // not every example draws ranges
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}
