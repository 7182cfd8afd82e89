from __future__ import annotations

from pathlib import Path

import pytest
from helpers import load_tool
from sweep_task import run_example

SWEEP = load_tool("sweep")
SPECS = [{"example": name, "seed": seed} for name in ("ping_pong.yaml", "hello.yaml") for seed in range(3)]


def test_shard_parse_and_partition() -> None:
    shards = [SWEEP.Shard.parse(f"{i}/3") for i in (1, 2, 3)]
    picked = [[t for t in range(10) if s.picks(t)] for s in shards]
    assert picked == [[0, 3, 6, 9], [1, 4, 7], [2, 5, 8]]
    for bad in ("0/3", "4/3", "1/0", "a/b", "1"):
        with pytest.raises(SWEEP.SweepError):
            SWEEP.Shard.parse(bad)


def test_bad_executor_is_a_clear_error() -> None:
    with pytest.raises(SWEEP.SweepError, match="dask://HOST:PORT"):
        SWEEP.run_sweep(run_example, SPECS, executor="ray://x")


def test_one_process_two_processes_and_shards_agree(tmp_path: Path) -> None:
    one = SWEEP.run_sweep(run_example, SPECS, workers=1)
    two = SWEEP.run_sweep(run_example, SPECS, workers=2)
    assert [r["trial"] for r in one] == list(range(len(SPECS)))
    assert one == two
    assert {r["code"] for r in one} == {0}
    paths = []
    for shard in (SWEEP.Shard(1, 2), SWEEP.Shard(2, 2)):
        part = SWEEP.run_sweep(run_example, SPECS, workers=1, shard=shard)
        paths.append(SWEEP.shard_path(tmp_path, "t", shard))
        SWEEP.write_shard(paths[-1], part, len(SPECS))
    assert SWEEP.merge_shards(paths) == one
    with pytest.raises(SWEEP.SweepError, match="missing"):
        SWEEP.merge_shards(paths[:1])
    assert SWEEP.merge_shards(paths[:1], complete=False) == one[::2]  # a campaign cut short: what ran
    with pytest.raises(SWEEP.SweepError, match="also in another shard"):
        SWEEP.merge_shards([paths[0], paths[0], paths[1]])


def test_a_two_worker_dask_cluster_gives_the_same_results() -> None:
    distributed = pytest.importorskip("distributed")
    local = SWEEP.run_sweep(run_example, SPECS, workers=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, host="127.0.0.1") as cluster:
        address = cluster.scheduler_address.removeprefix("tcp://")
        on_cluster = SWEEP.run_sweep(run_example, SPECS, executor=f"dask://{address}")
    assert on_cluster == local
