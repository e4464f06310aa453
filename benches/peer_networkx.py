"""Peer comparison: the same ROUTE on the same graph with networkx.

Reads nrgdb model JSON (see examples/demo_building.rs), builds the navigable
graph the way nrgdb does (spaces of kind != other, connections of kind !=
adjacent, weight = length_m) and times networkx's Dijkstra between two ids.
The graph is built once, outside the timing (nrgdb also indexes a revision
once per session). Prints microseconds per query: the best and the median of
five batches (timeit's autorange picks the batch size).

usage: python3 peer_networkx.py MODEL.json FROM_ID TO_ID
"""
import json
import os
import sys
import timeit

import networkx as nx


def main():
    path, source, target = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    with open(path) as f:
        model = json.load(f)
    graph = nx.Graph()
    navigable = {s["id"] for s in model["spaces"] if s["kind"] != "other"}
    graph.add_nodes_from(navigable)
    for c in model["connections"]:
        if c["kind"] != "adjacent" and c["a"] in navigable and c["b"] in navigable:
            graph.add_edge(c["a"], c["b"], length_m=c["length_m"])
    length, route = nx.single_source_dijkstra(graph, source, target, weight="length_m")
    timer = timeit.Timer(lambda: nx.single_source_dijkstra(graph, source, target, weight="length_m"))
    number, _ = timer.autorange()
    batches = sorted(timer.timeit(number) / number for _ in range(5))
    print(f"networkx {nx.__version__}: {os.path.basename(path)}, {len(model['spaces'])} spaces, "
          f"route {source}->{target} {length:.2f} m over {len(route)} spaces: "
          f"{batches[0] * 1e6:.1f} us/query (best of 5 batches; median batch {batches[2] * 1e6:.1f} us; "
          f"{5 * number} runs)")


if __name__ == "__main__":
    main()
