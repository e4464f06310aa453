-- nrgdb schema 6: the building level a space is on (issue 25): its name
-- ("0", "M", "-1") and the elevation of its floor in metres. NULL for the
-- spaces of a map without levels (one floor).

ALTER TABLE spaces ADD COLUMN level_name TEXT;
ALTER TABLE spaces ADD COLUMN level_elevation REAL;
