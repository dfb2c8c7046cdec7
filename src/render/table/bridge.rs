//! The bridge lines of `load` with a vehicle or fill: the scope, the fill, the vehicle and,
//! with `--critical`, the critical position and the influence line.

use super::format::sig;
use crate::bridge::critical::{Collapse, Critical};
use crate::render::json::{influence_status, FillJson, VehicleJson, SCOPE};
use std::fmt::Write;

/// The bridge lines (each ends with a newline); `vehicle_kn` the vehicle's total (kN).
pub fn bridge(
    fill: Option<&FillJson>,
    vehicle: Option<&VehicleJson>,
    critical: Option<&Critical>,
    vehicle_kn: Option<f64>,
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "scope               {SCOPE}");
    if let Some(f) = fill {
        let weight = f
            .weight_kn_m3
            .map_or(String::new(), |w| format!("{} kN/m^3, ", sig(w, 6)));
        let depth = f
            .depth_m
            .map_or(String::new(), |d| format!("{} m, ", sig(d, 6)));
        let _ = writeln!(
            s,
            "fill                {weight}g_f = {} of the masonry's; road {depth}h = {} r above the highest extrados point",
            sig(f.weight_ratio, 6),
            sig(f.depth_ratio, 6)
        );
        if let Some(d) = f.depth_at_least_ring_m {
            let _ = writeln!(
                s,
                "                    h held as the ring varies: at the least ring the road is {} m above its extrados",
                sig(d, 6)
            );
        }
    }
    if let Some(v) = vehicle.filter(|v| !v.axles_kn.is_empty()) {
        let axles: Vec<String> = v.axles_kn.iter().map(|a| sig(*a, 6)).collect();
        let gaps: Vec<String> = v.spacing_m.iter().map(|a| sig(*a, 6)).collect();
        let _ = writeln!(
            s,
            "vehicle             axles {} kN{}, first axle at X = {} m from the left springing; dispersal {}, effective width {} m",
            axles.join(", "),
            if gaps.is_empty() { String::new() } else { format!(" {} m apart", gaps.join(", ")) },
            sig(v.at_m, 10),
            sig(v.dispersal, 6),
            sig(v.effective_width_m, 6)
        );
    }
    if let Some(v) = vehicle {
        if let Some([q, a, b]) = v.patch {
            let _ = writeln!(
                s,
                "patch load          {} kN/m^2 on the road from X = {} m to {} m",
                sig(q, 6),
                sig(a, 8),
                sig(b, 8)
            );
        }
        let _ = writeln!(
            s,
            "                    at lambda = 1 the ring carries {} kN of it, the abutments {} kN",
            sig(v.carried_kn, 6),
            sig(v.abutments_kn, 6)
        );
    }
    if let Some(c) = critical {
        critical_lines(&mut s, c, vehicle_kn);
    }
    s
}

fn critical_lines(s: &mut String, c: &Critical, vehicle_kn: Option<f64>) {
    let kn = |l: f64| vehicle_kn.map_or(String::new(), |v| format!(" ({} kN)", sig(l * v, 6)));
    match c.minima.first() {
        None => {
            let _ = writeln!(
                s,
                "critical            no finite collapse multiplier on the crossing"
            );
        }
        Some(m) => {
            let _ = writeln!(
                s,
                "critical            X* = {} m (in [{}, {}]), adequacy factor lambda_c = {}{}",
                sig(m.at_m, 10),
                sig(m.bracket_m.0, 10),
                sig(m.bracket_m.1, 10),
                sig(m.lambda, 10),
                kn(m.lambda)
            );
            if let Some(x) = c.mirror_m {
                let _ = writeln!(s, "                    its mirror image X = {} m ties (symmetric arch and vehicle)", sig(x, 10));
            }
            for o in c.minima.iter().skip(1) {
                let _ = writeln!(
                    s,
                    "local minimum       X = {} m, lambda_c = {}{}",
                    sig(o.at_m, 10),
                    sig(o.lambda, 10),
                    kn(o.lambda)
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "influence line      {} samples; {} complete searches and {} static maxima in all",
        c.influence.len(),
        c.surveys,
        c.statics
    );
    let _ = writeln!(s, "{:>16}  {:>16}", "X (m)", "lambda_c");
    for p in &c.influence {
        let v = match &p.collapse {
            Collapse::At(l) => sig(*l, 10),
            other => influence_status(other).to_string(),
        };
        let _ = writeln!(s, "{:>16}  {:>16}", sig(p.at_m, 8), v);
    }
}
