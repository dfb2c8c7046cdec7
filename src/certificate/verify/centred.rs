//! `stands_at_every_thickness`: on an arch of three joints the line of thrust through the
//! centre of every joint (M = 0 at all three) is one state, the solution of three linear
//! equations in x = (h, v, w). Where it has N > 0 (and |T| < μN) at every joint, its hinge
//! rows ±M − ηN/2 = −ηN/2 are negative at every η > 0: a state is admissible at every
//! thickness, and η* = 0 is not attained. The equations are solved by Cramer's rule in
//! interval arithmetic over cells of η covering [0, 2] (with the true-centroid weight the
//! weight's line of action moves with η), a cell split in two where it is not proved.

use super::report::{reject, Rejection};
use super::statics::{ntm_rows, Model, ETA_LIMIT};
use crate::certificate::interval::{det3, Interval as I};

/// The narrowest cell of η tried before the proof is given up.
const NARROWEST_CELL: f64 = ETA_LIMIT / 4096.0;

/// Proves the centred line of thrust admissible at every η in [0, 2] (the model must be a
/// discrete arch of exactly three joints); returns the number of cells and the state at
/// η = 0 (the middle of its enclosure, for the report).
pub(super) fn prove_centred(
    model: &Model,
    mu: Option<f64>,
) -> Result<(usize, [f64; 3]), Rejection> {
    let joints = match &model.joints {
        Some(js) if js.len() == 3 => [js[0], js[1], js[2]],
        _ => {
            return reject("a stands_at_every_thickness claim needs a discrete arch of exactly three joints (two voussoirs): only there is the centred line of thrust one state")
        }
    };
    let mut todo = vec![(ETA_LIMIT, 0.0)];
    let mut cells = 0;
    while let Some((hi, lo)) = todo.pop() {
        match centred_over(model, &joints, I::new(lo, hi), mu) {
            Ok(_) => cells += 1,
            // with the weight on the centreline nothing depends on η: splitting cannot help
            Err(why) if !model.centroid || hi - lo <= NARROWEST_CELL => {
                return reject(format!(
                "the centred line of thrust is not proved admissible at eta in [{lo}, {hi}]: {why}"
            ))
            }
            Err(_) => {
                let mid = 0.5 * (lo + hi);
                todo.push((hi, mid));
                todo.push((mid, lo));
            }
        }
    }
    let at_zero =
        centred_over(model, &joints, I::point(0.0), mu).map_or([f64::NAN; 3], |x| x.map(I::mid));
    Ok((cells, at_zero))
}

/// The centred state over the cell `eta` (enclosed), proved to have N > 0 and, at finite
/// μ, |T| < μN at the three joints; or why not.
fn centred_over(
    model: &Model,
    joints: &[f64; 3],
    eta: I,
    mu: Option<f64>,
) -> Result<[I; 3], String> {
    // the rows N, T, M at each joint; M = 0 at all three
    let rows = joints.map(|beta| ntm_rows(model, beta, eta));
    let a = rows.map(|[_, _, m]| m.0);
    let rhs = rows.map(|[_, _, m]| -m.1);
    let inv = det3(a)
        .recip()
        .ok_or("the three joints' moment equations are not proved independent")?;
    let x = [0, 1, 2].map(|k| {
        let mut ak = a;
        for j in 0..3 {
            ak[j][k] = rhs[j];
        }
        det3(ak) * inv
    });
    let at = |(g, c): ([I; 3], I)| x[0] * g[0] + x[1] * g[1] + x[2] * g[2] + c;
    for (&beta, &[n, t, _]) in joints.iter().zip(&rows) {
        let (n, t) = (at(n), at(t));
        if n.lo <= 0.0 {
            return Err(format!("N at beta = {beta} is not proved positive"));
        }
        if let Some(mu) = mu {
            let mn = I::point(mu) * n;
            if (t - mn).hi >= 0.0 || (-t - mn).hi >= 0.0 {
                return Err(format!("|T| < mu N at beta = {beta} is not proved"));
            }
        }
    }
    Ok(x)
}
