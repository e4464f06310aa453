//! [`ExtractParams`] by name: read from TOML (grouped tables, or the flat
//! keys parameter files used before the groups) and set one parameter by
//! its name (`--set`, `nrgdb eval --loo`). One place knows which group a
//! key is in: the groups' own serialised form.

use toml::{Table, Value};

use super::error::ExtractError;
use super::params::ExtractParams;

/// The parameters' TOML form, groups as tables.
fn table_of(params: &ExtractParams) -> Result<Table, ExtractError> {
    Table::try_from(params).map_err(|e| ExtractError::ParamsText {
        message: e.to_string(),
    })
}

/// The group (`building`, `output`, `internals`) whose table holds `key`
/// in `defaults` (the default parameters' table).
fn group_of<'a>(defaults: &'a Table, key: &str) -> Option<&'a str> {
    defaults.iter().find_map(|(group, v)| {
        v.as_table()
            .is_some_and(|t| t.contains_key(key))
            .then_some(group.as_str())
    })
}

/// Moves every top-level key that belongs to a group into that group's
/// table. A key given both ways is refused by name.
fn nest(mut table: Table, defaults: &Table) -> Result<Table, ExtractError> {
    let flat: Vec<String> = table
        .keys()
        .filter(|k| !defaults.contains_key(*k))
        .cloned()
        .collect();
    for key in flat {
        let Some(group) = group_of(defaults, &key) else {
            continue; // not a parameter: refused by name below
        };
        let Some(value) = table.remove(&key) else {
            continue;
        };
        let sub = table
            .entry(group.to_owned())
            .or_insert_with(|| Value::Table(Table::new()));
        let Some(sub) = sub.as_table_mut() else {
            return Err(ExtractError::ParamsText {
                message: format!("`{group}` must be a table of parameters"),
            });
        };
        if sub.contains_key(&key) {
            return Err(ExtractError::ParamsText {
                message: format!("`{key}` is given twice: on its own and in [{group}]"),
            });
        }
        sub.insert(key, value);
    }
    Ok(table)
}

impl ExtractParams {
    /// Reads parameters from TOML text: the groups as tables
    /// (`[building]`, `[output]`, `[internals]`), or their keys on their
    /// own; missing keys take their defaults. Unknown keys and values of
    /// the wrong type are refused by name. The values are not checked
    /// against each other here, so that flags given after the file can
    /// still put them in order: call [`ExtractParams::validate`] once all
    /// are set (extraction does).
    ///
    /// ```
    /// use nrgdb::extract::ExtractParams;
    /// let p = ExtractParams::from_toml("method = \"ccl\"\n[internals]\ncore_radius_m = 0.4").unwrap();
    /// assert_eq!(p.internals.core_radius_m, 0.4);
    /// let e = ExtractParams::from_toml("door_width_maxx_m = 1").unwrap_err();
    /// assert!(e.to_string().contains("door_width_maxx_m"));
    /// ```
    pub fn from_toml(text: &str) -> Result<ExtractParams, ExtractError> {
        let table: Table = toml::from_str(text).map_err(|e| ExtractError::ParamsText {
            message: e.to_string(),
        })?;
        let defaults = table_of(&ExtractParams::default())?;
        let params: ExtractParams =
            nest(table, &defaults)?
                .try_into()
                .map_err(|e: toml::de::Error| ExtractError::ParamsText {
                    message: e.to_string(),
                })?;
        Ok(params)
    }

    /// Every parameter's name as [`ExtractParams::set`] takes it: the
    /// top-level ones, then `group.key` for each group's.
    ///
    /// ```
    /// let keys = nrgdb::extract::ExtractParams::keys();
    /// assert!(keys.contains(&"method".to_string()));
    /// assert!(keys.contains(&"building.door_width_max_m".to_string()));
    /// ```
    pub fn keys() -> Vec<String> {
        let Ok(defaults) = table_of(&ExtractParams::default()) else {
            return Vec::new();
        };
        let mut out: Vec<String> = defaults
            .iter()
            .filter(|(_, v)| !v.is_table())
            .map(|(k, _)| k.clone())
            .collect();
        for (group, v) in &defaults {
            if let Some(t) = v.as_table() {
                out.extend(t.keys().map(|k| format!("{group}.{k}")));
            }
        }
        out
    }

    /// Sets one parameter by name, `group.key` or the bare key (the names
    /// are unique), to `value`: a TOML value (number, boolean, quoted
    /// string), or a bare word as a string. An unknown name or a value of
    /// the wrong type is refused and leaves `self` unchanged. The values
    /// are not checked against each other here, so that several can be
    /// set in turn (a least and a greatest width both raised): call
    /// [`ExtractParams::validate`] after the last (extraction does).
    ///
    /// ```
    /// use nrgdb::extract::ExtractParams;
    /// let mut p = ExtractParams::default();
    /// p.set("furniture_max_m", "0").unwrap();
    /// p.set("internals.door_constriction", "0.8").unwrap();
    /// p.set("method", "ccl").unwrap();
    /// assert_eq!((p.building.furniture_max_m, p.internals.door_constriction), (0.0, 0.8));
    /// assert!(p.set("no_such_m", "1").is_err());
    /// assert!(p.set("building.door_width_max_m", "wide").is_err());
    /// assert!(p.validate().is_ok());
    /// ```
    pub fn set(&mut self, key: &str, value: &str) -> Result<(), ExtractError> {
        let mut table = table_of(self)?;
        let unknown = || ExtractError::UnknownParam {
            key: key.to_owned(),
            known: ExtractParams::keys().join(", "),
        };
        let (group, name) = match key.split_once('.') {
            Some((g, n)) => (Some(g.to_owned()), n),
            None => (group_of(&table, key).map(str::to_owned), key),
        };
        let slot = match &group {
            Some(g) => table
                .get_mut(g)
                .and_then(Value::as_table_mut)
                .ok_or_else(unknown)?,
            None => &mut table,
        };
        if slot.get(name).is_none_or(Value::is_table) {
            return Err(unknown());
        }
        let parsed = toml::from_str::<Table>(&format!("v = {}", value.trim()))
            .ok()
            .and_then(|mut t| t.remove("v"))
            .unwrap_or_else(|| Value::String(value.trim().to_owned()));
        slot.insert(name.to_owned(), parsed);
        let params: ExtractParams =
            table
                .try_into()
                .map_err(|e: toml::de::Error| ExtractError::ParamsText {
                    message: format!("{key} = {}: {e}", value.trim()),
                })?;
        *self = params;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_and_grouped_files_read_alike_and_a_key_given_twice_is_refused() {
        let grouped = ExtractParams::from_toml(
            "working_resolution_m = 0.1\n[building]\nfurniture_max_m = 0.5\n[internals]\ndoor_join_m = 0.3",
        )
        .unwrap();
        let flat = ExtractParams::from_toml(
            "working_resolution_m = 0.1\nfurniture_max_m = 0.5\ndoor_join_m = 0.3",
        )
        .unwrap();
        assert_eq!(grouped, flat);
        assert_eq!(grouped.building.furniture_max_m, 0.5);
        assert_eq!(grouped.internals.door_join_m, 0.3);
        assert_eq!(grouped.building.door_width_max_m, 1.8, "the rest default");
        let e =
            ExtractParams::from_toml("furniture_max_m = 0.5\n[building]\nfurniture_max_m = 0.6")
                .unwrap_err()
                .to_string();
        assert!(e.contains("furniture_max_m") && e.contains("twice"), "{e}");
        let e = ExtractParams::from_toml("[building]\ncore_radius_m = 0.4")
            .unwrap_err()
            .to_string();
        assert!(e.contains("core_radius_m"), "a key in the wrong table: {e}");
        // Read unchecked; checked once everything is set.
        let e = ExtractParams::from_toml("door_width_min_m = 2.5")
            .unwrap()
            .validate()
            .unwrap_err()
            .to_string();
        assert!(e.contains("building.door_width_max_m"), "{e}");
    }

    #[test]
    fn every_key_can_be_set_by_its_listed_name_and_a_refusal_changes_nothing() {
        let keys = ExtractParams::keys();
        assert_eq!(keys.len(), 28, "{keys:?}");
        let defaults = table_of(&ExtractParams::default()).unwrap();
        for key in keys.iter().filter(|k| k.contains('.')) {
            let (group, name) = key.split_once('.').unwrap();
            let default = defaults[group][name].as_float().unwrap();
            // 10 % more keeps every least value under its greatest and
            // every fraction under 1.
            let mut p = ExtractParams::default();
            p.set(key, &format!("{}", default * 1.1 + 0.01))
                .unwrap_or_else(|e| panic!("{key}: {e}"));
            assert_ne!(p, ExtractParams::default(), "{key} moved nothing");
            // The bare name reaches the same parameter.
            let mut q = ExtractParams::default();
            q.set(name, &format!("{}", default * 1.1 + 0.01)).unwrap();
            assert_eq!(p, q, "{key}");
        }
        // Set in turn: both widths raised, checked after the last.
        let mut p = ExtractParams::default();
        p.set("door_width_min_m", "2.0").unwrap();
        assert!(p.validate().is_err());
        p.set("building.door_width_max_m", "2.5").unwrap();
        p.set("wall_gap_width_max_m", "2.6").unwrap();
        assert!(p.validate().is_ok());
        let mut p = ExtractParams::default();
        let e = p
            .set("door_width_min_m", "\"wide\"")
            .unwrap_err()
            .to_string();
        assert!(e.contains("door_width_min_m"), "{e}");
        assert_eq!(p, ExtractParams::default(), "unchanged after a refusal");
        let e = p
            .set("building.core_radius_m", "1")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("no such parameter") && e.contains("internals.core_radius_m"),
            "{e}"
        );
    }
}
