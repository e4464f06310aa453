//! A map's georeference in PostgreSQL: `nrgdb.maps.georef` (JSON).

use postgres::Client;

use super::fault::R;
use super::prepared::Prepared;
use super::read::map_id;
use crate::model::Georef;
use crate::store::georef_json::{decode, encode};

/// The georeference of `map`.
pub(super) fn get(c: &mut Client, p: &mut Prepared, map: &str) -> R<Option<Georef>> {
    let id = map_id(c, p, map)?;
    let row = p.query_one(c, "SELECT georef FROM maps WHERE id = $1", &[&id])?;
    let text: Option<String> = row.get(0);
    Ok(text.map(|t| decode(map, &t)).transpose()?)
}

/// Sets or removes the georeference of `map`.
pub(super) fn set(c: &mut Client, p: &mut Prepared, map: &str, g: Option<&Georef>) -> R<()> {
    let id = map_id(c, p, map)?;
    let text = g.map(encode);
    p.execute(
        c,
        "UPDATE maps SET georef = $1 WHERE id = $2",
        &[&text, &id],
    )?;
    Ok(())
}
