//! The store engines the conformance suite runs on: memory, an SQLite
//! file in a fresh directory, and PostgreSQL with PostGIS in a fresh
//! database of a throw-away server (see [`postgres_server`]).

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

use nrgdb::store::Store;
use nrgdb::store::memory::MemoryStore;

/// One engine with a fresh, empty database; `open` gives another handle
/// onto the same database (another connection, as another process would).
pub struct EngineUnderTest {
    /// The engine's name, for messages.
    pub name: &'static str,
    open: Box<dyn Fn() -> Store + Send + Sync>,
    _dir: Option<tempfile::TempDir>,
}

impl EngineUnderTest {
    /// A handle onto this engine's database.
    pub fn open(&self) -> Store {
        (self.open)()
    }
}

/// Every engine, each with a fresh database.
pub fn engines() -> Vec<EngineUnderTest> {
    let memory = MemoryStore::new();
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("conformance.sqlite");
    let mut all = vec![
        EngineUnderTest {
            name: "memory",
            open: Box::new(move || Store::on(Box::new(memory.clone()))),
            _dir: None,
        },
        EngineUnderTest {
            name: "sqlite",
            open: Box::new(move || Store::open(&file).unwrap()),
            _dir: Some(dir),
        },
    ];
    all.extend(postgres());
    all
}

fn postgres() -> Option<EngineUnderTest> {
    let url = fresh_postgres_database()?;
    Some(EngineUnderTest {
        name: "postgres",
        open: Box::new(move || Store::open_db(&url).unwrap()),
        _dir: None,
    })
}

/// A throw-away PostgreSQL server for this test process, or its URL from
/// `NRGDB_TEST_POSTGRES` when one is given.
struct PgServer {
    url: String,
    /// `scripts/pg-throwaway.sh run …`: it stops the server and deletes its
    /// folder when our end of its stdin closes (when this process ends,
    /// however it ends).
    _child: Option<Mutex<Child>>,
}

static SERVER: OnceLock<Option<PgServer>> = OnceLock::new();
static DATABASES: AtomicUsize = AtomicUsize::new(0);

fn required() -> bool {
    std::env::var("NRGDB_REQUIRE_SHARED").as_deref() == Ok("1")
}

/// Skips (with a notice) or, under `NRGDB_REQUIRE_SHARED=1`, fails.
fn unavailable(why: &str) -> Option<PgServer> {
    assert!(
        !required(),
        "NRGDB_REQUIRE_SHARED=1 but PostgreSQL is unavailable: {why} (run scripts/install-test-tools.sh)"
    );
    eprintln!("notice: skipping the PostgreSQL engine: {why}");
    None
}

/// The throw-away server, started on first use.
pub fn postgres_server() -> Option<&'static str> {
    SERVER
        .get_or_init(|| {
            if let Ok(url) = std::env::var("NRGDB_TEST_POSTGRES") {
                return Some(PgServer { url, _child: None });
            }
            let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/pg-throwaway.sh");
            let mut child = match Command::new("sh")
                .args([
                    script,
                    "run",
                    "sh",
                    "-c",
                    "printf '%s\\n' \"$DATABASE_URL\"; read _",
                ])
                .env("PG_THROWAWAY_DB", "nrgdb_tests")
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
            {
                Ok(c) => c,
                Err(e) => return unavailable(&format!("cannot run sh: {e}")),
            };
            let mut line = String::new();
            let read = child
                .stdout
                .take()
                .map(|out| BufReader::new(out).read_line(&mut line));
            if !matches!(read, Some(Ok(n)) if n > 0) || !line.starts_with("postgres") {
                let _ = child.wait();
                return unavailable(
                    "scripts/pg-throwaway.sh could not start a server (is PostgreSQL installed?)",
                );
            }
            Some(PgServer {
                url: line.trim().to_string(),
                _child: Some(Mutex::new(child)),
            })
        })
        .as_ref()
        .map(|s| s.url.as_str())
}

/// A fresh, empty database on the throw-away server with PostGIS, as a URL.
pub fn fresh_postgres_database() -> Option<String> {
    let url = postgres_server()?;
    let mut admin = postgres::Client::connect(url, postgres::NoTls).unwrap();
    let has_postgis = admin
        .query_one(
            "SELECT COUNT(*) FROM pg_available_extensions WHERE name = 'postgis'",
            &[],
        )
        .unwrap()
        .get::<_, i64>(0)
        > 0;
    if !has_postgis {
        unavailable("PostGIS is not installed (postgresql-15-postgis-3)");
        return None;
    }
    let name = format!(
        "nrgdb_c{}_{}",
        std::process::id(),
        DATABASES.fetch_add(1, Ordering::SeqCst)
    );
    admin
        .batch_execute(&format!("CREATE DATABASE {name}"))
        .unwrap();
    let (base, _) = url.rsplit_once('/').unwrap();
    Some(format!("{base}/{name}"))
}
