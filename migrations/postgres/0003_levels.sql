-- The building level a space is on (issue 25): its name and the elevation
-- of its floor in metres; NULL for a map without levels (one floor).
ALTER TABLE spaces ADD COLUMN level_name TEXT;
ALTER TABLE spaces ADD COLUMN level_elevation DOUBLE PRECISION;
