-- nrgdb schema 3: a door's doorway line (the line across its opening, from
-- one jamb to the other, metres in the map frame), as the extractor
-- measured it. NULL for other kinds and for doors stored before: those get
-- the midline of their polygon's minimum-area rectangle when read.

ALTER TABLE spaces ADD COLUMN doorway_ax REAL;
ALTER TABLE spaces ADD COLUMN doorway_ay REAL;
ALTER TABLE spaces ADD COLUMN doorway_bx REAL;
ALTER TABLE spaces ADD COLUMN doorway_by REAL;
