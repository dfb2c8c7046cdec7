//! `arch-enum certify` and `arch-enum verify`: checkable evidence for η*(μ), and its
//! independent re-check.

use super::arch_args::ArchArgs;
use super::{to_json, Exit, Io};
use crate::arch::{check_mu, fmt_value, InputError};
use crate::certificate::{certify, verify, ArchSpec, Certificate, Claim, NotCertified, Rejection};
use crate::render::json::JSON_VERSION;
use crate::settings::Settings;
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct CertifyArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Friction coefficient mu > 0; `inf` for no sliding.
    #[arg(long, allow_negative_numbers = true)]
    mu: f64,
    /// Requested relative gap (eta_hi - eta_lo)/eta_hi, 1e-15 to 1e-4. If it cannot be proved, the best certificate found (gap widened tenfold up to 1e-4) is still written, with status gap_not_reached and exit 1.
    #[arg(long, default_value_t = 1e-12, allow_negative_numbers = true)]
    gap: f64,
    /// Write the certificate here instead of standard output.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print one JSON document (status, claim, bracket, gaps, and the certificate) instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

#[derive(Args, Debug)]
pub(crate) struct VerifyArgs {
    /// The certificate file.
    file: PathBuf,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

/// The claim in words.
fn claim_name(c: Claim) -> &'static str {
    match c {
        Claim::LeastThickness => "least_thickness",
        Claim::NoEquilibrium => "no_equilibrium",
        Claim::LargestMultiplier => "largest_multiplier",
        Claim::UnboundedMultiplier => "unbounded_multiplier",
    }
}

/// "inf" for `None`, else the number.
fn mu_text(mu: Option<f64>) -> String {
    mu.map_or("inf".into(), |m| m.to_string())
}

/// The arch of a certificate as in every JSON document (`render::json::ArchJson` keys).
fn arch_json(a: &ArchSpec) -> serde_json::Value {
    let mut v = serde_json::json!({
        "beta_right": a.beta_right,
        "beta_left": a.beta_left,
        "weight": a.weight,
        "joints": if a.joint_angles.is_some() { "discrete" } else { "continuous" },
    });
    if let Some(j) = &a.joint_angles {
        v["joint_angles"] = serde_json::json!(j);
    }
    v
}

pub(crate) fn run_certify(a: CertifyArgs, settings: &Settings, io: &mut Io) -> Exit {
    let arch = match a.arch.build().and_then(|arch| check_mu(a.mu).map(|_| arch)) {
        Ok(arch) => arch,
        Err(e) => return io.bad_input(&e),
    };
    if !(a.gap.is_finite() && (1e-15..=1e-4).contains(&a.gap)) {
        return io.bad_input(&InputError::OutOfRange {
            arg: "--gap",
            value: fmt_value(a.gap),
            range: "1e-15 <= gap <= 1e-4".into(),
        });
    }
    let cert = match certify(&arch, a.mu, a.gap, settings) {
        Ok(cert) => cert,
        Err(NotCertified(reason)) => {
            if a.json {
                io.out(&to_json(&serde_json::json!({
                    "version": JSON_VERSION,
                    "status": "not_certified",
                    "message": reason,
                })));
            }
            io.err(&format!("not certified: {reason}\n"));
            return Exit::NoAnswer;
        }
    };
    let delivered = cert.delivers_gap(a.gap);
    let bracket = cert.bracket();
    let gap_relative = bracket.map(|(lo, hi)| (hi - lo) / hi);
    if let Some(path) = &a.out {
        if let Err(e) = std::fs::write(path, to_json(&cert)) {
            return io.bad(format!("cannot write --out {}: {e}", path.display()));
        }
    }
    if !delivered {
        io.err(&format!(
            "warning: the requested relative gap {:e} could not be proved; the best certificate has relative gap {}\n",
            a.gap,
            gap_relative.map_or("none".into(), |g| format!("{g:e}"))
        ));
    }
    if a.json {
        io.out(&to_json(&serde_json::json!({
            "version": JSON_VERSION,
            "status": if delivered { "ok" } else { "gap_not_reached" },
            "file": a.out.as_ref().map(|p| p.display().to_string()),
            "claim": cert.claim,
            "mu": cert.mu,
            "eta_lo": bracket.map(|b| b.0),
            "eta_hi": bracket.map(|b| b.1),
            "gap_requested": a.gap,
            "gap_relative": gap_relative,
            "certificate": cert,
        })));
    } else if let Some(path) = &a.out {
        let what = match bracket {
            Some((lo, hi)) => format!(
                "claim: eta* lies in [{lo}, {hi}] at mu = {}, relative gap {:e} (requested {:e})",
                mu_text(cert.mu),
                (hi - lo) / hi,
                a.gap
            ),
            None => format!("claim: no thickness stands at mu = {}", mu_text(cert.mu)),
        };
        let search = cert.search.as_ref().map_or(
            "  limit states: not certified (the search could not be completed)\n".to_string(),
            |s| {
                format!(
                    "  limit states: {} at eta_s, {} above it ({}; Farkas evidence for {} state(s) without a mechanism)\n",
                    if s.mechanism_at_eta { "one" } else { "none" },
                    s.limit_states_above.len(),
                    if s.unique { "unique" } else { "not unique" },
                    s.no_mechanism.len() + usize::from(s.least_state.is_some())
                )
            },
        );
        io.out(&format!("wrote {}\n  {what}\n{search}", path.display()));
    } else {
        io.out(&to_json(&cert));
    }
    if delivered {
        Exit::Answered
    } else {
        Exit::NoAnswer
    }
}

pub(crate) fn run_verify(a: VerifyArgs, io: &mut Io) -> Exit {
    let file = a.file;
    let text = match std::fs::read_to_string(&file) {
        Ok(t) => t,
        Err(e) => return io.bad(format!("cannot read FILE {}: {e}", file.display())),
    };
    let cert: Certificate = match serde_json::from_str(&text) {
        Ok(c) => c,
        Err(e) => return io.bad(format!("FILE {} is not a certificate: {e}", file.display())),
    };
    let outcome = verify(&cert);
    if a.json {
        let (status, checks, reason) = match &outcome {
            Ok(r) => ("ok", r.checks.clone(), None),
            Err(Rejection(why)) => ("rejected", Vec::new(), Some(why.clone())),
        };
        let bracket = cert.bracket();
        let mut doc = serde_json::json!({
            "version": JSON_VERSION,
            "status": status,
            "claim": cert.claim,
            "mu": cert.mu,
            "eta_lo": bracket.map(|b| b.0),
            "eta_hi": bracket.map(|b| b.1),
            "arch": arch_json(&cert.arch),
            "checks": checks,
        });
        if let Ok(r) = &outcome {
            doc["statement"] = serde_json::json!(r.statement());
            doc["limit_states"] = serde_json::json!(r.limit_states);
        }
        if let Some(reason) = reason {
            doc["reason"] = serde_json::json!(reason);
        }
        io.out(&to_json(&doc));
    } else {
        match &outcome {
            Ok(r) => io.out(&format!(
                "certificate holds\n{}\n{}  arch: {}\n  {}\n",
                r.statement(),
                r.limit_states
                    .as_ref()
                    .map_or(String::new(), |l| format!("{l}\n")),
                r.arch_text(),
                r.checks.join("\n  ")
            )),
            Err(Rejection(reason)) => io.out(&format!(
                "certificate REJECTED ({} claim at mu = {}): {reason}\nnothing is proved\n",
                claim_name(cert.claim),
                mu_text(cert.mu)
            )),
        }
    }
    match outcome {
        Ok(_) => Exit::Answered,
        Err(_) => Exit::NoAnswer,
    }
}
