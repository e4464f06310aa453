//! A map's georeference in SQLite: `maps.georef` (JSON).

use rusqlite::Connection;

use super::fault::R;
use super::read::map_id;
use crate::model::Georef;
use crate::store::georef_json::{decode, encode};

/// The georeference of `map`.
pub(super) fn get(conn: &Connection, map: &str) -> R<Option<Georef>> {
    let id = map_id(conn, map)?;
    let text: Option<String> =
        conn.query_row("SELECT georef FROM maps WHERE id = ?1", [id], |r| r.get(0))?;
    Ok(text.map(|t| decode(map, &t)).transpose()?)
}

/// Sets or removes the georeference of `map`.
pub(super) fn set(conn: &Connection, map: &str, g: Option<&Georef>) -> R<()> {
    let id = map_id(conn, map)?;
    conn.execute(
        "UPDATE maps SET georef = ?1 WHERE id = ?2",
        rusqlite::params![g.map(encode), id],
    )?;
    Ok(())
}
