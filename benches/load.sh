#!/usr/bin/env bash
# Load run of `nrgdb serve` (issue #7). Not a test: run by hand, on a machine
# as quiet as you can get, and record the figures in benches/README.md.
#
#   benches/load.sh                 # 20 s per run, 32 connections
#   DURATION=30s CONNS=64 benches/load.sh
#
# Builds the release binary (once; REBUILD=1 forces it), stores the `nrgdb
# demo` building in a temporary database, serves it, and drives
# GET /maps/demo/route with wrk (Debian package `wrk`):
#   run 1: routes only;
#   run 2: routes while revisions are uploaded every UPLOAD_EVERY seconds
#          (alternately the demo's two revisions, so each upload changes
#          something), counting reader errors.
# RSS of the server is sampled every second during both runs.
# Goals: >= 20 000 req/s, p99 <= 5 ms, zero errors, flat memory.
set -euo pipefail
cd "$(dirname "$0")/.."

DURATION=${DURATION:-20s}
CONNS=${CONNS:-32}
THREADS=${THREADS:-1}
PORT=${PORT:-18080}
UPLOAD_EVERY=${UPLOAD_EVERY:-0.5}
BIN=${BIN:-target/release/nrgdb}
TOKEN=load-test-token

command -v wrk >/dev/null || { echo "wrk not found (apt-get install wrk)" >&2; exit 2; }
if [ "$BIN" = target/release/nrgdb ] && { [ ! -x "$BIN" ] || [ "${REBUILD:-0}" = 1 ]; }; then
    cargo build --release --bin nrgdb
fi

WORK=$(mktemp -d)
SERVER=
UPLOADER=
cleanup() {
    [ -n "$UPLOADER" ] && kill "$UPLOADER" 2>/dev/null || true
    [ -n "$SERVER" ] && kill -TERM "$SERVER" 2>/dev/null && wait "$SERVER" 2>/dev/null || true
    rm -rf "$WORK"
}
trap cleanup EXIT

DB="$WORK/load.sqlite"
"$BIN" demo --dir "$WORK/demo" --db "$DB" >/dev/null
"$BIN" export demo@1 --db "$DB" --out "$WORK/rev1.gml" >/dev/null
"$BIN" export demo@2 --db "$DB" --out "$WORK/rev2.gml" >/dev/null

NRGDB_TOKEN=$TOKEN "$BIN" serve --db "$DB" --addr "127.0.0.1:$PORT" >"$WORK/serve.log" 2>&1 &
SERVER=$!
BASE="http://127.0.0.1:$PORT"
for _ in $(seq 50); do
    curl -sf "$BASE/health" >/dev/null && break
    sleep 0.1
done

# The two rooms furthest apart in id order: a route across the building.
read -r FROM TO < <(curl -sf "$BASE/maps/demo/spaces?kind=room" |
    python3 -c 'import json,sys; s=[x["id"] for x in json.load(sys.stdin)["spaces"]]; print(s[0], s[-1])')
URL="$BASE/maps/demo/route?from=$FROM&to=$TO"
echo "route: $URL"
curl -sf "$URL" | python3 -c 'import json,sys; r=json.load(sys.stdin)["routes"][0]; print("  %.1f m, %d spaces, %d doors" % (r["distance"], len(r["spaces"]), len(r["doors"])))'

sample_rss() { # file
    while kill -0 "$SERVER" 2>/dev/null; do
        awk '/VmRSS/ {print $2}' "/proc/$SERVER/status" 2>/dev/null || true
        sleep 1
    done >"$1"
}

summary() { # name wrk-output rss-file
    local rps p99 errors non2xx rss
    rps=$(awk '/Requests\/sec/ {print $2}' "$2")
    p99=$(awk '$1 == "99%" {print $2}' "$2")
    errors=$(awk '/Socket errors/ {print $0}' "$2")
    non2xx=$(awk '/Non-2xx/ {print $NF}' "$2")
    rss=$(awk 'NR == 1 {first = $1} {if ($1 > max) max = $1; last = $1} END {printf "first %d KiB, max %d KiB, last %d KiB", first, max, last}' "$3")
    echo "$1: ${rps} req/s, p99 ${p99}, non-2xx ${non2xx:-0}, ${errors:-socket errors 0}; RSS $rss"
}

echo "== run 1: routes only ($DURATION, $CONNS connections, $THREADS wrk thread)"
sample_rss "$WORK/rss1" &
SAMPLER=$!
wrk -t"$THREADS" -c"$CONNS" -d"$DURATION" --latency "$URL" >"$WORK/run1.txt"
kill "$SAMPLER" 2>/dev/null || true
cat "$WORK/run1.txt"

echo "== run 2: routes while uploading a revision every ${UPLOAD_EVERY}s"
(
    i=0
    while true; do
        f="$WORK/rev$((i % 2 + 1)).gml"
        curl -s -o /dev/null -w '%{http_code}\n' -H "Authorization: Bearer $TOKEN" \
            -H 'Content-Type: application/xml' --data-binary "@$f" \
            "$BASE/maps/demo/revisions?message=load+$i" >>"$WORK/uploads.txt"
        i=$((i + 1))
        sleep "$UPLOAD_EVERY"
    done
) &
UPLOADER=$!
sample_rss "$WORK/rss2" &
SAMPLER=$!
wrk -t"$THREADS" -c"$CONNS" -d"$DURATION" --latency "$URL" >"$WORK/run2.txt"
kill "$UPLOADER" "$SAMPLER" 2>/dev/null || true
UPLOADER=
cat "$WORK/run2.txt"

echo "== summary ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg))"
summary "routes only" "$WORK/run1.txt" "$WORK/rss1"
summary "routes + uploads" "$WORK/run2.txt" "$WORK/rss2"
echo "uploads: $(grep -c '^201$' "$WORK/uploads.txt" || true) created, $(grep -vc '^201$' "$WORK/uploads.txt" || true) failed"
echo "latest revision: $(curl -sf "$BASE/maps" | python3 -c 'import json,sys; print(json.load(sys.stdin)["maps"][0]["latest"])')"
curl -sf "$BASE/metrics" | grep -E '^nrgdb_cache_(hits|misses)_total'
