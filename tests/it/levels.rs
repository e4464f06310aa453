//! Buildings with floors (issue 25): levels in the model, kept through
//! model JSON and IndoorGML (3D polygons at each level's elevation, the
//! level in the cell's description), a document of stacked 3D floors read
//! as its levels, and the checker judging overlaps floor by floor.

use nrgdb::format::{ModelFormat, model_from_bytes, render};
use nrgdb::model::{ConnectionKind, SpaceKind};
use nrgdb::route::walked_model;

use crate::support::shared_dir;

#[test]
fn a_three_storey_building_goes_through_indoorgml_whole() {
    let nrg = nrgdb::fixtures::storeys(3, 4);
    let walked = walked_model(&nrg);
    let gml = render(&walked, ModelFormat::IndoorGml);
    // Level 2's cells lie at 7 m.
    assert!(gml.contains(r#"srsDimension="3""#));
    assert!(gml.contains(" 7 ") || gml.contains(" 7\n") || gml.contains(" 7<"));
    let doc = nrgdb::indoorgml::read_str(&gml).unwrap();
    assert!(
        nrgdb::indoorgml::check(&doc).is_empty(),
        "{:?}",
        nrgdb::indoorgml::check(&doc)
    );
    let (back, _) =
        model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "t.gml".as_ref()).unwrap();
    assert_eq!(back, walked.nrg);
    assert_eq!(back.levels().len(), 3);
    let vertical = back
        .connections()
        .iter()
        .filter(|c| c.kind == ConnectionKind::Vertical)
        .count();
    assert_eq!(vertical, 5);
    // Walking does not flatten a climb: stairs keep their cost.
    for (c, w) in nrg.connections().iter().zip(back.connections()) {
        if c.kind == ConnectionKind::Vertical {
            assert_eq!(c.length_m, w.length_m, "{}-{}", c.a, c.b);
        }
    }
    // Floors stacked on one plane would overlap; per level they do not.
    let stairs = back
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Stairs)
        .count();
    assert_eq!(stairs, 3);
}

#[test]
fn levels_come_from_the_heights_of_a_3d_document() {
    // Two floors written at 0 m and 3.5 m without the level extras, as
    // another program writes stacked floors.
    let nrg = nrgdb::fixtures::storeys(2, 3);
    let gml = render(&walked_model(&nrg), ModelFormat::IndoorGml);
    let mut doc = nrgdb::indoorgml::read_str(&gml).unwrap();
    for cell in &mut doc.primal.as_mut().unwrap().cells {
        let text = cell.info.description.take().unwrap();
        let mut value: serde_json::Value = serde_json::from_str(&text).unwrap();
        value
            .as_object_mut()
            .unwrap()
            .remove("nrgdb:level")
            .unwrap();
        if value.as_object().is_some_and(|o| !o.is_empty()) {
            cell.info.description = Some(value.to_string());
        }
    }
    let gml = nrgdb::indoorgml::write_string(&doc);
    assert!(!gml.contains("nrgdb:level"), "the extras are gone");
    let (back, _) =
        model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "t.gml".as_ref()).unwrap();
    let levels = back.levels();
    assert_eq!(
        levels
            .iter()
            .map(|l| (l.name.as_str(), l.elevation_m))
            .collect::<Vec<_>>(),
        [("0", 0.0), ("1", 3.5)]
    );
    assert_eq!(back.spaces().len(), nrg.spaces().len());
    // Cells that name their storey (`storey="…"`, as the InFactory/KU
    // tools write it) give the levels those names; a floor whose cells
    // disagree keeps the numbering.
    let storey = |doc: &mut nrgdb::indoorgml::Document, name_of: &dyn Fn(usize, f64) -> String| {
        for (k, cell) in doc.primal.as_mut().unwrap().cells.iter_mut().enumerate() {
            // The cell's height: the z of its first position (2D cells
            // written at their level's elevation).
            let z = match &cell.geometry {
                Some(nrgdb::indoorgml::document::CellGeometry::Surface(p)) => p.exterior.values[2],
                other => panic!("a surface cell, got {other:?}"),
            };
            cell.info.description = Some(format!("storey=\"{}\":indoor=\"room\":", name_of(k, z)));
        }
        let gml = nrgdb::indoorgml::write_string(doc);
        let (nrg, _) =
            model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "t.gml".as_ref()).unwrap();
        let levels: Vec<(String, f64)> = nrg
            .levels()
            .into_iter()
            .map(|l| (l.name, l.elevation_m))
            .collect();
        levels
    };
    let mut named = doc.clone();
    let by_floor = |_: usize, z: f64| {
        if z < 1.0 {
            "EG".to_string()
        } else {
            "OG1".to_string()
        }
    };
    assert_eq!(
        storey(&mut named, &by_floor),
        [("EG".to_string(), 0.0), ("OG1".to_string(), 3.5)]
    );
    let mut mixed = doc.clone();
    let disagree = |k: usize, z: f64| {
        if k == 0 {
            "X".to_string()
        } else {
            by_floor(k, z)
        }
    };
    assert_eq!(
        storey(&mut mixed, &disagree),
        [("0".to_string(), 0.0), ("1".to_string(), 3.5)]
    );
}

/// The cells of an IndoorGML text per floor, counted from the text itself
/// (each `cellSpaceMember`'s lowest `gml:pos` z), lowest floor first.
fn cells_per_floor(text: &str) -> Vec<(f64, usize)> {
    let mut floors: std::collections::BTreeMap<i64, usize> = Default::default();
    for member in text.split("<core:cellSpaceMember>").skip(1) {
        let member = member.split("</core:cellSpaceMember>").next().unwrap();
        let lowest = member
            .split("<gml:pos")
            .skip(1)
            .filter_map(|p| {
                let body = &p[p.find('>')? + 1..p.find('<')?];
                body.split_whitespace().nth(2)?.parse::<f64>().ok()
            })
            .reduce(f64::min)
            .expect("a cell with 3D positions");
        *floors.entry((lowest * 1000.0).round() as i64).or_default() += 1;
    }
    floors
        .into_iter()
        .map(|(z, n)| (z as f64 / 1000.0, n))
        .collect()
}

#[test]
fn sample_201_reads_as_its_three_floors() {
    let Some(shared) = shared_dir("indoorgml/samples/201-2019-05-24-corrected.gml") else {
        return;
    };
    let path = shared.join("indoorgml/samples/201-2019-05-24-corrected.gml");
    let bytes = std::fs::read(&path).unwrap();
    let (nrg, _) = model_from_bytes(&bytes, ModelFormat::IndoorGml, &path).unwrap();
    // The file: 80 cells (MANIFEST.md), on three floors.
    assert_eq!(nrg.spaces().len(), 80);
    let levels = nrg.levels();
    assert_eq!(levels.len(), 3, "{levels:?}");
    let mut per_level: Vec<usize> = levels
        .iter()
        .map(|l| {
            nrg.spaces()
                .iter()
                .filter(|s| s.level.as_ref().is_some_and(|m| m.name == l.name))
                .count()
        })
        .collect();
    eprintln!("201: levels {levels:?}, spaces per level {per_level:?}");
    // Each level holds exactly the cells the file has on that floor, and
    // is named by the storey its cells give (1, 2, 3).
    let text = std::str::from_utf8(&bytes).unwrap();
    let floors = cells_per_floor(text);
    assert_eq!(floors.len(), 3, "{floors:?}");
    let ours: Vec<(f64, usize)> = levels
        .iter()
        .map(|l| l.elevation_m)
        .zip(per_level.iter().copied())
        .collect();
    assert_eq!(ours, floors);
    let names: Vec<&str> = levels.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["1", "2", "3"]);
    // Imported (its overlaps repaired, as the import says) and exported,
    // it keeps its floors: our checker and the OGC schema accept the
    // file, which holds the same number of cells on each floor.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let db = ["--db", "t.sqlite"];
    let absolute = path.canonicalize().unwrap();
    let path_text = absolute.to_str().unwrap();
    let (ok, said) = run(
        d,
        &[&["import", path_text, "--map", "b201"][..], &db].concat(),
    );
    assert!(ok, "{said}");
    let (ok, said) = run(
        d,
        &[&["export", "b201", "--out", "b201.gml"][..], &db].concat(),
    );
    assert!(ok, "{said}");
    let (ok, said) = run(d, &["check", "b201.gml"]);
    assert!(ok, "{said}");
    crate::support::schema_valid_if_shared(&d.join("b201.gml"));
    let gml = std::fs::read_to_string(d.join("b201.gml")).unwrap();
    assert_eq!(cells_per_floor(&gml), floors);
    let (back, _) =
        model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "b201.gml".as_ref()).unwrap();
    assert_eq!(back.levels(), nrg.levels());
    per_level.sort_unstable();
    assert!(per_level[0] >= 10, "{per_level:?}");
}

/// Runs nrgdb in `dir` and returns (success, stdout + stderr).
fn run(dir: &std::path::Path, args: &[&str]) -> (bool, String) {
    let out = crate::support::nrgdb(dir, args);
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr),
    )
}

fn model(dir: &std::path::Path, file: &str) -> nrgdb::model::Nrg {
    nrgdb::model::Nrg::from_json(&std::fs::read_to_string(dir.join(file)).unwrap()).unwrap()
}

#[test]
fn a_simulated_tower_imports_from_its_manifest_level_by_level() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (ok, said) = run(
        d,
        &["simulate", "--levels", "3", "--seed", "3", "--out", "sim"],
    );
    assert!(ok, "{said}");
    let db = ["--db", "t.sqlite"];
    let (ok, said) = run(
        d,
        &[&["import", "sim/building.toml", "--map", "tower"][..], &db].concat(),
    );
    assert!(ok, "{said}");
    // Each level alone, as the single-floor import extracts it.
    let (ok, said) = run(
        d,
        &[&["import", "sim/level0/map.yaml", "--map", "flat"][..], &db].concat(),
    );
    assert!(ok, "{said}");
    assert!(
        run(
            d,
            &[&["export", "tower", "--out", "tower.json"][..], &db].concat()
        )
        .0
    );
    assert!(
        run(
            d,
            &[&["export", "flat", "--out", "flat.json"][..], &db].concat()
        )
        .0
    );
    let (tower, flat) = (model(d, "tower.json"), model(d, "flat.json"));
    let levels = tower.levels();
    assert_eq!(
        levels
            .iter()
            .map(|l| (l.name.as_str(), l.elevation_m))
            .collect::<Vec<_>>(),
        [("0", 0.0), ("1", 3.5), ("2", 7.0)]
    );
    let on = |name: &str| {
        tower
            .spaces()
            .iter()
            .filter(|s| s.level.as_ref().is_some_and(|l| l.name == name))
            .count()
    };
    assert_eq!(on("0"), flat.spaces().len());
    // The stairwell and the lift shaft on every level, joined: stairs
    // between neighbours (3.5 m of rise: 14 m), the lift between every pair.
    let count = |k: SpaceKind| tower.spaces().iter().filter(|s| s.kind == k).count();
    assert_eq!(
        (count(SpaceKind::Stairs), count(SpaceKind::Elevator)),
        (3, 3)
    );
    let mut vertical: Vec<(SpaceKind, f64)> = tower
        .connections()
        .iter()
        .filter(|c| c.kind == ConnectionKind::Vertical)
        .map(|c| (tower.space(c.a).unwrap().kind, c.length_m))
        .collect();
    vertical.sort_by(|a, b| a.1.total_cmp(&b.1));
    let expected = [
        (SpaceKind::Stairs, nrgdb::model::stairs_length_m(3.5)),
        (SpaceKind::Stairs, nrgdb::model::stairs_length_m(3.5)),
        (SpaceKind::Elevator, nrgdb::model::elevator_length_m(1)),
        (SpaceKind::Elevator, nrgdb::model::elevator_length_m(1)),
        (SpaceKind::Elevator, nrgdb::model::elevator_length_m(2)),
    ];
    assert_eq!(vertical.len(), expected.len(), "{vertical:?}");
    for (got, want) in vertical.iter().zip(&expected) {
        assert_eq!(got.0, want.0);
        assert!((got.1 - want.1).abs() < 1e-9, "{got:?} vs {want:?}");
    }
    // Where a point is, level by level; FIND by level.
    let stairs1 = tower
        .spaces()
        .iter()
        .find(|s| s.kind == SpaceKind::Stairs && s.level.as_ref().unwrap().name == "1")
        .unwrap();
    let [x, y] = stairs1.anchor;
    let query = |q: &str| run(d, &["query", "--db", "t.sqlite", "--map", "tower", q]);
    let (ok, said) = query(&format!("LOCATE ({x}, {y}) ON LEVEL 1"));
    assert!(ok, "{said}");
    let rows: Vec<&str> = said.lines().filter(|l| l.contains("stairs")).collect();
    assert_eq!(rows.len(), 1, "{said}");
    assert!(
        rows[0].trim_start().starts_with(&stairs1.id.to_string()),
        "{said}"
    );
    let (ok, said) = query(&format!("LOCATE ({x}, {y})"));
    assert!(
        ok && said.contains("(3 rows)"),
        "one space on each level: {said}"
    );
    let (ok, said) = query("FIND stairs WHERE level = 2");
    assert!(ok && said.contains("(1 row)"), "{said}");
    let (ok, said) = query("FIND spaces WHERE level = \"0\"");
    assert!(
        ok && said.contains(&format!("({} rows)", flat.spaces().len())),
        "{said}"
    );
    // One picture a level.
    let (ok, said) = run(
        d,
        &[
            &["render", "tower", "--out", "l1.png", "--level", "1"][..],
            &db,
        ]
        .concat(),
    );
    assert!(
        ok && said.contains(&format!("({} spaces)", on("1"))),
        "{said}"
    );
    let (ok, said) = run(
        d,
        &[&["render", "tower", "--out", "all.png"][..], &db].concat(),
    );
    assert!(
        !ok && said.contains("levels 0, 1, 2: draw one with --level"),
        "{said}"
    );
    assert!(!d.join("all.png").exists());
    // A route across levels: one panel for each level it is on, with the
    // marks where it changes level; on one level, that level's part.
    let room = |level: &str| {
        tower
            .spaces()
            .iter()
            .find(|s| s.kind == SpaceKind::Room && s.level.as_ref().unwrap().name == level)
            .unwrap()
            .id
            .to_string()
    };
    let (ok, said) = run(
        d,
        &[
            &[
                "render",
                "tower",
                "--out",
                "route.svg",
                "--route",
                &room("0"),
                &room("2"),
            ][..],
            &db,
        ]
        .concat(),
    );
    assert!(ok && said.contains("(levels 0 -> 1 -> 2, route "), "{said}");
    let svg = std::fs::read_to_string(d.join("route.svg")).unwrap();
    for level in ["0", "1", "2"] {
        assert!(
            svg.contains(&format!("level {level}</text>")),
            "title of level {level}"
        );
    }
    assert_eq!(
        svg.matches("class=\"route-level\"").count(),
        3,
        "up; from and up; from"
    );
    assert!(svg.contains(">up to level 1<") && svg.contains(">from level 1<"));
    let (ok, said) = run(
        d,
        &[
            &[
                "render",
                "tower",
                "--out",
                "r1.svg",
                "--level",
                "1",
                "--route",
                &room("0"),
                &room("2"),
            ][..],
            &db,
        ]
        .concat(),
    );
    assert!(ok, "{said}");
    let svg = std::fs::read_to_string(d.join("r1.svg")).unwrap();
    assert!(
        svg.contains(">from level 0, up to level 2<"),
        "passing level 1 on the stairs"
    );
    assert!(!svg.contains("route-start") && !svg.contains("route-goal"));
    // The same manifest again: nothing changed, no revision.
    let (ok, said) = run(
        d,
        &[&["import", "sim/building.toml", "--map", "tower"][..], &db].concat(),
    );
    assert!(ok && said.contains("nothing changed"), "{said}");
    // Level 1 re-mapped (another robot run of the same floor): the new
    // revision changes level 1 only; levels 0 and 2 are kept as they were.
    for file in ["map.pgm", "map.yaml"] {
        std::fs::copy(
            d.join("sim/level2").join(file),
            d.join("sim/level1").join(file),
        )
        .unwrap();
    }
    let (ok, said) = run(
        d,
        &[&["import", "sim/building.toml", "--map", "tower"][..], &db].concat(),
    );
    assert!(ok && said.contains("tower@2"), "{said}");
    assert!(
        run(
            d,
            &[&["export", "tower@2", "--out", "tower2.json"][..], &db].concat()
        )
        .0
    );
    let again = model(d, "tower2.json");
    let level_of = |nrg: &nrgdb::model::Nrg, name: &str| -> Vec<nrgdb::model::Space> {
        nrg.spaces()
            .iter()
            .filter(|s| s.level.as_ref().is_some_and(|l| l.name == name))
            .cloned()
            .collect()
    };
    assert_eq!(level_of(&again, "0"), level_of(&tower, "0"));
    assert_eq!(level_of(&again, "2"), level_of(&tower, "2"));
    assert_ne!(level_of(&again, "1"), level_of(&tower, "1"));
    // The diff says where: every change row on level 1, and the IndoorGML
    // update holds level 1's cells only (under revision 1's ids where
    // they match), checked and schema-valid.
    // A room on level 1 becomes a corridor (an edit: revision 3).
    let room = level_of(&again, "1")
        .into_iter()
        .find(|s| s.kind == SpaceKind::Room)
        .unwrap();
    let (ok, said) = run(
        d,
        &[
            &[
                "query",
                "--map",
                "tower",
                &format!("SET {} KIND corridor", room.id),
            ][..],
            &db,
        ]
        .concat(),
    );
    assert!(ok, "{said}");
    let (ok, said) = run(
        d,
        &[&["diff", "tower", "2", "3", "--gml", "update.gml"][..], &db].concat(),
    );
    assert!(!ok, "a change exits 1: {said}");
    assert!(said.contains("changed levels: 1\n"), "{said}");
    assert!(
        said.contains(&format!("rekinded  1      {}", room.id)),
        "{said}"
    );
    let header = said
        .lines()
        .find(|l| l.starts_with("change "))
        .expect("a table");
    assert!(header.contains(" level "), "{header}");
    let on_level_1 = level_of(&again, "1").len();
    assert!(
        said.contains(&format!("update.gml: level 1 ({on_level_1} cells)")),
        "{said}"
    );
    // The picture of that diff: one panel, level 1's.
    let (ok, said) = run(
        d,
        &[
            &["render", "tower", "--diff", "2", "3", "--out", "d.svg"][..],
            &db,
        ]
        .concat(),
    );
    assert!(ok && said.contains("(changed levels 1: "), "{said}");
    let svg = std::fs::read_to_string(d.join("d.svg")).unwrap();
    assert_eq!(svg.matches("class=\"title\"").count(), 1);
    assert!(svg.contains("level 1</text>"));
    assert!(svg.contains("class=\"diff changed\""), "the re-kinded room");
    let (ok, said) = run(d, &["check", "update.gml"]);
    assert!(ok, "{said}");
    let text = std::fs::read_to_string(d.join("update.gml")).unwrap();
    assert_eq!(text.matches("<core:cellSpaceMember>").count(), on_level_1);
    let (update, _) = model_from_bytes(
        text.as_bytes(),
        ModelFormat::IndoorGml,
        "update.gml".as_ref(),
    )
    .unwrap();
    let names: Vec<String> = update.levels().into_iter().map(|l| l.name).collect();
    assert_eq!(names, ["1"]);
    crate::support::schema_valid_if_shared(&d.join("update.gml"));
}

#[test]
fn a_bad_manifest_names_its_line_and_stores_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    assert!(
        run(
            d,
            &["simulate", "--levels", "2", "--seed", "3", "--out", "sim"]
        )
        .0
    );
    let good = std::fs::read_to_string(d.join("sim/building.toml")).unwrap();
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "missing map",
            good.replace("level1/map.yaml", "level9/map.yaml"),
            "does not exist",
        ),
        (
            "same level name twice",
            good.replace("name = \"1\"", "name = \"0\""),
            "listed twice",
        ),
        (
            "a lift serving one level",
            good.replace("levels = [\"0\", \"1\"]", "levels = [\"1\"]"),
            "serves 1 level",
        ),
        (
            "a transform with NaN",
            good.replace(
                "map = \"level1/map.yaml\"",
                "map = \"level1/map.yaml\"\ntransform = { x = nan }",
            ),
            "not a finite number",
        ),
        (
            "stairs on one level",
            good.replace("level = \"1\" }", "level = \"0\" }"),
            "stairs join two levels",
        ),
    ];
    for (what, text, says) in cases {
        std::fs::write(d.join("sim/bad.toml"), &text).unwrap();
        let (ok, said) = run(
            d,
            &["import", "sim/bad.toml", "--map", "b", "--db", "t.sqlite"],
        );
        assert!(!ok, "{what}: {said}");
        assert!(said.contains("bad.toml: line "), "{what}: {said}");
        assert!(said.contains(says), "{what}: {said}");
        let maps = run(d, &["maps", "--db", "t.sqlite"]).1;
        assert!(!maps.lines().any(|l| l.starts_with("b ")), "{what}: {maps}");
    }
    // A lift standing outside every space.
    let lift_line = good.lines().find(|l| l.starts_with("at = [")).unwrap();
    let far = good.replace(lift_line, "at = [-500.0, -500.0]");
    std::fs::write(d.join("sim/far.toml"), far).unwrap();
    let (ok, said) = run(
        d,
        &["import", "sim/far.toml", "--map", "b", "--db", "t.sqlite"],
    );
    assert!(
        !ok && said.contains("lies outside every space of that level"),
        "{said}"
    );
    assert!(said.contains("far.toml: line "), "{said}");
}

/// The shortest route in `nrg` (exact profile unless given).
fn route(
    nav: &nrgdb::route::NavMesh,
    from: u32,
    to: u32,
    profile: nrgdb::route::Profile,
) -> Result<Option<nrgdb::route::Route>, nrgdb::route::RouteError> {
    let mut request =
        nrgdb::route::RouteRequest::new(nrgdb::model::SpaceId(from), nrgdb::model::SpaceId(to));
    request.profile = profile;
    nrgdb::route::shortest_route(nav, &request, &nrgdb::route::Budget::unlimited())
        .map(|mut r| r.pop())
}

/// Routes across levels are the shortest combination of walks on each
/// level and the rides between them: the test enumerates the ways (two
/// flights of stairs, or the lift) from walks it asks level by level,
/// and checks the route takes the cheapest allowed.
#[test]
fn routes_cross_levels_by_the_cheapest_allowed_way() {
    use nrgdb::model::{elevator_length_m, stairs_length_m};
    use nrgdb::route::{NavMesh, Profile};
    let nrg = walked_model(&nrgdb::fixtures::storeys(3, 4)).nrg;
    let nav = NavMesh::new(std::sync::Arc::new(nrg.clone()));
    let exact = Profile::exact();
    // Room 10 on level 0 to room 13 on level 2 (ids + 100 000 a level).
    let (from, to) = (10, 200_013);
    let (stairs, lift) = (90_000, 90_001);
    let walk = |a: u32, b: u32| route(&nav, a, b, exact).unwrap().unwrap().length_m;
    let by_stairs = walk(from, stairs) + 2.0 * stairs_length_m(3.5) + walk(200_000 + stairs, to);
    let by_lift = walk(from, lift) + elevator_length_m(2) + walk(200_000 + lift, to);
    let best = route(&nav, from, to, exact).unwrap().unwrap();
    assert!(
        (best.length_m - by_stairs.min(by_lift)).abs() < 1e-6,
        "{} vs {by_stairs} / {by_lift}",
        best.length_m
    );
    let said: Vec<String> = best.steps.iter().map(|s| s.instruction.clone()).collect();
    assert!(
        said.iter()
            .any(|s| s == "walk up the West stairs L0 to level 1"),
        "{said:?}"
    );
    assert!(
        said.iter()
            .any(|s| s == "walk up the West stairs L1 to level 2"),
        "{said:?}"
    );
    assert!(said.last().unwrap().starts_with("arrive at"), "{said:?}");
    assert_eq!(*best.spaces.first().unwrap(), nrgdb::model::SpaceId(from));
    assert_eq!(*best.spaces.last().unwrap(), nrgdb::model::SpaceId(to));
    // Without stairs: the lift, at its own cost.
    let no_stairs = Profile {
        no_stairs: true,
        ..exact
    };
    let lifted = route(&nav, from, to, no_stairs).unwrap().unwrap();
    assert!(
        (lifted.length_m - by_lift).abs() < 1e-6,
        "{} vs {by_lift}",
        lifted.length_m
    );
    let said: Vec<String> = lifted.steps.iter().map(|s| s.instruction.clone()).collect();
    assert!(
        said.iter()
            .any(|s| s == "take Lift A L0 from level 0 to level 2"),
        "{said:?}"
    );
    assert!(!said.iter().any(|s| s.contains("stairs")), "{said:?}");
    // Neither stairs nor lift: no route between levels, one within a level.
    let neither = Profile {
        no_stairs: true,
        no_elevator: true,
        ..exact
    };
    assert!(route(&nav, from, to, neither).unwrap().is_none());
    let mut request =
        nrgdb::route::RouteRequest::new(nrgdb::model::SpaceId(from), nrgdb::model::SpaceId(to));
    request.profile = neither;
    let why = nrgdb::route::no_route_reason(&nav, &request);
    assert!(
        why.contains("on levels not joined without stairs or lifts"),
        "{why}"
    );
    // Alternatives across levels differ in their stairs or lifts: the
    // best is the stairs' way, and the lift's way is among the others at
    // the length the test put together.
    let mut request =
        nrgdb::route::RouteRequest::new(nrgdb::model::SpaceId(from), nrgdb::model::SpaceId(to));
    request.profile = exact;
    request.alternatives = 3;
    let routes =
        nrgdb::route::shortest_route(&nav, &request, &nrgdb::route::Budget::unlimited()).unwrap();
    assert!(routes.len() >= 2, "{}", routes.len());
    assert!((routes[0].length_m - by_stairs.min(by_lift)).abs() < 1e-6);
    for w in routes.windows(2) {
        assert!(w[0].length_m <= w[1].length_m + 1e-9);
    }
    let lift_way = routes
        .iter()
        .find(|r| r.spaces.contains(&nrgdb::model::SpaceId(lift)))
        .expect("a way by the lift");
    assert!(
        (lift_way.length_m - by_lift).abs() < 1e-6,
        "{} vs {by_lift}",
        lift_way.length_m
    );
    // A lift that does not serve level 2: without stairs, level 1 is
    // reached by the lift and level 2 not at all, said clearly.
    let (spaces, links) = nrg.clone().into_parts();
    let links = links
        .into_iter()
        .filter(|c| {
            !(c.kind == ConnectionKind::Vertical && [c.a.0, c.b.0].contains(&(200_000 + lift)))
        })
        .collect();
    let short_lift = NavMesh::new(std::sync::Arc::new(
        nrgdb::model::Nrg::new(spaces, links).unwrap(),
    ));
    assert!(route(&short_lift, from, to, no_stairs).unwrap().is_none());
    let one_up = route(&short_lift, from, 100_013, no_stairs)
        .unwrap()
        .unwrap();
    assert!(one_up.spaces.contains(&nrgdb::model::SpaceId(lift)));
    let mut request =
        nrgdb::route::RouteRequest::new(nrgdb::model::SpaceId(from), nrgdb::model::SpaceId(to));
    request.profile = no_stairs;
    let why = nrgdb::route::no_route_reason(&short_lift, &request);
    assert!(
        why.contains("without stairs (no lift serves both levels)"),
        "{why}"
    );
    // From the stairs on level 0: the route starts there, on level 0.
    let up = route(&nav, stairs, 100_000 + from, exact).unwrap().unwrap();
    assert_eq!(up.levels.first().unwrap().level, "0");
    assert_eq!(
        up.waypoints.first(),
        Some(&nrg.space(nrgdb::model::SpaceId(stairs)).unwrap().anchor)
    );
    // To where one is: one point, arrived.
    let here = route(&nav, from, from, exact).unwrap().unwrap();
    assert_eq!(here.spaces, [nrgdb::model::SpaceId(from)]);
    assert_eq!(here.waypoints.len(), 1);
    assert_eq!(here.levels.len(), 1);
    assert_eq!(
        here.steps.last().unwrap().instruction,
        "arrive at Office 1 L0"
    );
    let same_level = route(&nav, from, 13, neither).unwrap().unwrap();
    assert!((same_level.length_m - walk(from, 13)).abs() < 1e-9);
    // A point has no level: a clear error.
    let mut request = nrgdb::route::RouteRequest::between(
        nrgdb::route::Endpoint::Point([2.0, 4.0]),
        nrgdb::route::Endpoint::Space(nrgdb::model::SpaceId(to)),
    );
    request.profile = exact;
    let err = nrgdb::route::shortest_route(&nav, &request, &nrgdb::route::Budget::unlimited())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("does not say its level") && err.contains("ON LEVEL"),
        "{err}"
    );
    // Points on levels: the walks from the point and to the point are
    // asked of each floor alone (a plain model), and the route is the
    // cheaper of the two ways the test puts together.
    use nrgdb::route::{Budget, Endpoint, RouteRequest, shortest_route};
    let floor = |level: &str| {
        let (spaces, links) = nrg.level_model(level).unwrap().into_parts();
        let spaces = spaces
            .into_iter()
            .map(|s| nrgdb::model::Space { level: None, ..s })
            .collect();
        NavMesh::new(std::sync::Arc::new(
            nrgdb::model::Nrg::new(spaces, links).unwrap(),
        ))
    };
    let walk_on = |nav: &NavMesh, a: Endpoint, b: Endpoint| {
        let request = RouteRequest {
            profile: exact,
            ..RouteRequest::between(a, b)
        };
        shortest_route(nav, &request, &Budget::unlimited()).unwrap()[0].length_m
    };
    let anchor = |id: u32| nrg.space(nrgdb::model::SpaceId(id)).unwrap().anchor;
    let p0 = [anchor(from)[0] + 0.4, anchor(from)[1] - 0.3];
    let p2 = [anchor(to)[0] - 0.5, anchor(to)[1] + 0.2];
    let (ground, top) = (floor("0"), floor("2"));
    let space = |id: u32| Endpoint::Space(nrgdb::model::SpaceId(id));
    let by_stairs = walk_on(&ground, Endpoint::Point(p0), space(stairs))
        + 2.0 * stairs_length_m(3.5)
        + walk_on(&top, space(200_000 + stairs), Endpoint::Point(p2));
    let by_lift = walk_on(&ground, Endpoint::Point(p0), space(lift))
        + elevator_length_m(2)
        + walk_on(&top, space(200_000 + lift), Endpoint::Point(p2));
    let mut request = RouteRequest::between(
        Endpoint::point_on(&nrg, p0, "0").unwrap(),
        Endpoint::point_on(&nrg, p2, "2").unwrap(),
    );
    request.profile = exact;
    let r = &shortest_route(&nav, &request, &Budget::unlimited()).unwrap()[0];
    assert!(
        (r.length_m - by_stairs.min(by_lift)).abs() < 1e-6,
        "{} vs {by_stairs} / {by_lift}",
        r.length_m
    );
    assert_eq!(r.waypoints.first(), Some(&p0));
    assert_eq!(r.waypoints.last(), Some(&p2));
    let levels: Vec<&str> = r.levels.iter().map(|s| s.level.as_str()).collect();
    assert_eq!(levels.first(), Some(&"0"));
    assert_eq!(levels.last(), Some(&"2"));
}

/// The HTTP route answer in a building: positions with z (each level's
/// elevation), the level of each stretch, and the profiles' flags.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_server_routes_across_levels_in_3d() {
    let s = crate::server_client::TestServer::read_only().await;
    {
        let mut store = nrgdb::store::Store::open(&s.db).unwrap();
        let tower = walked_model(&nrgdb::fixtures::storeys(3, 4)).nrg;
        store
            .import(
                "tower",
                &tower,
                nrgdb::store::ImportMeta::new("floors", "test"),
            )
            .unwrap();
    }
    let body = s.get("/maps/tower/route?from=10&to=200013").await.json();
    let route = &body["routes"][0];
    let coords = route["geometry"]["coordinates"].as_array().unwrap();
    assert!(coords.iter().all(|p| p.as_array().unwrap().len() == 3));
    let z: Vec<f64> = coords.iter().map(|p| p[2].as_f64().unwrap()).collect();
    assert_eq!(z.first(), Some(&0.0));
    assert_eq!(z.last(), Some(&7.0));
    let levels: Vec<&str> = route["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["level"].as_str().unwrap())
        .collect();
    assert_eq!(levels, ["0", "1", "2"], "by the stairs, floor by floor");
    let lifted = s
        .get("/maps/tower/route?from=10&to=200013&no_stairs=true")
        .await
        .json();
    let steps = lifted["routes"][0]["legs"][0]["steps"].as_array().unwrap();
    assert!(
        steps
            .iter()
            .any(|st| st["instruction"] == "take Lift A L0 from level 0 to level 2"),
        "{steps:?}"
    );
    s.get("/maps/tower/route?from=10&to=200013&no_stairs=maybe")
        .await
        .assert_error(400, "no_stairs");
    s.stop().await;
}
