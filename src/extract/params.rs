//! [`ExtractParams`]: every tunable of the pipeline, lengths in metres, in
//! three groups: [`BuildingPriors`] (what the building and its sensor are
//! like: what a user can reason about), [`OutputShape`] (how the spaces are
//! drawn) and [`MethodInternals`] (how the method works; change them only
//! to study it). Reading them from TOML and setting one by name is in
//! `params_file.rs`; their pixel form, in `pixel_config.rs`.

use serde::{Deserialize, Serialize};

use super::error::ExtractError;

/// Which segmentation the pipeline runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The paper's Experiment I (Tab. 1): erosion, opening, connected
    /// components, doors from the opening's XOR.
    Ccl,
    /// The paper's Experiment II (Tab. 2–4): distance transform, marker
    /// watershed, doors at narrow basin boundaries, RAG and refinement.
    #[default]
    Watershed,
}

impl std::str::FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "ccl" => Ok(Method::Ccl),
            "watershed" => Ok(Method::Watershed),
            other => Err(format!(
                "unknown method `{other}` (expected ccl or watershed)"
            )),
        }
    }
}

/// How the watershed method tells doors among the borders of its regions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DoorRule {
    /// A border is a door where it crosses a doorway gap in a wall, or is
    /// door-wide and a constriction of the spaces it joins (the default).
    #[default]
    Constriction,
    /// The paper's Tab. 2: a border is a door where the skeleton of the
    /// free space meets the skeleton of the walls, thickened by
    /// `skeleton_erode_m` and closed across doorways by an opening of
    /// radius `skeleton_open_m` (Tab. 1's `I_opn`).
    Skeleton,
}

/// All parameters of [`crate::extract::extract`]. Lengths are metres and
/// areas square metres, converted to pixels once per map (so one set of
/// defaults serves 0.05 and 0.1 m/px maps alike).
///
/// In TOML (see [`ExtractParams::from_toml`]) the groups are tables,
/// `[building]`, `[output]` and `[internals]`; missing keys take their
/// defaults, and a key may also be written without its table (the names
/// are unique), as parameter files did before the groups.
///
/// ```
/// use nrgdb::extract::ExtractParams;
/// let p = ExtractParams::from_toml("[building]\ndoor_width_max_m = 1.2").unwrap();
/// assert_eq!(p.building.door_width_max_m, 1.2);
/// assert_eq!(p.method, nrgdb::extract::Method::Watershed);
/// let flat = ExtractParams::from_toml("door_width_max_m = 1.2").unwrap();
/// assert_eq!(flat, p);
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ExtractParams {
    /// Segmentation method.
    pub method: Method,
    /// Watershed method: which borders are doors. Default `constriction`.
    pub door_rule: DoorRule,
    /// Maps finer than this are segmented on a copy coarsened by a whole
    /// factor k to about this resolution (k × k cells to one) and the labels
    /// are brought back to the map's pixels: k² times less work, with
    /// polygons at the working resolution. Off (0) by default: the k × k
    /// blocks fall differently on a turned copy of a map, so results would
    /// depend on how the map lies in its image. 0.1 makes a 0.05 m/px map
    /// about 3× faster at the same mean accuracy on the dev maps.
    pub working_resolution_m: f64,
    /// What the building and the sensor are like.
    pub building: BuildingPriors,
    /// How the spaces are drawn.
    pub output: OutputShape,
    /// How the method works inside.
    pub internals: MethodInternals,
}

/// What the building and its sensor are like: door widths, wall thickness,
/// furniture size, what the sensor leaves behind. These are the parameters
/// to change for a building unlike the defaults' (offices, labs and homes
/// mapped by a 2D LiDAR).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BuildingPriors {
    /// Borders narrower than this, or shorter (fewer pixels along the
    /// border, both sides counted), are corner contacts, not doorways: no
    /// door. Default 0.3 m: passages narrower than twice `noise_radius_m`
    /// are removed as noise anyway, and a border's width (twice its largest
    /// distance to an obstacle) runs short of its passage where scan specks
    /// line a doorway on a real map; leave-one-building-out picks 0.25–0.3
    /// over 0.4 for every development building (benches/README.md).
    pub door_width_min_m: f64,
    /// A boundary between two spaces whose passage is at most this wide is a
    /// door; wider boundaries are open connections. Default 1.8 m (double
    /// doors; IPA maps have 1.7 m openings between rooms and corridors).
    pub door_width_max_m: f64,
    /// Widest doorway gap in a wall (see `wall_jamb_m`): the walls on both
    /// sides are evidence a border in open space lacks, so it may be wider
    /// than `door_width_max_m` (IPA's cubicle fronts are 2 m). Default 2.1 m.
    pub wall_gap_width_max_m: f64,
    /// Widest opening in a wall (an open-fronted room or bay, a wide
    /// opening between two rooms): a gap wider than
    /// `wall_gap_width_max_m` and at most this wide, in a wall that goes on
    /// in line for a metre on both sides or ends at a wall across (a
    /// corner), through a wall no thicker than `wall_thickness_max_m`,
    /// with floor on both faces across its whole width, divides the spaces
    /// like a doorway and becomes a door as wide as the opening. A line
    /// joining two wall ends across a corridor (the corridor's side walls
    /// go on past both faces) is no opening. At most `wall_gap_width_max_m`
    /// turns this off. Default 4.0 m: the open fronts and room-to-room
    /// openings of the Intel lab, office_a and FR079 (IPA door recall
    /// 95.18 → 96.02 %, connections 91.84 → 92.70 %; ROSE² door recall
    /// 67.82 → 69.26 %) with no shared map worse; of 150 simulated
    /// buildings one gains a false door and one loses room recall
    /// (`benches/README.md`, "Openings wider than doorways").
    pub opening_width_max_m: f64,
    /// A gap between `door_width_min_m` and `wall_gap_width_max_m` in a
    /// straight wall (along the map's dominant directions) with at least
    /// this much wall on one side and a wall end on the other (a doorway
    /// next to a corner has a jamb only as thick as the wall it meets),
    /// open to free space on both faces of the wall (past both jambs on at
    /// least one face), is a doorway, even where it is as wide as the
    /// corridor it opens onto. 0 turns this off. Default 0.3 m.
    pub wall_jamb_m: f64,
    /// Walls thicker than this hold no doorway gaps (a longer narrow
    /// passage is a corridor); two doors between the same two spaces
    /// closer than this are the two faces of one doorway. Default 0.9 m,
    /// judged leave-one-building-out over 0.6–1.2 m (held out 93.3 % mean
    /// F1 against 93.2 % at 1.2 m; no building worse; ten of 400 simulated
    /// buildings lose a false door, such as house 22's from a bed 1.1 m
    /// deep against a wall to the wall across; `benches/README.md`, "Walls
    /// up to 0.9 m hold doorway gaps").
    pub wall_thickness_max_m: f64,
    /// Obstacle islands (not joined to any wall) whose bounding box is at
    /// most this long on both sides are furniture: rooms are segmented as if
    /// they were free, and own the pixels under them. 0 turns this off.
    /// Default 1.0 m: chair and table legs, boxes and pillars, but not the
    /// 1.2 m wall pieces left between neighbouring doorways.
    pub furniture_max_m: f64,
    /// Larger islands up to this long on both sides are clutter (clusters
    /// of chairs, tables and shelves on a real robot map) and treated like
    /// furniture, unless they look like walls: a straight bar, a solid
    /// block, or on the lines the building's walls run along (ROSE²'s
    /// decluttering; see `extract/clutter.rs`). At most `furniture_max_m`
    /// turns this off. Default 0 (off): leave-one-building-out over the
    /// shared maps does not pick it (held-out 90.5 % at 2.5 m against
    /// 90.6 % off), though on cluttered real maps 2.5 m cuts false doors
    /// between furniture clusters (ROSE² door precision 57.4 → 65.3 %;
    /// `benches/README.md`).
    pub clutter_max_m: f64,
    /// A passage narrower than `door_width_max_m` and at least this long
    /// (its area over its width) that opens into wider space, with one
    /// opening (a corridor stub) or two into different spaces (a strip
    /// corridor between a room and a corridor), is a space of its own, with
    /// a door where it opens out: the watershed floods straight into it and
    /// leaves no border there. A passage opening twice into the same space
    /// is an aisle of that space and stays in it. 0 turns this off.
    /// Default 3.0 m (door recall on the IPA maps 92.3 % without, 95.2 %
    /// with; the same from 2 to 3 m).
    pub passage_min_length_m: f64,
    /// Spaces smaller than this merge into their longest-bordering neighbour
    /// (small rooms above it are kept). Default 1.0 m².
    pub min_room_area_m2: f64,
    /// Free space narrower than twice this is noise (LiDAR rays leaking into
    /// unknown space, speckle) and is removed by an opening. Default 0.2 m.
    pub noise_radius_m: f64,
    /// Unknown pockets inside the building (the insides of furniture, what
    /// the sensor could not see) of at most this area join the spaces
    /// around them; unknown joined to the image border is outside and stays
    /// out. 0 turns this off. Default 4.0 m².
    pub unknown_pocket_max_m2: f64,
}

/// How the spaces are drawn.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct OutputShape {
    /// Least thickness of a door space across the doorway. A door spans
    /// its doorway from one face of the wall to the other, so it is as
    /// thick as the wall, and at least this where the wall is thinner, the
    /// opening is a passage running on past 0.7 m (a corridor stub: the door
    /// stays at its mouth) or the border crosses open space. Default 0.1 m:
    /// a door is a transition, and a thick one takes floor from the rooms
    /// it joins. The diff matches doors by their doorway line, not their
    /// area, so thin doors are no harder to follow across revisions.
    pub door_depth_m: f64,
    /// Douglas–Peucker tolerance for polygons. Default 0.05 m.
    pub simplify_m: f64,
}

/// How the method works inside: thresholds of its rules, each judged on
/// the development maps (see `benches/README.md`). Change them to study
/// the method, not to describe a building.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MethodInternals {
    /// Room cores are the places farther than this from any obstacle; a
    /// passage narrower than twice this separates two spaces. Default 0.5 m.
    pub core_radius_m: f64,
    /// A room core that splits, at a higher distance level, into parts of at
    /// least this area becomes one space per part (rooms joined by a doorway
    /// wider than `2 core_radius_m`). Default 1.0 m².
    pub split_min_core_m2: f64,
    /// A border is a door only where it is a constriction: at most this
    /// fraction of the widest passage of the narrower space on either side,
    /// near the border (within 2.5 widest doors: a corridor that opens
    /// into a hall further on is as wide as it is where the border is), so
    /// a corridor's own width, between two parts of it, is no door, and
    /// such a border joins the two. 1 = any border under
    /// `door_width_max_m`. Default 0.7.
    pub door_constriction: f64,
    /// Stretches of border between the same two spaces closer than this are
    /// one doorway (a speck of noise does not make two doors); farther apart
    /// they are separate doors. Default 0.5 m.
    pub door_join_m: f64,
    /// Two regions of the watershed that meet across a border no doorway
    /// divides are one space: a border wider than `door_width_max_m` at
    /// least this fraction of the narrower region's widest inscribed
    /// diameter near the border (as for `door_constriction`), or a
    /// narrower border that is no constriction (see
    /// `door_constriction`), and no doorway gap. Such borders are where the
    /// floods of a corridor loop or an open hall met. 0 turns this off.
    /// Default 0.5: room recall on the IPA maps 96.90 % kept apart, 97.67 %
    /// joined.
    pub open_join_fraction: f64,
    /// Free components smaller than this are dropped. Default 1.0 m².
    pub min_free_area_m2: f64,
    /// A non-door space of degree ≥ 2 is a corridor only if its area over
    /// the square of its widest inscribed diameter (with the clutter standing
    /// in it filled: a furnished office is as wide as its walls) is at least
    /// this, and the longest walk inside it is at least four times its mean
    /// width (area over that walk: a room lined with shelves or a living
    /// area with an alcove is no corridor). 0 turns both off: the paper's
    /// pure degree rule. Default 2.5.
    pub corridor_min_elongation: f64,
    /// CCL method: erosion radius (thickens walls). Default 0.1 m.
    pub ccl_erode_m: f64,
    /// CCL method: opening radius (cuts doorways). Default 0.5 m.
    pub ccl_open_m: f64,
    /// `door_rule = "skeleton"`: erosion radius of the free space before
    /// the opening (thickens walls so that the opening can plug a doorway
    /// through a thin wall). Default 0.25 m.
    pub skeleton_erode_m: f64,
    /// `door_rule = "skeleton"`: opening radius; doorways narrower than
    /// about twice this (after the erosion) are plugged. Default 0.5 m.
    pub skeleton_open_m: f64,
}

impl Default for ExtractParams {
    fn default() -> Self {
        ExtractParams {
            method: Method::Watershed,
            door_rule: DoorRule::Constriction,
            working_resolution_m: 0.0,
            building: BuildingPriors::default(),
            output: OutputShape::default(),
            internals: MethodInternals::default(),
        }
    }
}

impl Default for BuildingPriors {
    fn default() -> Self {
        BuildingPriors {
            door_width_min_m: 0.3,
            door_width_max_m: 1.8,
            wall_gap_width_max_m: 2.1,
            opening_width_max_m: 4.0,
            wall_jamb_m: 0.3,
            wall_thickness_max_m: 0.9,
            furniture_max_m: 1.0,
            clutter_max_m: 0.0,
            passage_min_length_m: 3.0,
            min_room_area_m2: 1.0,
            noise_radius_m: 0.2,
            unknown_pocket_max_m2: 4.0,
        }
    }
}

impl Default for OutputShape {
    fn default() -> Self {
        OutputShape {
            door_depth_m: 0.1,
            simplify_m: 0.05,
        }
    }
}

impl Default for MethodInternals {
    fn default() -> Self {
        MethodInternals {
            core_radius_m: 0.5,
            split_min_core_m2: 1.0,
            door_constriction: 0.7,
            door_join_m: 0.5,
            open_join_fraction: 0.5,
            min_free_area_m2: 1.0,
            corridor_min_elongation: 2.5,
            ccl_erode_m: 0.1,
            ccl_open_m: 0.5,
            skeleton_erode_m: 0.25,
            skeleton_open_m: 0.5,
        }
    }
}

/// Parameters that are fractions (0 to 1).
const FRACTIONS: [&str; 2] = [
    "internals.door_constriction",
    "internals.open_join_fraction",
];

impl ExtractParams {
    /// Every number with its name as `--set` takes it (`group.key`).
    fn numbers(&self) -> [(&'static str, f64); 26] {
        let (b, o, i) = (&self.building, &self.output, &self.internals);
        [
            ("working_resolution_m", self.working_resolution_m),
            ("building.door_width_min_m", b.door_width_min_m),
            ("building.door_width_max_m", b.door_width_max_m),
            ("building.wall_gap_width_max_m", b.wall_gap_width_max_m),
            ("building.opening_width_max_m", b.opening_width_max_m),
            ("building.wall_jamb_m", b.wall_jamb_m),
            ("building.wall_thickness_max_m", b.wall_thickness_max_m),
            ("building.furniture_max_m", b.furniture_max_m),
            ("building.clutter_max_m", b.clutter_max_m),
            ("building.passage_min_length_m", b.passage_min_length_m),
            ("building.min_room_area_m2", b.min_room_area_m2),
            ("building.noise_radius_m", b.noise_radius_m),
            ("building.unknown_pocket_max_m2", b.unknown_pocket_max_m2),
            ("output.door_depth_m", o.door_depth_m),
            ("output.simplify_m", o.simplify_m),
            ("internals.core_radius_m", i.core_radius_m),
            ("internals.split_min_core_m2", i.split_min_core_m2),
            ("internals.door_constriction", i.door_constriction),
            ("internals.door_join_m", i.door_join_m),
            ("internals.open_join_fraction", i.open_join_fraction),
            ("internals.min_free_area_m2", i.min_free_area_m2),
            (
                "internals.corridor_min_elongation",
                i.corridor_min_elongation,
            ),
            ("internals.ccl_erode_m", i.ccl_erode_m),
            ("internals.ccl_open_m", i.ccl_open_m),
            ("internals.skeleton_erode_m", i.skeleton_erode_m),
            ("internals.skeleton_open_m", i.skeleton_open_m),
        ]
    }

    /// Checks every parameter: lengths, areas and factors finite and
    /// non-negative, fractions ([`MethodInternals::door_constriction`],
    /// [`MethodInternals::open_join_fraction`]) at most 1, and each least
    /// value at most its greatest (`door_width_min_m` ≤ `door_width_max_m`,
    /// `door_width_min_m` ≤ `wall_gap_width_max_m`, `door_depth_m` ≤
    /// `wall_thickness_max_m`). A minimum above its maximum would silently
    /// find nothing (no door is both at least 2.5 m and at most 1.8 m wide).
    /// Errors name parameters as `--set` takes them (`building.door_width_min_m`).
    ///
    /// ```
    /// use nrgdb::extract::{BuildingPriors, ExtractError, ExtractParams};
    /// let p = ExtractParams {
    ///     building: BuildingPriors { door_width_min_m: 2.5, ..BuildingPriors::default() },
    ///     ..ExtractParams::default()
    /// };
    /// let e = p.validate().unwrap_err();
    /// assert!(matches!(e, ExtractError::ParamsOutOfOrder { low: "building.door_width_min_m", .. }));
    /// assert!(ExtractParams::default().validate().is_ok());
    /// ```
    pub fn validate(&self) -> Result<(), ExtractError> {
        let fields = self.numbers();
        if let Some((name, value)) = fields
            .iter()
            .copied()
            .find(|(_, v)| !(v.is_finite() && *v >= 0.0))
        {
            return Err(ExtractError::BadParam { name, value });
        }
        if let Some((name, value)) = fields
            .iter()
            .copied()
            .find(|(name, v)| FRACTIONS.contains(name) && *v > 1.0)
        {
            return Err(ExtractError::NotAFraction { name, value });
        }
        let (b, o) = (&self.building, &self.output);
        let ordered = [
            (
                ("building.door_width_min_m", b.door_width_min_m),
                ("building.door_width_max_m", b.door_width_max_m),
            ),
            (
                ("building.door_width_min_m", b.door_width_min_m),
                ("building.wall_gap_width_max_m", b.wall_gap_width_max_m),
            ),
            (
                ("output.door_depth_m", o.door_depth_m),
                ("building.wall_thickness_max_m", b.wall_thickness_max_m),
            ),
        ];
        match ordered.into_iter().find(|((_, lo), (_, hi))| lo > hi) {
            Some(((low, low_value), (high, high_value))) => Err(ExtractError::ParamsOutOfOrder {
                low,
                low_value,
                high,
                high_value,
            }),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(p: ExtractParams) -> String {
        p.validate()
            .map_or_else(|e| e.to_string(), |()| "ok".into())
    }

    fn building(b: BuildingPriors) -> ExtractParams {
        ExtractParams {
            building: b,
            ..ExtractParams::default()
        }
    }

    #[test]
    fn contradictions_and_fractions_are_refused_with_both_names() {
        let d = BuildingPriors::default;
        assert_eq!(check(ExtractParams::default()), "ok");
        let m = check(building(BuildingPriors {
            door_width_min_m: 2.5,
            ..d()
        }));
        assert!(
            m.contains("`building.door_width_min_m` = 2.5")
                && m.contains("`building.door_width_max_m` = 1.8"),
            "{m}"
        );
        // Doors up to 2.5 m, wall gaps only up to 2.1 m: gaps at least
        // 2.2 m wide could never be found.
        let m = check(building(BuildingPriors {
            door_width_min_m: 2.2,
            door_width_max_m: 2.5,
            ..d()
        }));
        assert!(m.contains("`building.wall_gap_width_max_m` = 2.1"), "{m}");
        let m = check(ExtractParams {
            output: OutputShape {
                door_depth_m: 1.5,
                ..OutputShape::default()
            },
            ..ExtractParams::default()
        });
        assert!(m.contains("`building.wall_thickness_max_m` = 0.9"), "{m}");
        let internals = |i: MethodInternals| ExtractParams {
            internals: i,
            ..ExtractParams::default()
        };
        for (name, p) in [
            (
                "door_constriction",
                internals(MethodInternals {
                    door_constriction: 1.5,
                    ..MethodInternals::default()
                }),
            ),
            (
                "open_join_fraction",
                internals(MethodInternals {
                    open_join_fraction: 2.0,
                    ..MethodInternals::default()
                }),
            ),
        ] {
            let m = check(p);
            assert!(m.contains(name) && m.contains("fraction"), "{m}");
        }
        // Equal bounds and a fraction of exactly 1 are fine.
        let mut p = building(BuildingPriors {
            door_width_min_m: 1.8,
            ..d()
        });
        p.internals.door_constriction = 1.0;
        assert_eq!(check(p), "ok");
        let m = check(building(BuildingPriors {
            noise_radius_m: f64::NAN,
            ..d()
        }));
        assert!(m.contains("building.noise_radius_m"), "{m}");
    }
}
