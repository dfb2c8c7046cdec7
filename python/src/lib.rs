//! `arch_enum._native`: the Rust library behind the Python package `arch_enum`.
//!
//! A thin layer, no numerics: every function builds the arch from the Python arguments,
//! calls one library function with the GIL released, and returns the command line's JSON
//! document for that question (`render::json`, `render::load`) as Python dicts and lists,
//! plus the bulk data of the figures (lines of thrust and friction) and, on request, the
//! library's own SVG figures and COMPAS documents. Bad input raises `ValueError` with the
//! library's message, the argument named as in Python (`beta_right`, not `--beta-right`).
//! The Python side (`arch_enum/*.py`) turns the dicts into frozen dataclasses.

use arch_enum::arch::{check_eta, check_mu, fmt_value, InputError, JointLayout};
use arch_enum::atlas::{atlas as atlas_of, Rectangle};
use arch_enum::bridge::{Geometry, Intrados};
use arch_enum::certificate::{certify as certify_eta, verify as verify_cert, Certificate};
use arch_enum::figures::{self, ArchScene};
use arch_enum::friction::least_friction;
use arch_enum::limit::mu_ms_of;
use arch_enum::limit_curve::{available_threads, sample, trace_parallel};
use arch_enum::limit_states::survey;
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{check_load, survey_partial as load_survey};
use arch_enum::render::geometry as render_geometry;
use arch_enum::render::json::JSON_VERSION;
use arch_enum::render::load::{json as load_json, LoadQuestion};
use arch_enum::render::{compas, json, plot_arch, plot_curve};
use arch_enum::{Arch, Settings, WeightModel};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use serde_json::Value;

/// The arch as Python describes it: (alpha, beta_right, beta_left, blocks, joints, weight,
/// fill as (g_f, h)).
type ArchIn = (
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<i64>,
    Option<Vec<f64>>,
    String,
    Option<(f64, f64)>,
);

/// The Python name of a command-line argument: `--beta-right/--beta-left` →
/// `beta_right/beta_left`.
fn py_name(arg: &str) -> String {
    arg.split('/')
        .map(|a| a.trim_start_matches("--").replace('-', "_"))
        .collect::<Vec<_>>()
        .join("/")
}

/// `ValueError` with the library's message, the argument named as in Python (`rename`
/// may name it differently still, e.g. `mu[3]` for one element of an array).
fn value_error_as(e: InputError, rename: Option<&str>) -> PyErr {
    let message = match e {
        InputError::OutOfRange { arg, value, range } => format!(
            "invalid value for {}: {value} (valid range: {range})",
            rename.map_or_else(|| py_name(arg), str::to_string)
        ),
        InputError::Inconsistent { arg, reason } => format!(
            "invalid {}: {reason}",
            rename.map_or_else(|| py_name(arg), str::to_string)
        ),
    };
    PyValueError::new_err(message)
}

fn value_error(e: InputError) -> PyErr {
    value_error_as(e, None)
}

fn inconsistent(arg: &'static str, reason: &str) -> PyErr {
    value_error(InputError::Inconsistent {
        arg,
        reason: reason.into(),
    })
}

/// The weight model named `weight` ("centreline" or "centroid").
fn weight_of(weight: &str) -> PyResult<WeightModel> {
    match weight {
        "centreline" => Ok(WeightModel::Centreline),
        "centroid" => Ok(WeightModel::Centroid),
        other => Err(PyValueError::new_err(format!(
            "invalid value for weight: {other:?} (valid values: \"centreline\", \"centroid\")"
        ))),
    }
}

/// Builds and validates the arch (as `ArchArgs::build` does for the command line).
fn build_arch(a: &ArchIn) -> PyResult<Arch> {
    let (alpha, beta_right, beta_left, blocks, joints, weight, fill) = a;
    let fill = fill
        .map(|(g, h)| {
            arch_enum::fill::Fill::new(g, h).map_err(|e| {
                let name = match &e {
                    InputError::OutOfRange { arg, .. } if *arg == "--fill-depth" => "fill_height",
                    _ => "fill_ratio",
                };
                value_error_as(e, Some(name))
            })
        })
        .transpose()?;
    let with_fill = |a: Arch| match fill {
        Some(f) => a.with_fill(f),
        None => a,
    };
    let weight = weight_of(weight)?;
    let arch = match (alpha, beta_right, beta_left) {
        (Some(a), None, None) => Arch::symmetric(*a, weight),
        (None, Some(r), Some(l)) => Arch::new(*r, *l, weight),
        (Some(_), _, _) => {
            return Err(inconsistent(
                "alpha/beta_right/beta_left",
                "give alpha (a symmetric arch) or beta_right and beta_left, not both",
            ))
        }
        (None, None, None) => {
            return Err(inconsistent(
                "alpha/beta_right/beta_left",
                "describe the arch with alpha=A (radians), or beta_right=B1 and beta_left=B2",
            ))
        }
        _ => {
            return Err(inconsistent(
                "beta_right/beta_left",
                "an unsymmetric arch needs both springings, beta_right and beta_left",
            ))
        }
    }
    .map_err(value_error)?;
    match (blocks, joints) {
        (Some(_), Some(_)) => Err(inconsistent(
            "blocks/joints",
            "give blocks or joints, not both",
        )),
        (Some(n), None) => {
            // a negative count is out of the same range as 0
            let n = usize::try_from(*n).map_err(|_| {
                value_error(InputError::OutOfRange {
                    arg: "blocks",
                    value: n.to_string(),
                    range: "whole numbers 1 to 100000".into(),
                })
            })?;
            arch.with_blocks(n).map(with_fill).map_err(value_error)
        }
        (None, Some(j)) => arch.with_joints(j).map(with_fill).map_err(value_error),
        (None, None) => Ok(with_fill(arch)),
    }
}

/// A JSON value as a Python object (`null` → `None`).
fn to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_f64()) {
            (Some(i), _) if !n.is_f64() => i.into_pyobject(py)?.into_any(),
            (_, Some(f)) => f.into_pyobject(py)?.into_any(),
            _ => return Err(PyRuntimeError::new_err(format!("number out of range: {n}"))),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

fn figure_error(e: impl std::fmt::Display) -> PyErr {
    PyRuntimeError::new_err(format!("no figure: {e}"))
}

/// Numbers as the bytes of little-endian f64 (NumPy reads them without a Python float each).
fn f64_bytes<'py>(py: Python<'py>, v: impl Iterator<Item = f64>) -> Bound<'py, PyBytes> {
    let bytes: Vec<u8> = v.flat_map(f64::to_le_bytes).collect();
    PyBytes::new(py, &bytes)
}

/// The lines of a scene: the samples (β, N, e_M, e_T) and the lines of thrust and friction
/// as (x, y) points in units of r, each as the bytes of little-endian f64 ([`f64_bytes`];
/// points interleaved x, y), and the η drawn.
fn lines_py<'py>(py: Python<'py>, scene: &ArchScene) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let col = |f: fn(&figures::thrust_line::Eccentricity) -> f64| {
        f64_bytes(py, scene.lines.iter().map(f))
    };
    let pts = |p: Vec<(f64, f64)>| f64_bytes(py, p.into_iter().flat_map(|(x, y)| [x, y]));
    d.set_item("beta", col(|e| e.beta))?;
    d.set_item("n", col(|e| e.n))?;
    d.set_item("e_m", col(|e| e.e_m))?;
    d.set_item("e_t", col(|e| e.e_t))?;
    d.set_item("eta", scene.eta)?;
    d.set_item("thrust_line", pts(scene.thrust_line()))?;
    d.set_item("friction_line", pts(scene.friction_line()))?;
    d.set_item("outline", pts(scene.outline()))?;
    Ok(d)
}

/// The engineer's description (bridge spec §1): clear span and rise of the intrados and,
/// optionally, the ring thickness (metres), with what they give (the `geometry` object of
/// `--span --rise [--ring]`: R_i, α, the springings, r and η).
#[pyfunction]
#[pyo3(signature = (span, rise, ring=None))]
fn geometry<'py>(
    py: Python<'py>,
    span: f64,
    rise: f64,
    ring: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let intrados = Intrados::new(span, rise).map_err(value_error)?;
    let ring = ring
        .map(|t| intrados.ring(t))
        .transpose()
        .map_err(value_error)?;
    to_py(
        py,
        &render_geometry::json(&Geometry { intrados, ring }, None),
    )
}

/// Validates and describes the arch: the `arch` object of every JSON document.
#[pyfunction]
fn arch<'py>(py: Python<'py>, spec: ArchIn) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    let d = serde_json::to_value(json::ArchJson::new(&arch)).expect("serialisable");
    to_py(py, &d)
}

/// `solve --json` (η*(μ) and every limit state above η_s), with `lines`: the samples of the
/// lines of thrust and friction of the least limit state (`None` when there is none).
#[pyfunction]
fn solve<'py>(py: Python<'py>, spec: ArchIn, mu: f64) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    let (d, scene) = py
        .detach(|| -> Result<(Value, Option<ArchScene>), InputError> {
            let sv = survey(&arch, mu, &Settings::default())?;
            let d = serde_json::to_value(json::solve(&sv, false, &sv.rays(&Settings::default())))
                .expect("serialisable");
            Ok((d, figures::survey_scene(&sv, &Settings::default()).ok()))
        })
        .map_err(value_error)?;
    let out = to_py(py, &d)?;
    match scene {
        Some(s) => out.set_item("lines", lines_py(py, &s)?)?,
        None => out.set_item("lines", py.None())?,
    }
    Ok(out)
}

/// μ_ms of the arch (`mu="ms"` in Python, `--mu ms` on the command line): a `ValueError`
/// naming `mu` when the arch has none.
#[pyfunction]
fn mu_ms(py: Python<'_>, spec: ArchIn) -> PyResult<f64> {
    let arch = build_arch(&spec)?;
    py.detach(|| mu_ms_of(&arch, &Settings::default()))
        .map_err(|e| value_error_as(e, Some("mu")))
}

/// The scene `solve` reports at the top level, or the reason there is none.
fn solve_scene(spec: &ArchIn, mu: f64, py: Python<'_>) -> PyResult<ArchScene> {
    let arch = build_arch(spec)?;
    py.detach(|| {
        let sv = survey(&arch, mu, &Settings::default()).map_err(value_error)?;
        figures::survey_scene(&sv, &Settings::default()).map_err(figure_error)
    })
}

/// The `plot arch` figure (SVG) of the state `solve` reports.
#[pyfunction]
fn solve_svg(py: Python<'_>, spec: ArchIn, mu: f64) -> PyResult<String> {
    let scene = solve_scene(&spec, mu, py)?;
    plot_arch::svg(&scene).map_err(figure_error)
}

/// The COMPAS document (JSON text, as `solve --compas FILE` writes it) of the state
/// `solve` reports, scaled by `radius`.
#[pyfunction]
fn solve_compas(py: Python<'_>, spec: ArchIn, mu: f64, radius: f64) -> PyResult<String> {
    compas::check_radius(radius).map_err(value_error)?;
    let scene = solve_scene(&spec, mu, py)?;
    Ok(serde_json::to_string_pretty(&compas::document(&scene, radius)).expect("serialisable"))
}

/// `curve --json` at the given friction coefficients, solved on `threads` threads (default:
/// every core) with the GIL released.
#[pyfunction]
#[pyo3(signature = (spec, mus, threads=None))]
fn curve<'py>(
    py: Python<'py>,
    spec: ArchIn,
    mus: Vec<f64>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    for (i, &mu) in mus.iter().enumerate() {
        check_mu(mu).map_err(|e| value_error_as(e, Some(&format!("mu[{i}]"))))?;
    }
    let threads = match threads {
        Some(0) => {
            return Err(PyValueError::new_err(
                "invalid value for threads: 0 (valid range: 1 or more, or None for every core)",
            ))
        }
        Some(n) => n,
        None => available_threads(),
    };
    let d = py
        .detach(|| {
            let settings = Settings::default();
            let points = sample(&arch, &mus, &settings, threads, &|_, _| {})?;
            let mu_ms = least_friction(&arch, &settings).ok().flatten();
            Ok::<_, InputError>(
                serde_json::to_value(json::curve(&arch, mu_ms, &points)).expect("serialisable"),
            )
        })
        .map_err(value_error)?;
    to_py(py, &d)
}

/// `modes --json`: the whole η–μ limit curve (on every core, as the command line).
#[pyfunction]
fn modes<'py>(py: Python<'py>, spec: ArchIn) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    let d = py.detach(|| {
        let c = trace_parallel(&arch, &Settings::default(), available_threads());
        serde_json::to_value(json::modes(&arch, &c)).expect("serialisable")
    });
    to_py(py, &d)
}

/// `atlas --json`: the atlas of uniqueness over openings α and μ from μ_ms(α) (on every
/// core, as the command line).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn atlas<'py>(
    py: Python<'py>,
    alpha_min: f64,
    alpha_max: f64,
    mu_max_factor: f64,
    weight: &str,
    blocks: Option<usize>,
    columns: usize,
    samples: usize,
    certify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let rect = Rectangle {
        alpha_min,
        alpha_max,
        mu_max_factor,
        weight: weight_of(weight)?,
        blocks,
        columns,
        samples,
        certify,
    };
    let d = py
        .detach(|| {
            let a = atlas_of(&rect, &Settings::default(), available_threads(), &|_, _| {})?;
            Ok::<_, InputError>(serde_json::to_value(json::atlas(&a)).expect("serialisable"))
        })
        .map_err(value_error)?;
    to_py(py, &d)
}

/// The `plot curve` figure (SVG) of one arch.
#[pyfunction]
fn modes_svg(py: Python<'_>, spec: ArchIn) -> PyResult<String> {
    let arch = build_arch(&spec)?;
    py.detach(|| {
        let data = figures::curves(&[arch], &Settings::default()).map_err(figure_error)?;
        plot_curve::svg(&data, false).map_err(figure_error)
    })
}

/// `assess --json`: a given thickness at a given friction.
#[pyfunction]
fn assess<'py>(py: Python<'py>, spec: ArchIn, eta: f64, mu: f64) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    let d = py
        .detach(|| {
            let a = arch_enum::assess::assess(&arch, eta, mu, &Settings::default())?;
            Ok::<_, InputError>(
                serde_json::to_value(json::assess(&arch, &a)).expect("serialisable"),
            )
        })
        .map_err(value_error)?;
    to_py(py, &d)
}

/// The `plot arch --eta` figure (SVG): the state of greatest margin at η (the limit state
/// when η = η*).
#[pyfunction]
fn assess_svg(py: Python<'_>, spec: ArchIn, eta: f64, mu: f64) -> PyResult<String> {
    let arch = build_arch(&spec)?;
    check_eta(eta).map_err(value_error)?;
    check_mu(mu).map_err(value_error)?;
    py.detach(|| {
        let scene =
            figures::scene(&arch, mu, Some(eta), &Settings::default()).map_err(figure_error)?;
        plot_arch::svg(&scene).map_err(figure_error)
    })
}

/// The live load: `kind` "horizontal" (towards the right springing or not) or "point" at
/// `beta` radians or `beta_deg` degrees (snapped to a joint within 1e-9 rad, as on the
/// command line), or at joint `joint` of a discrete arch. Errors name the Python argument.
fn build_load(
    arch: &Arch,
    kind: &str,
    towards_right: bool,
    beta: Option<f64>,
    beta_deg: Option<f64>,
    joint: Option<i64>,
) -> PyResult<LiveLoad> {
    let joints: &[f64] = match arch.layout() {
        JointLayout::Discrete(j) => j,
        JointLayout::Continuous => &[],
    };
    let snap = |b: f64| arch.snap_to_joint(b);
    let load = match (kind, beta, beta_deg, joint) {
        ("horizontal", None, None, None) => LiveLoad::Horizontal { towards_right },
        ("point", Some(b), None, None) => {
            let load = LiveLoad::Point { beta: snap(b) };
            check_load(arch, &load).map_err(|e| value_error_as(e, Some("point_load")))?;
            load
        }
        ("point", None, Some(d), None) => {
            let load = LiveLoad::Point {
                beta: snap(d.to_radians()),
            };
            check_load(arch, &load).map_err(|_| {
                value_error(InputError::OutOfRange {
                    arg: "point_load_deg",
                    value: fmt_value(d),
                    range: format!(
                        "between the springings, {} to {} degrees",
                        arch.beta_right().to_degrees(),
                        arch.beta_left().to_degrees()
                    ),
                })
            })?;
            load
        }
        ("point", None, None, Some(k)) => {
            match usize::try_from(k).ok().and_then(|k| joints.get(k)) {
                Some(&beta) => LiveLoad::Point { beta },
                None => {
                    return Err(value_error(InputError::OutOfRange {
                        arg: "point_load_joint",
                        value: k.to_string(),
                        range: if joints.is_empty() {
                            "a joint index of a discrete arch (give blocks or joints)".into()
                        } else {
                            format!("0 <= point_load_joint <= {}", joints.len() - 1)
                        },
                    }))
                }
            }
        }
        _ => {
            return Err(inconsistent(
                "horizontal/point_load/point_load_deg/point_load_joint",
                "give exactly one live load",
            ))
        }
    };
    Ok(load)
}

/// `load --json`: the collapse multiplier of a live load at (η, μ).
#[pyfunction]
#[pyo3(signature = (spec, eta, mu, kind, towards_right, beta, beta_deg, joint))]
#[allow(clippy::too_many_arguments)]
fn load<'py>(
    py: Python<'py>,
    spec: ArchIn,
    eta: f64,
    mu: f64,
    kind: &str,
    towards_right: bool,
    beta: Option<f64>,
    beta_deg: Option<f64>,
    joint: Option<i64>,
) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    let live = build_load(&arch, kind, towards_right, beta, beta_deg, joint)?;
    let d = py
        .detach(|| {
            let outcome = load_survey(&arch, eta, mu, &live, &Settings::default())?;
            let q = LoadQuestion {
                arch: &arch,
                eta,
                mu,
                load: live,
                dims: None,
                vehicle_kn: None,
            };
            Ok::<_, InputError>(
                serde_json::to_value(load_json(&q, &outcome)).expect("serialisable"),
            )
        })
        .map_err(value_error)?;
    to_py(py, &d)
}

/// The `plot load` figure (SVG): every limit state of the live load, one panel each.
#[pyfunction]
#[pyo3(signature = (spec, eta, mu, kind, towards_right, beta, beta_deg, joint))]
#[allow(clippy::too_many_arguments)]
fn load_svg(
    py: Python<'_>,
    spec: ArchIn,
    eta: f64,
    mu: f64,
    kind: &str,
    towards_right: bool,
    beta: Option<f64>,
    beta_deg: Option<f64>,
    joint: Option<i64>,
) -> PyResult<String> {
    let arch = build_arch(&spec)?;
    let live = build_load(&arch, kind, towards_right, beta, beta_deg, joint)?;
    check_eta(eta).map_err(value_error)?;
    check_mu(mu).map_err(value_error)?;
    py.detach(|| {
        let scenes = figures::load_scenes(&arch, eta, mu, &live, &Settings::default())
            .map_err(figure_error)?;
        plot_arch::svg_panels(&scenes).map_err(figure_error)
    })
}

/// `certify --json` (`file` null): the certificate of η*(μ), or `not_certified`.
#[pyfunction]
fn certify<'py>(py: Python<'py>, spec: ArchIn, mu: f64, gap: f64) -> PyResult<Bound<'py, PyAny>> {
    let arch = build_arch(&spec)?;
    check_mu(mu).map_err(value_error)?;
    // the command line's range for --gap
    if !(gap.is_finite() && (1e-15..=1e-4).contains(&gap)) {
        return Err(value_error(InputError::OutOfRange {
            arg: "gap",
            value: fmt_value(gap),
            range: "1e-15 <= gap <= 1e-4".into(),
        }));
    }
    let d = py.detach(|| {
        let doc = match certify_eta(&arch, mu, gap, &Settings::default()) {
            Err(why) => json::CertifyJson::not_certified(why.0),
            Ok(cert) => json::CertifyJson::made(&cert, gap, None, None),
        };
        serde_json::to_value(doc).expect("serialisable")
    });
    to_py(py, &d)
}

/// `verify --json` of a certificate given as JSON text; `ValueError` when the text is not
/// a certificate.
#[pyfunction]
fn verify<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    let cert: Certificate = serde_json::from_str(text).map_err(|e| {
        PyValueError::new_err(format!("invalid certificate: not a certificate: {e}"))
    })?;
    let d = py.detach(|| {
        let doc = json::VerifyJson::new(&cert, &verify_cert(&cert));
        serde_json::to_value(doc).expect("serialisable")
    });
    to_py(py, &d)
}

/// Runs one command line of the `arch-enum` binary in-process (`args` without the program
/// name) with the GIL released: (exit code, standard output, standard error). The Python
/// side (`arch_enum/_commands.py`) builds the flags and reads the answer.
#[pyfunction]
fn run_command(py: Python<'_>, args: Vec<String>) -> (i32, Vec<u8>, String) {
    py.detach(|| {
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let argv = std::iter::once("arch-enum".to_string()).chain(args);
        let code = arch_enum::cli::run(argv, &mut out, &mut err);
        (code, out, String::from_utf8_lossy(&err).into_owned())
    })
}

/// The Rust side of the Python package `arch_enum`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("LP_SOLVER", arch_enum::lp::highs::SOLVER)?;
    m.add("JSON_VERSION", JSON_VERSION)?;
    m.add_function(wrap_pyfunction!(arch, m)?)?;
    m.add_function(wrap_pyfunction!(geometry, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(mu_ms, m)?)?;
    m.add_function(wrap_pyfunction!(solve_svg, m)?)?;
    m.add_function(wrap_pyfunction!(solve_compas, m)?)?;
    m.add_function(wrap_pyfunction!(curve, m)?)?;
    m.add_function(wrap_pyfunction!(modes, m)?)?;
    m.add_function(wrap_pyfunction!(atlas, m)?)?;
    m.add_function(wrap_pyfunction!(modes_svg, m)?)?;
    m.add_function(wrap_pyfunction!(assess, m)?)?;
    m.add_function(wrap_pyfunction!(assess_svg, m)?)?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(load_svg, m)?)?;
    m.add_function(wrap_pyfunction!(certify, m)?)?;
    m.add_function(wrap_pyfunction!(verify, m)?)?;
    m.add_function(wrap_pyfunction!(run_command, m)?)?;
    Ok(())
}
