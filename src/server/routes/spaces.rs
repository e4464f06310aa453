//! Spaces of a revision: listing with filters, one space in full, its
//! neighbours within some hops, and point location.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::Uri;
use serde_json::{Map, Value, json};

use crate::model::{Space, SpaceId, SpaceKind, doorway};
use crate::query::{IndexedRevision, Limits, Plan, QueryResult, Table, execute, like};
use crate::server::endpoint::{ParamDoc, REV, q};
use crate::server::error::ApiError;
use crate::server::params::{Params, level_param, parse_metres, parse_value};
use crate::server::state::AppState;

/// Query parameters of `GET /maps/{map}/spaces`.
pub const LIST_PARAMS: [ParamDoc; 4] = [
    q("kind", "string", false, "room, corridor, door or other"),
    LEVEL,
    q(
        "name",
        "string",
        false,
        "name or label, case-insensitive; % and _ are wildcards",
    ),
    REV,
];
/// Query parameters of `GET /maps/{map}/neighbours/{id}`.
pub const NEIGHBOUR_PARAMS: [ParamDoc; 2] = [
    q(
        "depth",
        "integer",
        false,
        "navigable hops, 1 to 64 (default 1)",
    ),
    REV,
];
/// Query parameters of `GET /maps/{map}/locate`.
pub const LOCATE_PARAMS: [ParamDoc; 4] = [
    q("x", "number", true, "x in metres, map frame"),
    q("y", "number", true, "y in metres, map frame"),
    q(
        "level",
        "string",
        false,
        "in a building with levels, the level searched (default: every level, the lowest first in `spaces`)",
    ),
    REV,
];

/// The `level` parameter of the listing.
const LEVEL: ParamDoc = q(
    "level",
    "string",
    false,
    "in a building with levels, only the spaces on this level",
);

/// The short JSON form of a space: id, kind, name, label, anchor, area,
/// degree, and for a door its width and doorway line.
pub(crate) fn space_summary(s: &Space, rev: &IndexedRevision) -> Value {
    let mut v = json!({
        "id": s.id,
        "kind": s.kind.as_str(),
        "name": s.name,
        "label": s.label(),
        "anchor": s.anchor,
        "area_m2": s.area_m2,
        "degree": rev.graph.degree(s.id),
    });
    if let Some(level) = &s.level {
        v["level"] = json!(level.name);
    }
    if let Some(d) = doorway(s) {
        v["width_m"] = json!(d.width_m);
        v["doorway"] = json!(d.line);
    }
    v
}

/// A table's rows as objects keyed by column.
pub(crate) fn rows_as_objects(t: &Table) -> Vec<Value> {
    t.rows
        .iter()
        .map(|row| {
            let obj: Map<String, Value> = t
                .columns
                .iter()
                .zip(row)
                .map(|(c, cell)| (c.clone(), serde_json::to_value(cell).unwrap_or(Value::Null)))
                .collect();
            Value::Object(obj)
        })
        .collect()
}

/// A path `{id}`: a space id that exists in `rev` (404 otherwise).
pub(crate) fn space_id(raw: &str, rev: &IndexedRevision) -> Result<SpaceId, ApiError> {
    let id = SpaceId(parse_value("id", raw, "a space id (a number)")?);
    if rev.nrg.space(id).is_none() {
        return Err(ApiError::not_found(
            "id",
            format!(
                "map '{}' has no space {id} in revision {} (GET /maps/{}/spaces lists them)",
                rev.map, rev.revision, rev.map
            ),
        ));
    }
    Ok(id)
}

fn envelope(rev: &IndexedRevision, key: &str, value: Value) -> Value {
    json!({ "map": rev.map, "revision": rev.revision, key: value })
}

/// `GET /maps/{map}/spaces?kind=&name=&rev=`.
pub async fn list_spaces(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let p = Params::parse(&uri, &["kind", "level", "name", "rev"])?;
    let kind: Option<SpaceKind> = p.opt("kind", "a kind (room, corridor, door or other)")?;
    let name = p.get("name").map(str::to_string);
    let level = p.get("level").map(str::to_string);
    let rev = p.rev()?;
    state
        .quick(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            let level = level_param(level.as_deref(), &r)?;
            let spaces: Vec<Value> = r
                .nrg
                .spaces()
                .iter()
                .filter(|s| kind.is_none_or(|k| s.kind == k))
                .filter(|s| {
                    level
                        .as_deref()
                        .is_none_or(|l| s.level.as_ref().is_some_and(|m| m.name == l))
                })
                .filter(|s| name.as_deref().is_none_or(|n| like(&s.label(), n)))
                .map(|s| space_summary(s, &r))
                .collect();
            Ok(Json(envelope(&r, "spaces", spaces.into())))
        })
        .await
}

/// `GET /maps/{map}/spaces/{id}?rev=`.
pub async fn space(
    State(state): State<AppState>,
    Path((map, id)): Path<(String, String)>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let rev = Params::parse(&uri, &["rev"])?.rev()?;
    state
        .quick(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            let id = space_id(&id, &r)?;
            let s = r.nrg.space(id).ok_or_else(|| ApiError::not_found("id", "no such space"))?;
            let mut v = space_summary(s, &r);
            v["polygon"] = json!(s.polygon);
            v["holes"] = json!(s.holes);
            v["attributes"] = Value::Object(s.attributes.clone());
            v["connections"] = r
                .nrg
                .connections_of(id)
                .filter_map(|c| c.other(id).map(|to| (to, c)))
                .map(|(to, c)| json!({"to": to, "kind": c.kind, "length_m": c.length_m, "navigable": c.kind.is_navigable()}))
                .collect::<Vec<_>>()
                .into();
            Ok(Json(envelope(&r, "space", v)))
        })
        .await
}

/// `GET /maps/{map}/neighbours/{id}?depth=&rev=`.
pub async fn neighbours(
    State(state): State<AppState>,
    Path((map, id)): Path<(String, String)>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let p = Params::parse(&uri, &["depth", "rev"])?;
    let depth: u32 = p
        .opt("depth", "a number of hops from 1 to 64")?
        .unwrap_or(1);
    if !(1..=64).contains(&depth) {
        return Err(ApiError::bad(
            "depth",
            format!("{depth} is out of range (1 to 64)"),
        ));
    }
    let rev = p.rev()?;
    let limits = Limits {
        timeout: state.config().timeout,
        ..Limits::default()
    };
    state
        .quick(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            let of = space_id(&id, &r)?;
            let rows = match execute(&Plan::Neighbours { of, depth }, &r, &limits)? {
                QueryResult::Table(t) => rows_as_objects(&t),
                _ => Vec::new(),
            };
            let mut v = envelope(&r, "neighbours", rows.into());
            v["of"] = json!(of);
            v["depth"] = json!(depth);
            Ok(Json(v))
        })
        .await
}

/// `GET /maps/{map}/locate?x=&y=&level=&rev=`: `"space": null` when no
/// space contains the point. In a building with levels, `spaces` lists
/// the space containing it on each level searched, lowest first, and
/// `space` is the first of them.
pub async fn locate(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let p = Params::parse(&uri, &["x", "y", "level", "rev"])?;
    let x = parse_metres("x", p.required("x")?)?;
    let y = parse_metres("y", p.required("y")?)?;
    let level = p.get("level").map(str::to_string);
    let rev = p.rev()?;
    state
        .quick(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            let level = level_param(level.as_deref(), &r)?;
            if !r.nrg.has_levels() {
                let found = r.locate([x, y]).map(|s| space_summary(s, &r));
                let mut v = envelope(&r, "space", found.unwrap_or(Value::Null));
                v["point"] = json!([x, y]);
                return Ok(Json(v));
            }
            let found: Vec<Value> = r
                .locate_on([x, y], level.as_deref())
                .into_iter()
                .map(|s| space_summary(s, &r))
                .collect();
            let first = found.first().cloned().unwrap_or(Value::Null);
            let mut v = envelope(&r, "space", first);
            v["spaces"] = found.into();
            v["point"] = json!([x, y]);
            Ok(Json(v))
        })
        .await
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::Cell;

    #[test]
    fn rows_become_objects() {
        let t = Table {
            columns: vec!["id".into(), "name".into()],
            rows: vec![vec![Cell::Int(3), Cell::Null]],
        };
        assert_eq!(rows_as_objects(&t), vec![json!({"id": 3, "name": null})]);
    }
}
