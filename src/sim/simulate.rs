//! The whole simulation: plan → route → LiDAR scans → log-odds map, and
//! writing it with its ground truth.

use std::path::{Path, PathBuf};

use super::SimError;
use super::floor_plan::{FloorPlan, FloorPlanParams};
use super::ground_truth::ground_truth_image;
use super::lidar::{LidarParams, simulate_scans};
use super::log_odds::{GreyMap, LogOddsMap, LogOddsParams};
use super::map_writer::{create_dir, encode_grey_png, encode_pgm, map_yaml, write_file};
use super::ray_cast::WallIndex;
use super::robot_path::sample_poses;

/// Everything [`simulate`] needs.
#[derive(Debug, Clone, PartialEq)]
pub struct SimParams {
    /// The building.
    pub plan: FloorPlanParams,
    /// The sensor.
    pub lidar: LidarParams,
    /// The mapper.
    pub mapper: LogOddsParams,
    /// Map resolution, metres per cell.
    pub resolution_m: f64,
    /// Distance between scans along the route, metres.
    pub pose_step_m: f64,
    /// Unknown border around the building, metres.
    pub margin_m: f64,
}

impl SimParams {
    /// Defaults for `seed`: 0.05 m/px, a scan every 0.3 m, 1 m border.
    pub fn new(seed: u64) -> SimParams {
        let lidar = LidarParams {
            seed,
            ..LidarParams::default()
        };
        let mapper = LogOddsParams {
            usable_range_m: lidar.max_range_m,
            ..LogOddsParams::default()
        };
        SimParams {
            plan: FloorPlanParams::new(seed),
            lidar,
            mapper,
            resolution_m: 0.05,
            pose_step_m: 0.3,
            margin_m: 1.0,
        }
    }
}

/// A simulated building and the map the robot built of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    /// The true floor plan ([`FloorPlan::truth`] gives the NRG).
    pub plan: FloorPlan,
    /// The occupancy map from the log-odds mapper.
    pub map: GreyMap,
    /// Scans taken.
    pub scans: usize,
    /// Beams integrated into the map.
    pub beams: usize,
}

/// Generates the plan, drives the route, scans and maps (all in memory,
/// deterministic in the seeds).
///
/// ```
/// use nrgdb::sim::{SimParams, simulate};
/// let mut p = SimParams::new(1);
/// p.plan.wings = (1, 1);
/// p.plan.corridor_length_m = (8.0, 8.0);
/// p.resolution_m = 0.1;
/// let sim = simulate(&p)?;
/// assert!(sim.map.grey.contains(&254) && sim.map.grey.contains(&0));
/// # Ok::<(), nrgdb::sim::SimError>(())
/// ```
pub fn simulate(params: &SimParams) -> Result<Simulation, SimError> {
    params.lidar.validate()?;
    if !(params.pose_step_m > 0.0 && params.pose_step_m.is_finite()) {
        return Err(SimError::BadParameter {
            name: "pose_step_m",
            value: params.pose_step_m.to_string(),
            expected: "a finite number > 0",
            hint: "0.3 m is the default",
        });
    }
    let plan = FloorPlan::generate(&params.plan)?;
    let mut grid = LogOddsMap::covering(
        plan.bounds(),
        params.margin_m.max(0.0),
        params.resolution_m,
        params.mapper.clone(),
    )?;
    let walls = WallIndex::new(plan.walls(), 1.0);
    let poses = sample_poses(&plan.route, params.pose_step_m);
    let scans = simulate_scans(&walls, &poses, &params.lidar);
    let beams = scans.iter().map(|s| grid.integrate(s)).sum();
    Ok(Simulation {
        map: grid.to_grey(),
        plan,
        scans: scans.len(),
        beams,
    })
}

/// The files [`write_simulation`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct SimFiles {
    /// `map.yaml`.
    pub yaml: PathBuf,
    /// `map.pgm`.
    pub pgm: PathBuf,
    /// `map_gt.png` (IPA ground-truth format).
    pub gt_png: PathBuf,
    /// `truth.json` (the true NRG in the model's JSON form).
    pub truth_json: PathBuf,
}

/// Writes `map.yaml`, `map.pgm`, `map_gt.png` and `truth.json` into `dir`
/// (created if missing). Everything is encoded before the first write and
/// each file is written atomically.
pub fn write_simulation(dir: &Path, sim: &Simulation) -> Result<SimFiles, SimError> {
    let files = SimFiles {
        yaml: dir.join("map.yaml"),
        pgm: dir.join("map.pgm"),
        gt_png: dir.join("map_gt.png"),
        truth_json: dir.join("truth.json"),
    };
    let truth = sim.plan.truth()?.to_json();
    let gt = ground_truth_image(&sim.plan, &sim.map);
    let png = encode_grey_png(sim.map.width, sim.map.height, &gt, &files.gt_png)?;
    let pgm = encode_pgm(&sim.map);
    let yaml = map_yaml("map.pgm", &sim.map);
    create_dir(dir)?;
    write_file(&files.pgm, &pgm)?;
    write_file(&files.yaml, yaml.as_bytes())?;
    write_file(&files.gt_png, &png)?;
    write_file(&files.truth_json, truth.as_bytes())?;
    Ok(files)
}
