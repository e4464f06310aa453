#!/bin/sh
# Writes the models the peer benches (peer_networkx.sh, peer_pgrouting.sh)
# route on and prints one route per line, "MODEL.json FROM TO":
#   the generated demo buildings (examples/demo_building.rs) with 28 and 1875
#   corridor segments (150 and 10 001 spaces), corner to corner: 3 to
#   5*(columns-1)+5, as benches/query.rs routes;
#   the willow-full extraction (${NRGDB_SHARED:-../shared}/maps/willow-full.yaml,
#   skipped with a notice when missing), from its first room to the room
#   farthest from it along the room graph (benches/peer_graph.py pair).
# Run from the crate root; cargo's output goes to stderr.
set -eu
mkdir -p target
for columns in 28 1875; do
    out=target/demo-$columns.json
    cargo run --quiet --example demo_building -- "$columns" "$out" >&2
    echo "$out 3 $((5 * (columns - 1) + 5))"
done
map=${NRGDB_SHARED:-../shared}/maps/willow-full.yaml
if [ -f "$map" ]; then
    out=target/willow-full.json
    cargo run --release --quiet -- extract "$map" --json "$out" >&2
    echo "$out $(python3 benches/peer_graph.py pair "$out")"
else
    echo "notice: $map not found (set NRGDB_SHARED); skipping willow-full" >&2
fi
