//! `POST /query`: statements of the query language, JSON results. The body
//! is the query text (`text/plain`) or `{"query", "map", "rev"}` (JSON).
//! `NAME … AS …` writes a revision and needs the bearer token.

use std::sync::Arc;

use axum::Json;
use axum::body::Body;
use axum::extract::State;
use axum::http::{HeaderMap, Uri, header};
use serde::Deserialize;
use serde_json::{Value, json};

use super::spaces::rows_as_objects;
use crate::grid::OccupancyGrid;
use crate::model::{Nrg, SpaceId};
use crate::query::{
    IndexedRevision, Limits, MapInfo, QueryError, QueryResult, RevisionInfo, Session, Source,
    SourceError, Statement,
};
use crate::server::auth::{has_token, require_write};
use crate::server::body::read_limited;
use crate::server::cache::RevisionCache;
use crate::server::endpoint::{ParamDoc, REV, q};
use crate::server::error::ApiError;
use crate::server::params::{Params, parse_rev};
use crate::server::state::AppState;
use crate::store::Store;

/// Query parameters of `POST /query` (the JSON body may give them too).
pub const PARAMS: [ParamDoc; 3] = [
    q(
        "map",
        "string",
        false,
        "map to USE first (default: the first map by name)",
    ),
    REV,
    q(
        "author",
        "string",
        false,
        "who corrections are recorded as made by (default: nrgdb serve)",
    ),
];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct QueryBody {
    query: String,
    map: Option<String>,
    rev: Option<Value>,
}

/// The store seen by a query, selecting revisions through the server's
/// cache of indexed revisions (the one every endpoint uses); NAME is
/// refused without the token.
struct QuerySource<'a> {
    store: &'a mut Store,
    cache: &'a RevisionCache,
    writable: bool,
}

impl Source for QuerySource<'_> {
    fn indexed(&self, map: &str, revision: u64) -> Result<Arc<IndexedRevision>, SourceError> {
        let seq = u32::try_from(revision).map_err(|_| SourceError::NoRevision {
            map: map.to_string(),
            revision,
        })?;
        self.cache.get_or_load(map, seq, || {
            let nrg = <Store as Source>::load(self.store, map, revision)?;
            Ok(IndexedRevision::new(map, revision, nrg))
        })
    }
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
        <Store as Source>::maps(self.store)
    }
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
        <Store as Source>::revisions(self.store, map)
    }
    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
        <Store as Source>::load(self.store, map, revision)
    }
    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
        <Store as Source>::grid(self.store, map, revision)
    }
    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError> {
        if !self.writable {
            return Err(SourceError::Backend(
                "NAME writes a revision: send 'Authorization: Bearer <token>' to a server started with --token"
                    .into(),
            ));
        }
        <Store as Source>::rename_space(self.store, map, revision, id, name)
    }
    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &crate::edit::Edit,
        statement: &str,
        author: &str,
    ) -> Result<crate::query::EditDone, SourceError> {
        if !self.writable {
            return Err(SourceError::Backend(
                "a correction writes a revision: send 'Authorization: Bearer <token>' to a server started with --token"
                    .into(),
            ));
        }
        <Store as Source>::edit(self.store, map, revision, edit, statement, author)
    }
}

/// A statement's result as JSON; a storage fault (500) or a busy store
/// (503) fails the whole request instead, keeping its class.
fn result_json(result: Result<QueryResult, QueryError>) -> Result<Value, ApiError> {
    Ok(match result {
        Ok(QueryResult::Table(t)) => {
            json!({"type": "table", "columns": t.columns, "rows": rows_as_objects(&t)})
        }
        Ok(QueryResult::Routes(r)) => json!({"type": "routes", "routes": r}),
        Ok(QueryResult::Message(m)) => json!({"type": "message", "message": m}),
        Ok(QueryResult::Plan(p)) => json!({"type": "plan", "plan": p}),
        Err(e) => {
            let api = ApiError::from(e);
            if matches!(api, ApiError::Internal(_) | ApiError::Busy) {
                return Err(api);
            }
            json!({"type": "error", "code": api.code(), "message": api.to_string()})
        }
    })
}

/// `POST /query`.
pub async fn query(
    State(state): State<AppState>,
    uri: Uri,
    headers: HeaderMap,
    body: Body,
) -> Result<Json<Value>, ApiError> {
    // The deadline of the whole request: past it the client has had its
    // 503 (`server::timeout`), so the statements stop too.
    let deadline = std::time::Instant::now().checked_add(state.config().timeout);
    let p = Params::parse(&uri, &["map", "rev", "author"])?;
    let author = p.get("author").unwrap_or("nrgdb serve").to_string();
    let config = state.config();
    let bytes = read_limited(&headers, body, config.max_body_bytes, config.body_timeout).await?;
    let is_json = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/json"));
    let (text, mut map, mut rev) = if is_json {
        let b: QueryBody = serde_json::from_slice(&bytes).map_err(|e| {
            ApiError::bad(
                "body",
                format!("{e} (expected {{\"query\": \"…\", \"map\"?, \"rev\"?}})"),
            )
        })?;
        let rev = match b.rev {
            None | Some(Value::Null) => None,
            Some(Value::String(s)) => parse_rev("rev", &s)?,
            Some(v) => parse_rev("rev", &v.to_string())?,
        };
        (b.query, b.map, rev)
    } else {
        let text = String::from_utf8(bytes.to_vec())
            .map_err(|_| ApiError::bad("body", "the query text is not UTF-8"))?;
        (text, None, None)
    };
    if let Some(m) = p.get("map") {
        map = Some(m.to_string());
    }
    if p.get("rev").is_some() {
        rev = p.rev()?;
    }
    if text.trim().is_empty() {
        return Err(ApiError::bad(
            "query",
            "empty (send statements such as FIND rooms;)",
        ));
    }
    // A request that would write (NAME) is refused as a whole, 401 or
    // 403 as for every other write, before anything runs (it used to
    // answer 200 with an error in the statement's slot).
    if crate::query::parse(&text)
        .map_err(ApiError::from)?
        .iter()
        .any(Statement::writes)
    {
        require_write(state.config(), &headers)?;
    }
    let writable = has_token(state.config(), &headers);
    let limits = Limits {
        timeout: state.config().timeout,
        deadline,
        ..Limits::default()
    };
    state
        .blocking(move |ctx| {
            let (store, cache) = ctx.store_and_cache();
            let source = QuerySource {
                store,
                cache,
                writable,
            };
            // Limits first: selecting the map indexes a revision, which
            // must not start past the deadline either.
            let mut session = Session::new(source);
            session.set_limits(limits);
            session.set_author(author);
            match &map {
                Some(m) => {
                    session
                        .use_map(m, rev.map(u64::from))
                        .map_err(|e| match e {
                            QueryError::Source(SourceError::NoMap { .. }) => {
                                ApiError::not_found("map", e.to_string())
                            }
                            QueryError::Source(SourceError::NoRevision { .. }) => {
                                ApiError::not_found("rev", e.to_string())
                            }
                            other => ApiError::from(other),
                        })?;
                }
                None => session.use_default_map()?,
            }
            let results = session.execute(&text)?;
            // Past the deadline the client has its 503: rendering the
            // finished statements' rows would be work for nobody.
            if limits.past_deadline() {
                return Err(ApiError::Timeout(limits.timeout.as_millis()));
            }
            let results = results
                .into_iter()
                .map(result_json)
                .collect::<Result<Vec<Value>, ApiError>>()?;
            let current = session
                .current()
                .map(|c| json!({"map": c.map, "revision": c.revision}));
            Ok(Json(json!({"using": current, "results": results})))
        })
        .await
}
