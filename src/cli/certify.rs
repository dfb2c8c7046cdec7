//! `arch-enum certify` and `arch-enum verify`: checkable evidence for η*(μ), and its
//! independent re-check.

use super::arch_args::ArchArgs;
use super::io::{to_json, Exit, Io};
use super::load::{prepare_parts, BridgeFlags, LiveLoadArgs};
use crate::arch::{check_mu, fmt_value, InputError};
use crate::certificate::{
    certify, certify_load, distinct_in_lambda, verify, Certificate, Claim, LoadSearchMethod,
    NotCertified, Rejection, SearchMethod,
};
use crate::render::json;
use crate::settings::Settings;
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
#[command(mut_group("live", |g| g.required(false)))]
pub(crate) struct CertifyArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Friction coefficient mu > 0; `inf` for no sliding.
    #[arg(long, allow_negative_numbers = true)]
    mu: f64,
    /// With a live-load flag: the thickness ratio eta = t/r, 0 < eta < 2, at which the load multiplier is certified.
    #[arg(long, allow_hyphen_values = true)]
    eta: Option<f64>,
    /// A live load (as for `load`): certify its largest admissible multiplier lambda_static and its limit states instead of eta*.
    #[command(flatten)]
    live: Option<LiveLoadArgs>,
    /// The dimensions, a vehicle (at --at, or at its critical position with --critical) and
    /// the fill, as for `load`.
    #[command(flatten)]
    bridge: BridgeFlags,
    /// Requested relative gap (hi - lo)/hi of the bracket (of eta*, or of lambda_static under a load), 1e-15 to 1e-4. If it cannot be proved, the best certificate found (gap widened tenfold up to 1e-4) is still written, with status gap_not_reached and exit 1.
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

/// "inf" for `None`, else the number.
fn mu_text(mu: Option<f64>) -> String {
    mu.map_or("inf".into(), |m| m.to_string())
}

/// What `certify` is asked: the arch (with its fill under a load), the load with its η,
/// where a vehicle stands and whether that is its critical position.
struct Asked {
    arch: crate::arch::Arch,
    load: Option<(f64, crate::load::LiveLoad)>,
    at_m: Option<f64>,
    critical: bool,
}

/// The question of `a`, every input checked.
fn asked(a: &CertifyArgs, settings: &Settings) -> Result<Asked, InputError> {
    check_mu(a.mu)?;
    if !(a.gap.is_finite() && (1e-15..=1e-4).contains(&a.gap)) {
        return Err(InputError::OutOfRange {
            arg: "--gap",
            value: fmt_value(a.gap),
            range: "1e-15 <= gap <= 1e-4".into(),
        });
    }
    // a live load (or a vehicle, on the arch with its fill) and its thickness come together
    let loaded = a.live.is_some() || a.bridge.vehicle.given();
    // with fill, --ring fixes r and so the fill's depth ratio, as for `solve`
    let ring_used = a.bridge.fill.given() && a.eta.is_none();
    if !loaded && a.eta.or(a.arch.ring).is_some() && !ring_used {
        return Err(InputError::Inconsistent {
            arg: "--eta/--ring",
            reason: "--eta (or --ring) is used only with a live load (--horizontal, --horizontal-left, --point-load, --point-load-deg or --point-load-joint) or, --ring, with fill; without one, certify finds eta* itself".into(),
        });
    }
    if !loaded {
        let arch = a.arch.build()?;
        return Ok(Asked {
            arch: match a.bridge.fill_on(&a.arch)? {
                Some(fill) => arch.with_fill(fill),
                None => arch,
            },
            load: None,
            at_m: None,
            critical: false,
        });
    }
    let q = prepare_parts((&a.arch, a.eta, a.mu), a.live.as_ref(), &a.bridge, settings)?;
    Ok(Asked {
        load: Some((q.eta, q.load)),
        at_m: q.vehicle_at(),
        critical: q.critical().is_some(),
        arch: q.arch,
    })
}

pub(crate) fn run_certify(a: CertifyArgs, settings: &Settings, io: &mut Io) -> Exit {
    let Asked {
        arch,
        load,
        at_m,
        critical,
    } = match asked(&a, settings) {
        Ok(q) => q,
        Err(e) => return io.bad_input(&e),
    };
    let made = match &load {
        Some((eta, live)) => certify_load(&arch, *eta, a.mu, live, a.gap, settings),
        None => certify(&arch, a.mu, a.gap, settings),
    };
    let cert = match made {
        Ok(cert) => cert,
        Err(NotCertified(reason)) => {
            if a.json {
                io.out(&to_json(&json::CertifyJson::not_certified(reason.clone())));
            }
            io.err(&format!("not certified: {reason}\n"));
            return Exit::NoAnswer;
        }
    };
    let delivered = cert.delivers_gap(a.gap);
    let bracket = cert.bracket().or(cert.lambda_bracket());
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
        let file = a.out.as_ref().map(|p| p.display().to_string());
        io.out(&to_json(&json::CertifyJson::made(&cert, a.gap, file, at_m)));
    } else if let Some(path) = &a.out {
        let vehicle = at_m.map_or(String::new(), |at| {
            let which = if critical {
                " (its critical position X*)"
            } else {
                ""
            };
            format!("  the vehicle at X = {at} m from the left springing{which}\n")
        });
        io.out(&format!(
            "wrote {}\n{vehicle}  {}\n{}",
            path.display(),
            claim_text(&cert, a.gap),
            limit_states_text(&cert)
        ));
    } else {
        io.out(&to_json(&cert));
    }
    if delivered {
        Exit::Answered
    } else {
        Exit::NoAnswer
    }
}

/// The certificate's claim in one line.
fn claim_text(cert: &Certificate, requested: f64) -> String {
    let mu = mu_text(cert.mu);
    let eta = cert.load.as_ref().map(|l| l.eta);
    match (cert.bracket(), cert.lambda_bracket(), eta) {
        (Some((lo, hi)), _, _) => format!(
            "claim: eta* lies in [{lo}, {hi}] at mu = {mu}, relative gap {:e} (requested {requested:e})",
            (hi - lo) / hi
        ),
        (None, Some((lo, hi)), Some(eta)) => format!(
            "claim: lambda_static lies in [{lo}, {hi}] at eta = {eta}, mu = {mu}, relative gap {:e} (requested {requested:e})",
            (hi - lo) / hi
        ),
        (None, None, Some(eta)) if cert.claim == Claim::UnboundedMultiplier => format!(
            "claim: lambda_static is unbounded at eta = {eta}, mu = {mu} (admissible states at every lambda >= {})",
            cert.multiplier
                .as_ref()
                .and_then(|m| m.admissible.as_ref())
                .map_or(f64::NAN, |s| s.lambda)
        ),
        (None, None, Some(eta)) => {
            format!("claim: no state is admissible at any lambda >= 0 at eta = {eta}, mu = {mu}")
        }
        (None, _, None) if cert.claim == Claim::StandsAtEveryThickness => format!(
            "claim: a state is admissible at every thickness eta > 0 at mu = {mu} (eta* = 0, not attained)"
        ),
        (None, _, None) => format!("claim: no thickness stands at mu = {mu}"),
    }
}

/// What the certificate says about the limit states, one line.
fn limit_states_text(cert: &Certificate) -> String {
    // no admissible state at all: no limit state either, nothing more to certify
    if cert.claim == Claim::NoEquilibrium {
        return String::new();
    }
    if cert.claim == Claim::StandsAtEveryThickness {
        return "  limit states: not certified (no least thickness to bracket; `modes` and `solve` list the limit states above it)\n".to_string();
    }
    if cert.load.is_some() {
        return cert.load_search.as_ref().map_or(
            "  limit states: not certified (the search could not be completed)\n".to_string(),
            |s| {
                format!(
                    "  limit states: {} ({}{}; {} method; Farkas evidence for {} state(s) without a mechanism)\n",
                    match (s.lambda, s.limit_states.first()) {
                        (Some(l), _) => format!("{}, the collapse multiplier lambda = {l}", s.limit_states.len()),
                        (None, Some(f)) => format!(
                            "{} found, the collapse multiplier at most lambda = {}",
                            s.limit_states.len(),
                            f.lambda
                        ),
                        (None, None) => "none".to_string(),
                    },
                    match (s.unique, s.limit_states.is_empty()) {
                        (_, true) => "the load drives no mechanism",
                        // two found distinct in λ (the verifier's count): not unique
                        _ if s.method == LoadSearchMethod::Found => {
                            match distinct_in_lambda(&s.limit_states) >= 2 {
                                true => "not unique",
                                false => "uniqueness not claimed",
                            }
                        }
                        (true, false) => "unique",
                        (false, false) => "not unique",
                    },
                    if s.mechanism_at_static { ", one at lambda_static" } else { "" },
                    match s.method {
                        LoadSearchMethod::Sweep => "sweep",
                        LoadSearchMethod::Faces => "face search",
                        LoadSearchMethod::Associative => "associative",
                        LoadSearchMethod::Refined => "refined",
                        LoadSearchMethod::Found => "found (not claimed complete)",
                    },
                    s.no_mechanism.len() + usize::from(s.static_state.is_some())
                )
            },
        );
    }
    if cert.arch.fill.is_some() {
        return "  limit states: not certified with fill (the proofs of the search rest on the ring's weight alone; the limit state at eta*, where one is there, is checked)\n".to_string();
    }
    cert.search.as_ref().map_or(
        "  limit states: not certified (the search could not be completed)\n".to_string(),
        |s| {
            let ridge = s.ridge.as_ref().map_or(String::new(), |r| {
                let pieces: usize = r.edges.iter().map(|e| e.pieces.len()).sum();
                format!(
                    "; ridge evidence: {} edges of Q, {pieces} pieces",
                    r.edges.len()
                )
            });
            format!(
                "  limit states: {} at eta_s, {} above it ({}; Farkas evidence for {} state(s) without a mechanism{ridge})\n",
                if s.mechanism_at_eta { "one" } else { "none" },
                s.limit_states_above.len(),
                match (s.unique, s.mechanism_at_eta || !s.limit_states_above.is_empty()) {
                    (true, _) => "unique",
                    (false, true) if s.method == SearchMethod::Found => {
                        "not unique; the states found, the list not claimed complete"
                    }
                    (false, true) => "not unique",
                    (false, false) => "the search found no limit state",
                },
                s.no_mechanism.len() + usize::from(s.least_state.is_some())
            )
        },
    )
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
        io.out(&to_json(&json::VerifyJson::new(&cert, &outcome)));
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
                cert.claim.name(),
                mu_text(cert.mu)
            )),
        }
    }
    match outcome {
        Ok(_) => Exit::Answered,
        Err(_) => Exit::NoAnswer,
    }
}
