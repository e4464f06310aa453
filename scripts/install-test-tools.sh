#!/usr/bin/env bash
# Installs the system tools nrgdb's tests use, when missing: xmllint
# (libxml2-utils) for IndoorGML schema validation, Chromium (Debian's
# `chromium`) for the web viewer's end-to-end test, and PostgreSQL with
# PostGIS and pgRouting (`postgresql`, `postgresql-15-postgis-3`,
# `postgresql-15-pgrouting`) for the store's
# PostgreSQL engine (the tests start a throw-away server of their own with
# scripts/pg-throwaway.sh), and GDAL's `ogrinfo` (`gdal-bin`, what QGIS
# reads vector files with) for the GeoJSON and OpenStreetMap checks. Safe to run repeatedly;
# without root or apt-get it only says what is missing (the tests that need a
# tool then skip with a notice, unless NRGDB_REQUIRE_SHARED=1).
set -u
need=()
command -v xmllint >/dev/null 2>&1 || need+=(libxml2-utils)
command -v ogrinfo >/dev/null 2>&1 || need+=(gdal-bin)
[ -x /usr/bin/chromium ] || command -v chromium >/dev/null 2>&1 || need+=(chromium)
ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1 || need+=(postgresql)
ls /usr/share/postgresql/*/extension/postgis.control >/dev/null 2>&1 || need+=(postgresql-15-postgis-3)
ls /usr/share/postgresql/*/extension/pgrouting.control >/dev/null 2>&1 || need+=(postgresql-15-pgrouting)
[ ${#need[@]} -eq 0 ] && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "install-test-tools: installing ${need[*]}" >&2
  { apt-get install -y -q "${need[@]}" || { apt-get update -q && apt-get install -y -q "${need[@]}"; }; } >/dev/null 2>&1 \
    || echo "install-test-tools: could not install ${need[*]}" >&2
else
  echo "install-test-tools: missing ${need[*]} (install them to run every test)" >&2
fi
exit 0
