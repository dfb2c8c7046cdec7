//! The `certify --json` and `verify --json` documents. Their keys are in alphabetical order
//! (as these documents have always printed them); keys that only a load certificate has are
//! absent for a least-thickness one.

use super::common::JSON_VERSION;
use crate::certificate::format::{ArchSpec, Certificate, Claim, FillSpec, LoadSpec};
use crate::certificate::verify::{Rejection, Report};
use schemars::JsonSchema;
use serde::Serialize;

/// The answer of `certify`: the certificate with the bracket it proves. `status` is `ok`,
/// `gap_not_reached` (the best certificate found, wider than asked) or `not_certified`
/// (`message` says why; no certificate).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "CertifyResult")]
pub struct CertifyJson {
    /// Where the vehicle stands, metres from the left springing (a vehicle's certificate).
    #[serde(skip_serializing_if = "Option::is_none")]
    at_m: Option<f64>,
    /// The certificate document, as `certify --out` writes it (what `verify` reads).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "keys_sorted"
    )]
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    certificate: Option<Certificate>,
    /// What is claimed (`least_thickness`, `no_equilibrium`, `largest_multiplier`, ...).
    #[serde(skip_serializing_if = "Option::is_none")]
    claim: Option<Claim>,
    /// The load certificate's thickness ratio.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta: Option<f64>,
    /// The upper end of the proved bracket of η*.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta_hi: Option<Option<f64>>,
    /// The lower end of the proved bracket of η*.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta_lo: Option<Option<f64>>,
    /// The file the certificate was written to (`--out`).
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<Option<String>>,
    /// (hi − lo)/hi of the proved bracket.
    #[serde(skip_serializing_if = "Option::is_none")]
    gap_relative: Option<Option<f64>>,
    /// The relative gap asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    gap_requested: Option<f64>,
    /// The upper end of the proved bracket of λ (load certificates).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_hi: Option<Option<f64>>,
    /// The lower end of the proved bracket of λ (load certificates).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_lo: Option<Option<f64>>,
    /// The live load (load certificates).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "keys_sorted"
    )]
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    load: Option<LoadSpec>,
    /// Why there is no certificate.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
    /// μ (`null` = ∞).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schemars(extend("x-null" = "infinity"))]
    mu: Option<Option<f64>>,
    /// `ok`, `gap_not_reached` or `not_certified`.
    status: &'static str,
    /// The document format's version (2).
    version: u32,
}

impl CertifyJson {
    /// The document of a certificate made for a relative gap `gap` (written to `file`; for
    /// a vehicle standing at `at_m`).
    pub fn made(cert: &Certificate, gap: f64, file: Option<String>, at_m: Option<f64>) -> Self {
        let bracket = cert.bracket().or(cert.lambda_bracket());
        let load = cert.load.as_ref();
        CertifyJson {
            at_m,
            certificate: Some(cert.clone()),
            claim: Some(cert.claim),
            eta: load.map(|l| l.eta),
            eta_hi: Some(cert.bracket().map(|b| b.1)),
            eta_lo: Some(cert.bracket().map(|b| b.0)),
            file: Some(file),
            gap_relative: Some(bracket.map(|(lo, hi)| (hi - lo) / hi)),
            gap_requested: Some(gap),
            lambda_hi: load.map(|_| cert.lambda_bracket().map(|b| b.1)),
            lambda_lo: load.map(|_| cert.lambda_bracket().map(|b| b.0)),
            load: load.cloned(),
            message: None,
            mu: Some(cert.mu),
            status: if cert.delivers_gap(gap) {
                "ok"
            } else {
                "gap_not_reached"
            },
            version: JSON_VERSION,
        }
    }

    /// The document of a question that could not be certified, and why.
    pub fn not_certified(reason: String) -> Self {
        CertifyJson {
            at_m: None,
            certificate: None,
            claim: None,
            eta: None,
            eta_hi: None,
            eta_lo: None,
            file: None,
            gap_relative: None,
            gap_requested: None,
            lambda_hi: None,
            lambda_lo: None,
            load: None,
            message: Some(reason),
            mu: None,
            status: "not_certified",
            version: JSON_VERSION,
        }
    }
}

/// Serialises `v` with the keys of every object in alphabetical order (through a
/// `serde_json::Value`, whose maps are sorted).
fn keys_sorted<T: Serialize, S: serde::Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
    serde_json::to_value(v)
        .map_err(serde::ser::Error::custom)?
        .serialize(s)
}

/// The arch of a certificate as `verify` describes it.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "CertifiedArch")]
pub struct CertifiedArchJson {
    /// The left springing β_L (radians).
    beta_left: f64,
    /// The right springing β_R (radians).
    beta_right: f64,
    /// The fill (absent without fill).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "keys_sorted"
    )]
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    fill: Option<FillSpec>,
    /// The joints of a discrete arch (absent for a continuous one).
    #[serde(skip_serializing_if = "Option::is_none")]
    joint_angles: Option<Vec<f64>>,
    /// `continuous` or `discrete`.
    joints: &'static str,
    /// `centreline` or `centroid`.
    weight: crate::arch::WeightModel,
}

impl CertifiedArchJson {
    fn new(a: &ArchSpec) -> Self {
        CertifiedArchJson {
            beta_left: a.beta_left,
            beta_right: a.beta_right,
            fill: a.fill,
            joint_angles: a.joint_angles.clone(),
            joints: if a.joint_angles.is_some() {
                "discrete"
            } else {
                "continuous"
            },
            weight: a.weight,
        }
    }
}

/// The independent re-check of a certificate: `status` `ok` (it holds: `statement` says
/// what is proved) or `rejected` (`reason`; nothing is proved).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "VerifyResult")]
pub struct VerifyJson {
    /// The certificate's arch.
    arch: CertifiedArchJson,
    /// One line per check that passed, each saying whether it was proved (interval
    /// arithmetic) or checked (floating point, evidence only).
    checks: Vec<String>,
    /// What is claimed.
    claim: Claim,
    /// The load certificate's thickness ratio.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta: Option<f64>,
    /// The upper end of the bracket of η*.
    eta_hi: Option<f64>,
    /// The lower end of the bracket of η*.
    eta_lo: Option<f64>,
    /// The upper end of the bracket of λ (load certificates).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_hi: Option<Option<f64>>,
    /// The lower end of the bracket of λ (load certificates).
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_lo: Option<Option<f64>>,
    /// What the limit-state search lists (certificates with a search section).
    #[serde(skip_serializing_if = "Option::is_none")]
    limit_states: Option<Option<String>>,
    /// The live load (load certificates).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "keys_sorted"
    )]
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    load: Option<LoadSpec>,
    /// μ (`null` = ∞).
    #[schemars(extend("x-null" = "infinity"))]
    mu: Option<f64>,
    /// Why the certificate is rejected.
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
    /// The proved statement, in one line.
    #[serde(skip_serializing_if = "Option::is_none")]
    statement: Option<String>,
    /// `ok` or `rejected`.
    status: &'static str,
    /// The document format's version (2).
    version: u32,
}

impl VerifyJson {
    /// The document of `verify`'s `outcome` on `cert`.
    pub fn new(cert: &Certificate, outcome: &Result<Report, Rejection>) -> Self {
        let bracket = cert.bracket();
        let load = cert.load.as_ref();
        let ok = outcome.as_ref().ok();
        VerifyJson {
            arch: CertifiedArchJson::new(&cert.arch),
            checks: ok.map_or(Vec::new(), |r| r.checks.clone()),
            claim: cert.claim,
            eta: load.map(|l| l.eta),
            eta_hi: bracket.map(|b| b.1),
            eta_lo: bracket.map(|b| b.0),
            lambda_hi: load.map(|_| cert.lambda_bracket().map(|b| b.1)),
            lambda_lo: load.map(|_| {
                cert.multiplier
                    .as_ref()
                    .and_then(|m| m.admissible.as_ref())
                    .map(|s| s.lambda)
            }),
            limit_states: ok.map(|r| r.limit_states.clone()),
            load: load.cloned(),
            mu: cert.mu,
            reason: outcome.as_ref().err().map(|Rejection(why)| why.clone()),
            statement: ok.map(|r| r.statement()),
            status: if ok.is_some() { "ok" } else { "rejected" },
            version: JSON_VERSION,
        }
    }
}
