#!/bin/sh
# Peer comparison for benches/query.rs and benches/route.rs: the same ROUTEs
# on the same buildings (benches/peer_models.sh: the generated 150- and
# 10 001-space buildings corner to corner, and the willow-full extraction),
# timed with networkx (installed with pip into a virtualenv under target/).
# Run from the crate root:
#   sh benches/peer_networkx.sh
# then compare with `cargo bench --bench query` (query/route/*-spaces) and
# `sh benches/peer_pgrouting.sh` (same routes with pgRouting).
set -eu
venv=target/peer-networkx
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet networkx
fi
mkdir -p target
sh benches/peer_models.sh >target/peer-routes.txt
while read -r model from to; do
    "$venv/bin/python" benches/peer_networkx.py "$model" "$from" "$to"
done <target/peer-routes.txt
