//! The corners of a limit curve as Markdown rows, in the layout of a paper's results table.

use super::format::right_half_angle;
use crate::arch::Arch;

/// The header of [`corner_rows`].
pub const CORNER_HEADER: &str =
    "| α_s | μ | φ [°] | η | β_N | β_T | between |\n|---:|---:|---:|---:|---:|---:|:---|";

/// The corners of a symmetric arch's limit curve as Markdown rows in the layout of a
/// paper's results table: α_s, μ and φ = atan μ (degrees), η, the intrados hinge β_N and
/// the sliding joint β_T in the right half (radians), the two modes the corner separates.
pub fn corner_rows(arch: &Arch, curve: &crate::limit_curve::LimitCurve) -> Vec<String> {
    use crate::contact::ContactKind;
    let alpha = 0.0 - arch.beta_right();
    let mut all: Vec<&crate::limit_curve::Corner> =
        curve.corners.iter().chain(&curve.transitions).collect();
    all.sort_by(|a, b| b.mu.total_cmp(&a.mu));
    all.into_iter()
        .map(|c| {
            let f = |v: Option<f64>| v.map_or("–".to_string(), |b| format!("{b:.8}"));
            let (mu, phi) = if c.mu.is_finite() {
                (
                    format!("{:.8}", c.mu),
                    format!("{:.4}", c.mu.atan().to_degrees()),
                )
            } else {
                ("∞".to_string(), "90".to_string())
            };
            format!(
                "| {alpha:.6} | {mu} | {phi} | {:.8} | {} | {} | {} / {}{} |",
                c.t,
                f(right_half_angle(arch, &c.pattern, |j| j.kind == ContactKind::HingeIntrados)),
                f(right_half_angle(arch, &c.pattern, |j| !j.kind.is_hinge())),
                c.between()[0].name(),
                c.between()[1].name(),
                match (c.exact, c.detail.kink) {
                    (true, true) => "",
                    (true, false) if c.mu.is_infinite() => " (asymptote)",
                    (true, false) => " (smooth transition)",
                    (false, _) => " (bracketed only)",
                }
            )
        })
        .collect()
}
