"""The room graph the peer benches route on, from nrgdb model JSON (standard
library only, so it runs without the networkx virtualenv).

The graph is the one benches/peer_networkx.py builds: spaces of kind != other,
connections of kind != adjacent between two such spaces, weight = length_m,
undirected; one edge per pair of spaces (the last connection listed wins, as
in networkx's Graph).

usage:
  python3 peer_graph.py edges MODEL.json   CSV id,source,target,cost on stdout
  python3 peer_graph.py pair MODEL.json    "FROM TO": the first room (file
      order) and the room farthest from it along the graph (ties: lower id)
"""
import heapq
import json
import sys


def edges(model):
    navigable = {s["id"] for s in model["spaces"] if s["kind"] != "other"}
    out = {}
    for c in model["connections"]:
        if c["kind"] != "adjacent" and c["a"] in navigable and c["b"] in navigable:
            out[frozenset((c["a"], c["b"]))] = (c["a"], c["b"], c["length_m"])
    return list(out.values())


def pair(model):
    adjacency = {}
    for a, b, w in edges(model):
        adjacency.setdefault(a, []).append((b, w))
        adjacency.setdefault(b, []).append((a, w))
    rooms = [s["id"] for s in model["spaces"] if s["kind"] == "room"]
    source = rooms[0]
    dist = {source: 0.0}
    heap = [(0.0, source)]
    while heap:
        d, u = heapq.heappop(heap)
        if d > dist[u]:
            continue
        for v, w in adjacency.get(u, ()):
            if d + w < dist.get(v, float("inf")):
                dist[v] = d + w
                heapq.heappush(heap, (d + w, v))
    target = max((r for r in rooms if r in dist), key=lambda r: (dist[r], -r))
    return source, target


def main():
    command, path = sys.argv[1], sys.argv[2]
    with open(path) as f:
        model = json.load(f)
    if command == "edges":
        for i, (a, b, w) in enumerate(edges(model), 1):
            print(f"{i},{a},{b},{w!r}")
    elif command == "pair":
        print(*pair(model))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
