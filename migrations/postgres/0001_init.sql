-- nrgdb PostgreSQL schema 1: the same records as the SQLite schema 1-4
-- (maps, immutable revisions as [valid_from, valid_to) row ranges, grids,
-- corrections), with PostGIS geometry beside the exact coordinates so that
-- QGIS opens the tables as layers, LOCATE uses a GiST index and pgRouting
-- runs on `route_edges`. Everything lives in the schema `nrgdb` (the
-- engine sets `search_path` to `nrgdb, public`), apart from other data.
-- Coordinates are metres in each map's own frame (SRID 0: a map has no
-- georeference yet).

CREATE TABLE maps (
    id          BIGSERIAL PRIMARY KEY,
    name        TEXT NOT NULL UNIQUE,
    created_at  TEXT NOT NULL
);

CREATE TABLE revisions (
    map_id            BIGINT NOT NULL REFERENCES maps(id),
    seq               INTEGER NOT NULL,
    parent            INTEGER,
    created_at        TEXT NOT NULL,
    source_name       TEXT,
    source_sha256     TEXT,
    params            TEXT,
    message           TEXT NOT NULL,
    author            TEXT NOT NULL,
    space_count       BIGINT NOT NULL,
    connection_count  BIGINT NOT NULL,
    spaces_added      BIGINT NOT NULL,
    spaces_changed    BIGINT NOT NULL,
    spaces_removed    BIGINT NOT NULL,
    PRIMARY KEY (map_id, seq)
);

-- One row per version of a space, valid in revisions valid_from <= r <
-- valid_to (NULL: still valid in the latest). `geometry` is the exact
-- outline (every coordinate's f64 bits, see store/geometry_blob.rs);
-- `geom` the same as a PostGIS polygon for GIS tools and the GiST index.
CREATE TABLE spaces (
    row_id      BIGSERIAL PRIMARY KEY,
    map_id      BIGINT NOT NULL REFERENCES maps(id),
    space_id    BIGINT NOT NULL,
    valid_from  INTEGER NOT NULL,
    valid_to    INTEGER,
    kind        TEXT NOT NULL,
    name        TEXT,
    attributes  JSON NOT NULL,
    anchor_x    DOUBLE PRECISION NOT NULL,
    anchor_y    DOUBLE PRECISION NOT NULL,
    geometry    BYTEA NOT NULL,
    geom        geometry(Polygon, 0) NOT NULL,
    doorway_ax  DOUBLE PRECISION,
    doorway_ay  DOUBLE PRECISION,
    doorway_bx  DOUBLE PRECISION,
    doorway_by  DOUBLE PRECISION
);
CREATE INDEX spaces_by_id ON spaces (map_id, space_id, valid_to);
CREATE INDEX spaces_open ON spaces (map_id, valid_to);
CREATE INDEX spaces_geom ON spaces USING GIST (geom);

-- Connections between stable space ids (a < b), with the line between
-- their anchors for drawing.
CREATE TABLE connections (
    map_id      BIGINT NOT NULL REFERENCES maps(id),
    a           BIGINT NOT NULL,
    b           BIGINT NOT NULL,
    valid_from  INTEGER NOT NULL,
    valid_to    INTEGER,
    kind        TEXT NOT NULL,
    length_m    DOUBLE PRECISION NOT NULL,
    geom        geometry(LineString, 0),
    PRIMARY KEY (map_id, a, b, valid_from)
);
CREATE INDEX connections_open ON connections (map_id, valid_to, a, b);

CREATE TABLE revision_grids (
    map_id      BIGINT NOT NULL,
    seq         INTEGER NOT NULL,
    width       BIGINT NOT NULL,
    height      BIGINT NOT NULL,
    resolution  DOUBLE PRECISION NOT NULL,
    origin_x    DOUBLE PRECISION NOT NULL,
    origin_y    DOUBLE PRECISION NOT NULL,
    origin_yaw  DOUBLE PRECISION NOT NULL,
    png         BYTEA NOT NULL,
    PRIMARY KEY (map_id, seq),
    FOREIGN KEY (map_id, seq) REFERENCES revisions (map_id, seq)
);

CREATE TABLE corrections (
    map_id     BIGINT NOT NULL REFERENCES maps(id),
    id         INTEGER NOT NULL,
    made_on    INTEGER NOT NULL,
    created_at TEXT NOT NULL,
    author     TEXT NOT NULL,
    statement  TEXT NOT NULL,
    rule       TEXT NOT NULL,
    state      TEXT NOT NULL CHECK (state IN ('applied', 'failed')),
    reason     TEXT,
    checked_on INTEGER NOT NULL,
    dropped_at TEXT,
    PRIMARY KEY (map_id, id)
);

-- The latest revision of every map, as GIS layers.
CREATE VIEW latest_spaces AS
    SELECT s.row_id, m.name AS map, s.space_id, s.kind, s.name, s.attributes,
           s.anchor_x, s.anchor_y, s.geom
    FROM spaces s JOIN maps m ON m.id = s.map_id
    WHERE s.valid_to IS NULL;

CREATE VIEW latest_connections AS
    SELECT m.name AS map, c.a, c.b, c.kind, c.length_m, c.geom
    FROM connections c JOIN maps m ON m.id = c.map_id
    WHERE c.valid_to IS NULL;

-- The latest revision's connections shaped for pgRouting:
--   SELECT * FROM pgr_dijkstra(
--     'SELECT id, source, target, cost, reverse_cost FROM nrgdb.route_edges WHERE map = ''lab''',
--     10, 13);
-- source and target are stable space ids; cost is the walked length in
-- metres, the same both ways. Only navigable connections (through a door
-- or an open boundary): spaces that merely share a wall are not edges.
CREATE VIEW route_edges AS
    SELECT row_number() OVER (ORDER BY c.map_id, c.a, c.b) AS id,
           m.name AS map, c.a AS source, c.b AS target,
           c.length_m AS cost, c.length_m AS reverse_cost, c.kind, c.geom
    FROM connections c JOIN maps m ON m.id = c.map_id
    WHERE c.valid_to IS NULL AND c.kind <> 'adjacent';
