-- nrgdb schema 1: maps, immutable revisions, spaces and connections kept
-- with [valid_from, valid_to) revision ranges, and an R*Tree of space
-- bounding boxes. Revisions of a map form a line: parent = seq - 1.

CREATE TABLE maps (
    id          INTEGER PRIMARY KEY,
    name        TEXT NOT NULL UNIQUE,
    created_at  TEXT NOT NULL
) STRICT;

CREATE TABLE revisions (
    map_id            INTEGER NOT NULL REFERENCES maps(id),
    seq               INTEGER NOT NULL,          -- 1, 2, 3, ... per map
    parent            INTEGER,                   -- seq of the parent, NULL for the first
    created_at        TEXT NOT NULL,             -- UTC, ISO 8601
    source_name       TEXT,                      -- file the revision came from
    source_sha256     TEXT,                      -- its SHA-256, lower-case hex
    params            TEXT,                      -- extraction parameters, JSON
    message           TEXT NOT NULL,
    author            TEXT NOT NULL,
    space_count       INTEGER NOT NULL,
    connection_count  INTEGER NOT NULL,
    spaces_added      INTEGER NOT NULL,          -- rows opened / closed by
    spaces_changed    INTEGER NOT NULL,          -- this revision, for `log`
    spaces_removed    INTEGER NOT NULL,
    PRIMARY KEY (map_id, seq)
) STRICT, WITHOUT ROWID;

-- One row per version of a space: valid in revisions valid_from <= r <
-- valid_to (valid_to NULL: still valid in the latest revision).
CREATE TABLE spaces (
    row_id      INTEGER PRIMARY KEY,             -- also the R*Tree id
    map_id      INTEGER NOT NULL REFERENCES maps(id),
    space_id    INTEGER NOT NULL,                -- stable id within the map
    valid_from  INTEGER NOT NULL,
    valid_to    INTEGER,
    kind        TEXT NOT NULL,
    name        TEXT,
    attributes  TEXT NOT NULL,                   -- JSON object
    anchor_x    REAL NOT NULL,                   -- metres, map frame
    anchor_y    REAL NOT NULL,
    geometry    BLOB NOT NULL                    -- polygon and holes, see store/geometry_blob.rs
) STRICT;
CREATE INDEX spaces_by_id ON spaces(map_id, space_id, valid_to);
CREATE INDEX spaces_open ON spaces(map_id, valid_to);

CREATE VIRTUAL TABLE space_boxes USING rtree(row_id, min_x, max_x, min_y, max_y);

CREATE TABLE connections (
    map_id      INTEGER NOT NULL REFERENCES maps(id),
    a           INTEGER NOT NULL,                -- stable space ids, a < b
    b           INTEGER NOT NULL,
    valid_from  INTEGER NOT NULL,
    valid_to    INTEGER,
    kind        TEXT NOT NULL,
    length_m    REAL NOT NULL,
    PRIMARY KEY (map_id, a, b, valid_from)
) STRICT, WITHOUT ROWID;
CREATE INDEX connections_open ON connections(map_id, valid_to, a, b);
