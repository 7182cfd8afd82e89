"""Helpers of tools/bench_engine.py: the timing harness, hfsm's workloads and the peers' adapters."""
