-- nrgdb schema 2: the occupancy grid a revision was extracted from (when it
-- was imported from a ROS .yaml map), so revisions from different mapping
-- runs can be aligned before diffing (`nrgdb diff NAME A B --align`).

CREATE TABLE revision_grids (
    map_id      INTEGER NOT NULL REFERENCES maps(id),
    seq         INTEGER NOT NULL,                -- the revision
    width       INTEGER NOT NULL,                -- pixels
    height      INTEGER NOT NULL,
    resolution  REAL NOT NULL,                   -- metres per pixel
    origin_x    REAL NOT NULL,                   -- map-frame pose of the lower-left corner
    origin_y    REAL NOT NULL,
    origin_yaw  REAL NOT NULL,
    png         BLOB NOT NULL,                   -- 8-bit grey PNG: 255 free, 0 occupied, 205 unknown
    PRIMARY KEY (map_id, seq),
    FOREIGN KEY (map_id, seq) REFERENCES revisions(map_id, seq)
) STRICT, WITHOUT ROWID;
