"""Kept for bench/per_node_cycles.py, bench/texture_speed.py and bench/threads.py, which import
`common` by name: the helpers are texcc_tools.bench.common (python/texcc_tools/bench/)."""
from texcc_tools.bench.common import *  # noqa: F401,F403
