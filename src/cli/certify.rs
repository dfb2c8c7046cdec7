//! `arch-enum certify` and `arch-enum verify`: checkable evidence for η*(μ), and its
//! independent re-check.

use super::arch_args::ArchArgs;
use super::{to_json, Exit, Io};
use crate::arch::{check_mu, fmt_value, InputError};
use crate::certificate::{certify, verify, Certificate, NotCertified, Rejection};
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
    /// Target relative gap (eta_hi - eta_lo)/eta_hi, 1e-15 to 1e-4; widened tenfold until provable.
    #[arg(long, default_value_t = 1e-12, allow_negative_numbers = true)]
    gap: f64,
    /// Write the certificate here instead of standard output.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print a JSON summary instead of text (the certificate itself is always JSON).
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
    match certify(&arch, a.mu, a.gap, settings) {
        Ok(cert) => {
            let text = to_json(&cert);
            match a.out {
                Some(path) => {
                    if let Err(e) = std::fs::write(&path, &text) {
                        io.err(&format!("error: cannot write {}: {e}\n", path.display()));
                        return Exit::BadInput;
                    }
                    let summary = serde_json::json!({"status": "ok", "file": path.display().to_string(), "claim": cert.claim, "gap_relative": cert.gap_relative});
                    if a.json {
                        io.out(&to_json(&summary));
                    } else {
                        io.out(&format!(
                            "wrote {} ({:?}, relative gap {:?})\n",
                            path.display(),
                            cert.claim,
                            cert.gap_relative
                        ));
                    }
                }
                None => io.out(&text),
            }
            Exit::Answered
        }
        Err(NotCertified(reason)) => {
            if a.json {
                io.out(&to_json(
                    &serde_json::json!({"status": "not_certified", "message": reason}),
                ));
            }
            io.err(&format!("not certified: {reason}\n"));
            Exit::NoAnswer
        }
    }
}

pub(crate) fn run_verify(a: VerifyArgs, io: &mut Io) -> Exit {
    let file = a.file;
    let text = match std::fs::read_to_string(&file) {
        Ok(t) => t,
        Err(e) => {
            io.err(&format!(
                "error: cannot read FILE {}: {e}\n",
                file.display()
            ));
            return Exit::BadInput;
        }
    };
    let cert: Certificate = match serde_json::from_str(&text) {
        Ok(c) => c,
        Err(e) => {
            io.err(&format!(
                "error: FILE {} is not a certificate: {e}\n",
                file.display()
            ));
            return Exit::BadInput;
        }
    };
    match verify(&cert) {
        Ok(report) => {
            if a.json {
                io.out(&to_json(
                    &serde_json::json!({"status": "holds", "checks": report.checks}),
                ));
            } else {
                io.out(&format!(
                    "certificate holds\n  {}\n",
                    report.checks.join("\n  ")
                ));
            }
            Exit::Answered
        }
        Err(Rejection(reason)) => {
            if a.json {
                io.out(&to_json(
                    &serde_json::json!({"status": "rejected", "reason": reason}),
                ));
            } else {
                io.out(&format!("certificate REJECTED: {reason}\n"));
            }
            Exit::NoAnswer
        }
    }
}
