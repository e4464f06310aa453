-- nrgdb schema 4: corrections (issue 22). Each edit made through the query
-- language (MERGE, SPLIT, ADD DOOR, REMOVE DOOR, SET, UNSET) is kept as a
-- rule: the edit and the footprints of the spaces it named (JSON), so that
-- it is applied again to every later import of the map. `state` is what
-- happened at the last import (`applied`, or `failed` with `reason`);
-- `dropped_at` is set when someone dropped it (kept for the record).

CREATE TABLE corrections (
    map_id     INTEGER NOT NULL REFERENCES maps(id),
    id         INTEGER NOT NULL,
    made_on    INTEGER NOT NULL,
    created_at TEXT    NOT NULL,
    author     TEXT    NOT NULL,
    statement  TEXT    NOT NULL,
    rule       TEXT    NOT NULL,
    state      TEXT    NOT NULL CHECK (state IN ('applied', 'failed')),
    reason     TEXT,
    checked_on INTEGER NOT NULL,
    dropped_at TEXT,
    PRIMARY KEY (map_id, id)
);
