"""One runner for every seeded campaign of tools/: local processes, a Dask cluster, or shards.

    run_sweep(fn, specs)                                   # local processes (spawn), 2 workers
    run_sweep(fn, specs, executor="dask://host:8786")      # the trials on a Dask distributed cluster
    run_sweep(fn, specs, shard=Shard(1, 4))                # trials 0, 4, 8, ... (batch schedulers)

`fn` takes one spec and returns a JSON-able dict; it must be importable by the workers (a function
of an installed package, such as `hfsm_behaviours.trial.run_trial_dict`). Every result carries its trial
index and results come back sorted by it, so a sweep gives the same results on 1 process, 2
processes or a cluster: seeds come from the specs, never from the worker.

Shards write JSON lines (`write_shard`); `merge_shards` reads them back and refuses a set that misses
or repeats a trial. The Dask executor is an optional extra: `pip install 'hfsm[dask]'`.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import Executor, ProcessPoolExecutor, as_completed
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

Result = dict[str, Any]


class SweepError(Exception):
    """A sweep that cannot run as asked: a bad executor or shard, shards that do not add up."""


@dataclass(frozen=True)
class Shard:
    """Shard `index` of `count` (1-based): the trials whose index is index-1 modulo count."""

    index: int
    count: int

    @classmethod
    def parse(cls, text: str) -> Shard:
        try:
            index, count = (int(part) for part in text.split("/"))
        except ValueError:
            raise SweepError(f"--shard takes I/N with whole numbers, as 2/4, not {text!r}") from None
        if count < 1 or not 1 <= index <= count:
            raise SweepError(f"--shard {text}: I must be between 1 and N")
        return cls(index, count)

    def picks(self, trial: int) -> bool:
        return trial % self.count == self.index - 1



def add_results_args(parser: argparse.ArgumentParser, name: str, doc: str) -> None:
    """The options of a bench that writes a doc: its section's file, its figures, its raw results,
    or `--from` a raw file, writing the docs again without running."""
    docs = Path(__file__).resolve().parent.parent / "docs"
    parser.add_argument("--doc", type=Path, default=docs / doc)
    parser.add_argument("--figures", type=Path, default=docs / "figures" / name)
    parser.add_argument("--raw", type=Path, default=docs / "results" / f"{name}.json")
    parser.add_argument("--from", dest="saved", type=Path,
                        help="no run: write the docs again from a --raw file")


def save_results(path: Path, saved: dict[str, Any]) -> None:
    """A bench's raw results, as `--from` reads them."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(saved, indent=1) + "\n", encoding="utf-8")


def add_executor_args(parser: argparse.ArgumentParser) -> None:
    """The options every sweep shares: where its trials run."""
    parser.add_argument("--workers", type=int, default=2, help="local processes (with --executor local)")
    parser.add_argument("--executor", default="local", help="local, or dask://HOST:PORT for a Dask cluster")


def run_sweep(
    fn: Callable[[Any], Result],
    specs: Sequence[Any],
    *,
    executor: str = "local",
    workers: int = 2,
    shard: Shard | None = None,
    label: str = "trials",
) -> list[Result]:
    """Run `fn` on every spec (or on the shard's), with a progress bar; results sorted by trial."""
    chosen = [(i, spec) for i, spec in enumerate(specs) if shard is None or shard.picks(i)]
    results: dict[int, Result] = {}
    with _executor(executor, workers) as pool:
        futures = {pool.submit(fn, spec): i for i, spec in chosen}
        bar = tqdm(total=len(futures), desc=label, unit="trial", file=sys.stderr, disable=None)
        with bar:
            for future in as_completed(futures):
                results[futures[future]] = {"trial": futures[future], **future.result()}
                bar.update()
    return [results[i] for i in sorted(results)]


@contextmanager
def _executor(address: str, workers: int) -> Iterator[Executor]:
    if workers < 1:
        raise SweepError(f"workers must be at least 1, not {workers}")
    if address == "local":
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
            yield pool
        return
    if not address.startswith("dask://") or not address.removeprefix("dask://"):
        raise SweepError(f"--executor takes 'local' or 'dask://HOST:PORT', not {address!r}")
    try:
        from distributed import Client
    except ImportError:
        raise SweepError("the Dask executor needs the extra: pip install 'hfsm[dask]'") from None
    with Client("tcp://" + address.removeprefix("dask://")) as client:
        yield client.get_executor(pure=False)


def shard_path(folder: Path, label: str, shard: Shard) -> Path:
    return folder / f"{label}-{shard.index}-of-{shard.count}.jsonl"


def write_shard(path: Path, results: list[Result], total: int) -> None:
    """One JSON line per result, after a header line with the size of the whole sweep."""
    path.parent.mkdir(parents=True, exist_ok=True)
    lines = [json.dumps({"total": total}), *(json.dumps(r, default=str) for r in results)]
    path.write_text("\n".join(lines) + "\n")


def merge_shards(paths: Sequence[Path], complete: bool = True) -> list[Result]:
    """The results of several shards as one sweep, sorted by trial; every trial exactly once (with
    `complete` false, the trials of the shards there are: a campaign cut short)."""
    totals: set[int] = set()
    results: dict[int, Result] = {}
    for path in paths:
        header, *rows = path.read_text().splitlines()
        totals.add(json.loads(header)["total"])
        for row in rows:
            result = json.loads(row)
            if result["trial"] in results:
                raise SweepError(f"{path}: trial {result['trial']} is also in another shard")
            results[result["trial"]] = result
    if len(totals) != 1:
        raise SweepError(f"the shards come from sweeps of different sizes: {sorted(totals)}")
    missing = sorted(set(range(totals.pop())) - set(results))
    if missing and complete:
        more = " ..." if len(missing) > 10 else ""
        raise SweepError(f"trials missing from the shards: {missing[:10]}{more}")
    return [results[i] for i in sorted(results)]
