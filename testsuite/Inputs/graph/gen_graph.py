"""Writes large graph.json files for the stack-sizing tests (signatures: sigs.json).

  gen_graph.py chain N    a chain of N nodes: leaf <- neg <- neg ...   (needs 1 slot)
  gen_graph.py tree D     a balanced binary tree of add nodes, depth D  (needs D+1 slots)

The generator is texcc_tools.testing.gen_graph (reliability/gen.py uses its chain too)."""
from texcc_tools.testing.gen_graph import main

if __name__ == "__main__":
    main()
