#!/bin/sh
# Peer comparison for benches/query.rs: the same corner-to-corner ROUTE on
# the same generated buildings, timed with networkx (installed with pip into
# a virtualenv under target/). Run from the crate root:
#   sh benches/peer_networkx.sh
# then compare with `cargo bench --bench query` (query/route/*-spaces).
set -eu
venv=target/peer-networkx
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet networkx
fi
for columns in 28 1875; do
    out=target/demo-$columns.json
    cargo run --quiet --example demo_building -- "$columns" "$out"
    "$venv/bin/python" benches/peer_networkx.py "$out" 3 $((5 * (columns - 1) + 5))
done
