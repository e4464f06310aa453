#!/bin/sh
# Peer comparison for benches/query.rs and benches/route.rs: the same ROUTEs
# as benches/peer_networkx.sh (benches/peer_models.sh: the generated 150- and
# 10 001-space buildings corner to corner, and the willow-full extraction),
# timed with pgRouting's pgr_dijkstra in a throw-away PostgreSQL
# (scripts/pg-throwaway.sh). Run from the crate root:
#   sh benches/peer_pgrouting.sh
# As root without pgRouting, it apt-get installs postgresql-<major>-pgrouting.
#
# Each graph is one edge table (id, source, target, cost = length_m; the graph
# of benches/peer_graph.py, undirected: directed => false, no reverse_cost),
# loaded once. A query is what a client sends: pgr_dijkstra over that table,
# all route rows returned (pgRouting reads the edges and builds its graph in
# every call; there is no prebuilt graph to keep between queries). pgbench
# runs it on one connection with prepared statements: a warm-up of 10, then
# N transactions, N = PEER_SECONDS (default 5) / the warm-up's median,
# clamped to 20..2000. Prints the median and p90 latency per query as pgbench
# sees it (loopback unix socket, round trip included).
set -eu
seconds=${PEER_SECONDS:-5}
. scripts/pg-throwaway.sh

bindir=$(_pgt_bindir 2>/dev/null || true)
if [ -z "$bindir" ] || [ ! -f "$("$bindir/pg_config" --sharedir)/extension/pgrouting.control" ]; then
    pg_throwaway_install pgrouting
    bindir=$(_pgt_bindir)
fi

# Models first (cargo may build), then the server.
mkdir -p target
sh benches/peer_models.sh >target/peer-routes.txt
work=target/peer-pgrouting
rm -rf "$work"
mkdir -p "$work"

pg_throwaway_start
psql="$PG_THROWAWAY_BINDIR/psql -X -q -v ON_ERROR_STOP=1"
$psql -c 'create extension pgrouting cascade' 2>/dev/null
versions=$($psql -Atc "select 'pgRouting ' || pgr_version() || ' (PostgreSQL ' || current_setting('server_version') || ')'")
versions=${versions% (Debian*}
case "$versions" in *')') ;; *) versions="$versions)" ;; esac

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
p90() { sort -n | awk '{ v[NR] = $1 } END { i = int(NR * 0.9 + 0.999999); if (i < 1) i = 1; print v[i] }'; }

while read -r model from to; do
    name=$(basename "$model" .json)
    table=edges_$(printf '%s' "$name" | tr -c 'a-zA-Z0-9\n' '_')
    $psql -c "create table $table (id bigint primary key, source bigint not null, target bigint not null, cost float8 not null)"
    python3 benches/peer_graph.py edges "$model" | $psql -c "\\copy $table from stdin with (format csv)"
    $psql -c "analyze $table"
    edges_sql="SELECT id, source, target, cost FROM $table"
    query="SELECT seq, node, edge, cost, agg_cost FROM pgr_dijkstra('$edges_sql', :from::bigint, :to::bigint, directed => false);"
    check=$($psql -Atc "select count(*) || ' ' || round(max(agg_cost)::numeric, 2) from pgr_dijkstra('$edges_sql', $from, $to, directed => false)")
    spaces=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["spaces"]))' "$model")
    printf '%s\n' "$query" >"$work/$name.sql"
    bench() { # COUNT PREFIX: pgbench COUNT transactions, one latency (us) per line on stdout
        "$PG_THROWAWAY_BINDIR/pgbench" -n -M prepared -c 1 -j 1 -t "$1" -D from="$from" -D to="$to" \
            -f "$work/$name.sql" -l --log-prefix="$work/$2" >"$work/$2.out" 2>&1 ||
            { cat "$work/$2.out" >&2; return 1; }
        cat "$work/$2".[0-9]* | awk '{ print $3 }'
    }
    warm=$(bench 10 "$name-warm" | median)
    count=$(awk -v s="$seconds" -v m="$warm" 'BEGIN { n = int(s * 1e6 / (m > 0 ? m : 1)); if (n < 20) n = 20; if (n > 2000) n = 2000; print n }')
    bench "$count" "$name" >"$work/$name.us"
    set -- $check
    printf '%s: %s.json, %s spaces, route %s->%s %s m over %s spaces: %s us/query (median of %s; p90 %s us; pgbench -M prepared, 1 connection)\n' \
        "$versions" "$name" "$spaces" "$from" "$to" "$2" "$1" \
        "$(median <"$work/$name.us")" "$count" "$(p90 <"$work/$name.us")"
done <target/peer-routes.txt
