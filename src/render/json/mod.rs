//! The JSON shapes of the command-line contract (`shared/spec/cli.md`), one file per
//! command; the arch, the error document and the limit state's parts are shared.
//! Angles in radians; `null` stands for +∞.

mod assess;
mod atlas;
mod bridge;
mod certificate;
mod common;
mod curve;
mod load;
mod load_curve;
mod load_map;
mod modes;
mod modes_fill;
mod schema;
mod solve;
mod state;

pub use assess::{assess, AssessJson};
pub use atlas::{atlas, AtlasJson};
pub use bridge::{bridge, status as influence_status, BridgeJson, FillJson, VehicleJson, SCOPE};
pub use certificate::{CertifyJson, VerifyJson};
pub use common::{status, ArchJson, ErrorJson, JSON_VERSION};
pub use curve::{curve, CurveJson};
pub use load::{load, LoadDoc};
pub(crate) use load_curve::curve_row;
pub use load_curve::{load_curve, LoadCurveDoc, LoadCurveRow};
pub use load_map::{load_map, LoadMapJson};
pub use modes::{modes, ModesJson};
pub use modes_fill::{modes_fill, FillModesJson};
pub use schema::schema;
pub use solve::{solve, SolveJson};
