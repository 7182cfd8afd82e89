"""tools/bench_verify_workers.py: one search on one process and on workers, each a process of its own."""

from __future__ import annotations

from helpers import load_tool

bench = load_tool("bench_verify_workers")


def test_a_search_is_timed_with_its_workers_cpu() -> None:
    name, args = bench.cases(300)[0]
    small = [*args, "--param", "limit=5"]
    alone, two = bench.one(small, 1), bench.one(small, 2)
    assert name.startswith("call_off")
    assert (alone["verdict"], two["verdict"]) == ("ok", "ok")
    assert alone["states"] == two["states"] > 100
    assert alone["cpu"] > 0 and two["cpu"] > 0
