-- A map's georeference (issue 24): WGS84 origin, heading and level as JSON,
-- kept with the map across its revisions; NULL when the map has none.
ALTER TABLE maps ADD COLUMN georef TEXT;
