//! The `--db` option shared by the store subcommands, and the `NAME[@REV]`
//! syntax.

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::store::Store;

/// Where the database is.
#[derive(Debug, Clone, clap::Args)]
pub struct DbArg {
    /// The database: an SQLite file (created by `import`, `apply` or
    /// `name`) or a PostgreSQL URL `postgres://user@host/db` (PostGIS
    /// needed; nrgdb creates its schema `nrgdb` there).
    #[arg(
        long,
        env = "NRGDB_DB",
        default_value = "nrgdb.sqlite",
        value_name = "DB"
    )]
    pub db: String,
}

impl DbArg {
    /// Opens the database (creating it and its schema if needed): for the
    /// commands that write (`import`, `apply`, `name`).
    pub fn open(&self) -> miette::Result<Store> {
        Store::open_db(&self.db)
            .into_diagnostic()
            .wrap_err_with(|| format!("opening database {}", self.shown()))
    }

    /// Opens an existing database, refusing a path with no file: for the
    /// commands that only read.
    pub fn open_existing(&self) -> miette::Result<Store> {
        Store::open_existing_db(&self.db).into_diagnostic()
    }

    /// The database as messages name it (a URL without its password).
    pub fn shown(&self) -> String {
        hide_password(&self.db)
    }
}

/// `db` with the password of a `scheme://user:password@host/…` URL
/// replaced by `***`.
pub fn hide_password(db: &str) -> String {
    let Some((scheme, rest)) = db.split_once("://") else {
        return db.to_string();
    };
    match rest.split_once('@') {
        Some((user, host)) if user.contains(':') => {
            let name = user.split(':').next().unwrap_or("");
            format!("{scheme}://{name}:***@{host}")
        }
        _ => db.to_string(),
    }
}

/// Splits `NAME[@REV]` into the map name and the revision (None: latest).
pub fn parse_map_rev(text: &str) -> miette::Result<(String, Option<u32>)> {
    match text.rsplit_once('@') {
        None => Ok((text.to_string(), None)),
        Some((name, rev)) => {
            let rev: u32 = rev.parse().map_err(|_| {
                miette::miette!(
                    "bad revision '{rev}' in '{text}': expected NAME@N with N a revision number \
                     (see `nrgdb revisions {name}`)"
                )
            })?;
            Ok((name.to_string(), Some(rev)))
        }
    }
}

/// The author recorded in new revisions: `--author`, else `$NRGDB_AUTHOR`,
/// else `$USER`, else "unknown".
pub fn author(given: Option<String>) -> String {
    given
        .or_else(|| std::env::var("USER").ok())
        .filter(|a| !a.is_empty())
        .unwrap_or_else(|| "unknown".to_string())
}
