#!/usr/bin/env bash
# Load run of two `nrgdb serve` replicas over one PostgreSQL database, side
# by side with one server over SQLite on the same data (issue 23). Not a
# test: run by hand and record the figures in benches/README.md.
#
#   sh scripts/pg-throwaway.sh run bash benches/load_replicas.sh
#
# Needs DATABASE_URL (a database it may fill; pg-throwaway.sh sets it) and
# wrk. Stores the `nrgdb demo` building in both engines, then drives
# GET /maps/demo/route (no `rev`: every request also asks which revision is
# latest) with wrk over loopback:
#   run 1: one server over SQLite;
#   run 2: two servers over PostgreSQL, wrk on each at once (half the
#          connections each) while revisions are uploaded through the
#          first every UPLOAD_EVERY seconds; reader errors are counted.
set -euo pipefail
cd "$(dirname "$0")/.."
DURATION=${DURATION:-15s}
CONNS=${CONNS:-32}
UPLOAD_EVERY=${UPLOAD_EVERY:-0.5}
BIN=${BIN:-target/release/nrgdb}
TOKEN=load-test-token
: "${DATABASE_URL:?run under scripts/pg-throwaway.sh run …}"
command -v wrk >/dev/null || { echo "wrk not found (apt-get install wrk)" >&2; exit 2; }
[ -x "$BIN" ] || cargo build --release --bin nrgdb

WORK=$(mktemp -d)
PIDS=()
cleanup() { for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$WORK"; }
trap cleanup EXIT

"$BIN" demo --dir "$WORK/demo" --db "$WORK/load.sqlite" >/dev/null
"$BIN" demo --dir "$WORK/demo" --db "$DATABASE_URL" >/dev/null
"$BIN" export demo@1 --db "$WORK/load.sqlite" --out "$WORK/rev1.gml" >/dev/null
"$BIN" export demo@3 --db "$WORK/load.sqlite" --out "$WORK/rev3.gml" >/dev/null

serve() { # db port
    NRGDB_TOKEN=$TOKEN "$BIN" serve --db "$1" --addr "127.0.0.1:$2" >"$WORK/serve-$2.log" 2>&1 &
    PIDS+=($!)
    for _ in $(seq 100); do curl -sf "http://127.0.0.1:$2/health" >/dev/null && return; sleep 0.1; done
    echo "server on $2 did not start" >&2; cat "$WORK/serve-$2.log" >&2; exit 1
}
serve "$WORK/load.sqlite" 18181
serve "$DATABASE_URL" 18182
serve "$DATABASE_URL" 18183
ROUTE="/maps/demo/route?from=1&to=13"
for port in 18181 18182 18183; do
    curl -sf "http://127.0.0.1:$port$ROUTE" | python3 -c 'import json,sys; r=json.load(sys.stdin)["routes"][0]; print("  %.2f m" % r["distance"])'
done

echo "== run 1: one server over SQLite ($DURATION, $CONNS connections)"
wrk -t1 -c"$CONNS" -d"$DURATION" --latency "http://127.0.0.1:18181$ROUTE" >"$WORK/sqlite.txt"
cat "$WORK/sqlite.txt"

echo "== run 2: two servers over PostgreSQL, uploads through the first every ${UPLOAD_EVERY}s"
(
    i=0
    while true; do
        f="$WORK/rev$(( (i % 2) * 2 + 1 )).gml"
        curl -s -o /dev/null -w '%{http_code}\n' -H "Authorization: Bearer $TOKEN" \
            -H 'Content-Type: application/xml' --data-binary "@$f" \
            "http://127.0.0.1:18182/maps/demo/revisions?message=load+$i" >>"$WORK/uploads.txt"
        i=$((i + 1))
        sleep "$UPLOAD_EVERY"
    done
) &
PIDS+=($!)
wrk -t1 -c"$((CONNS / 2))" -d"$DURATION" --latency "http://127.0.0.1:18182$ROUTE" >"$WORK/pg-a.txt" &
A=$!
wrk -t1 -c"$((CONNS / 2))" -d"$DURATION" --latency "http://127.0.0.1:18183$ROUTE" >"$WORK/pg-b.txt"
wait "$A"
cat "$WORK/pg-a.txt" "$WORK/pg-b.txt"

line() { # name file
    echo "$1: $(awk '/Requests\/sec/ {print $2}' "$2") req/s, p99 $(awk '$1 == "99%" {print $2}' "$2"), non-2xx $(awk '/Non-2xx/ {print $NF}' "$2" | grep . || echo 0), $(grep 'Socket errors' "$2" || echo 'socket errors 0')"
}
echo "== summary ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg))"
line "SQLite, 1 server" "$WORK/sqlite.txt"
line "PostgreSQL, replica A (uploads through it)" "$WORK/pg-a.txt"
line "PostgreSQL, replica B" "$WORK/pg-b.txt"
echo "uploads: $(grep -c '^201$' "$WORK/uploads.txt" || true) created, $(grep -vc '^201$' "$WORK/uploads.txt" || true) failed"
echo "latest on A: $(curl -sf http://127.0.0.1:18182/maps/demo | python3 -c 'import json,sys; print(json.load(sys.stdin)["latest"]["seq"])'), on B: $(curl -sf http://127.0.0.1:18183/maps/demo | python3 -c 'import json,sys; print(json.load(sys.stdin)["latest"]["seq"])')"
