//! A multi-storey building to test with (issue 25): the same floor plan on
//! every level, so stairwells and lift shafts line up, each level mapped
//! by its own robot run (its own sensor noise), and a building manifest
//! (`building.toml`) that `nrgdb import` takes as it is. The smallest room
//! of the plan is the stairwell, the next smallest the lift shaft; the
//! connectors stand at their rooms' true anchors.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::SimError;
use super::simulate::{SimFiles, SimParams, simulate, write_simulation};
use crate::model::SpaceKind;

/// Most levels simulated.
pub const MAX_SIM_LEVELS: usize = 50;

/// Height between floors, metres.
pub const STOREY_HEIGHT_M: f64 = 3.5;

/// What [`write_storeys`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct StoreyFiles {
    /// The building manifest.
    pub manifest: PathBuf,
    /// Each level's files (`level0/`, `level1/`, …), lowest first.
    pub levels: Vec<SimFiles>,
    /// Where the stairs and the lift stand (map frame, metres).
    pub stairs_at: [f64; 2],
    /// Where the lift stands.
    pub lift_at: [f64; 2],
}

/// Simulates `levels` floors of the building `params` describes into
/// `dir` and writes their manifest (see the module docs). Level `k` is
/// named `k`, at `k` × [`STOREY_HEIGHT_M`]; its sensor seed is the plan's
/// plus `k`.
pub fn write_storeys(
    dir: &Path,
    params: &SimParams,
    levels: usize,
) -> Result<StoreyFiles, SimError> {
    if !(2..=MAX_SIM_LEVELS).contains(&levels) {
        return Err(SimError::BadParameter {
            name: "--levels",
            value: levels.to_string(),
            expected: "between 2 and 50",
            hint: "a building of one level is a plain `nrgdb simulate`",
        });
    }
    let mut files = Vec::with_capacity(levels);
    let mut truth = None;
    for k in 0..levels {
        let mut p = params.clone();
        p.lidar.seed = params.lidar.seed.wrapping_add(k as u64);
        let sim = simulate(&p)?;
        if truth.is_none() {
            truth = Some(sim.plan.truth()?);
        }
        files.push(write_simulation(&dir.join(format!("level{k}")), &sim)?);
    }
    let truth = truth.unwrap_or_default();
    let mut rooms: Vec<_> = truth
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Room)
        .collect();
    rooms.sort_by(|a, b| a.area_m2.total_cmp(&b.area_m2).then(a.id.cmp(&b.id)));
    let [stairs, lift] = match rooms.as_slice() {
        [a, b, ..] => [a.anchor, b.anchor],
        _ => {
            return Err(SimError::BadParameter {
                name: "--seed",
                value: params.plan.seed.to_string(),
                expected: "a plan with two rooms or more",
                hint: "try another seed",
            });
        }
    };
    let mut toml =
        String::from("# A simulated building: `nrgdb import building.toml --map NAME`.\n");
    for k in 0..levels {
        let _ = write!(
            toml,
            "\n[[level]]\nname = \"{k}\"\nelevation_m = {:.1}\nmap = \"level{k}/map.yaml\"\n",
            k as f64 * STOREY_HEIGHT_M
        );
    }
    let names: Vec<String> = (0..levels).map(|k| format!("\"{k}\"")).collect();
    let _ = write!(
        toml,
        "\n[[elevator]]\nname = \"Lift A\"\nat = [{:.3}, {:.3}]\nlevels = [{}]\n",
        lift[0],
        lift[1],
        names.join(", ")
    );
    for k in 1..levels {
        let _ = write!(
            toml,
            "\n[[stairs]]\nname = \"Stairs\"\nfrom = {{ at = [{x:.3}, {y:.3}], level = \"{}\" }}\nto = {{ at = [{x:.3}, {y:.3}], level = \"{k}\" }}\n",
            k - 1,
            x = stairs[0],
            y = stairs[1],
        );
    }
    let manifest = dir.join("building.toml");
    crate::atomic::write(&manifest, toml.as_bytes()).map_err(|source| SimError::Io {
        path: manifest.clone(),
        source,
    })?;
    Ok(StoreyFiles {
        manifest,
        levels: files,
        stairs_at: stairs,
        lift_at: lift,
    })
}
