"""The paper's section 5 as bench trials, and what it reports, read off its text (the figures
themselves give no numbers; Table 1 does)."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

from tools.tararc.scenes import scene
from tools.tararc.trials import HELP_AT, BenchTrial

PAPER_TABLE1_PRINTED: dict[tuple[int, ...], str] = {
    (1, 2, 3): "33.05", (1, 3, 2): "29.25", (2, 1, 3): "20.15",
    (2, 3, 1): "33.00", (3, 1, 2): "21.525", (3, 2, 1): "∞",
}  # fmt: skip
"""The paper's Table 1 as printed (convergence time, s): quoted so, never rounded."""
PAPER_TABLE1: dict[tuple[int, ...], float] = {
    order: math.inf if text == "∞" else float(text) for order, text in PAPER_TABLE1_PRINTED.items()
}
PAPER_SAYS = {
    "density": "flat from 0.6 to 1.4, then a sharp rise: robots too close to avoid each other",
    "size": "grows as a straight line with the number of robots",
    "speed": "falls up to 1.0 m/s, then rises: above about 1.6 m/s robots collide",
    "ability": "group 2 always the most able and always gets the hardest task (0.9); group 0's ability "
               "drops after it fails its third task, and it then gets the easiest",
    "help": "7a (agent low on energy hands over) and 7b (a short group gets members of the nearest); "
            "no measurement given",
}


@dataclass(frozen=True)
class Config:
    seeds: int = 3
    densities: tuple[float, ...] = (0.6, 1.0, 1.4, 1.8, 2.2, 2.6)
    speeds: tuple[float, ...] = (0.25, 0.5, 1.0, 1.6, 2.0)
    sizes: tuple[int, ...] = (10, 20, 30, 40, 50)
    size_seeds: int = 2
    chains: int = 2
    help_seeds: int = 2
    max_time: float = 300.0
    first_seed: int = 1


QUICK = Config(seeds=1, densities=(1.0, 2.2), speeds=(0.5, 1.6), sizes=(10, 20), size_seeds=1, chains=1,
               help_seeds=1)


def main_trials(c: Config) -> list[BenchTrial]:
    """Table 1 and Figures 5 to 8: everything that does not need another trial's result."""
    seeds = range(c.first_seed, c.first_seed + c.seeds)
    out = [BenchTrial("table1", list(order), s, scene(priorities=order), max_time=c.max_time)
           for order in itertools.permutations((1, 2, 3)) for s in seeds]
    out += [BenchTrial("density", d, s, scene(density=d), max_time=c.max_time)
            for d in c.densities for s in seeds]
    out += [BenchTrial("speed", v, s, scene(speed=v), max_time=c.max_time) for v in c.speeds for s in seeds]
    out += [BenchTrial("size", n, s, scene(robots=n, tasks=3 * n // 10), max_time=c.max_time)
            for n in c.sizes for s in range(c.first_seed, c.first_seed + c.size_seeds)]
    out += ability_trials(c)
    return out


def ability_trials(c: Config) -> list[BenchTrial]:
    """Figure 8: four allocations in a row sharing one history file, the tasks auctioned hardest first
    (the paper plots "task difficulty (or priority)": the hardest has the first priority). In the
    third allocation every robot of one group fails mid-move, so its task fails, as the paper's group
    0 "implements the task very poorly, even fully fails"."""
    return [BenchTrial("ability", k, c.first_seed + 100 * k, scene(priorities=(3, 2, 1)), max_time=c.max_time,
                       runs=4, fail_group_in=3) for k in range(c.chains)]


EXPERIMENTS = ("table1", "density", "speed", "size", "ability", "help")


def help_trials(c: Config, baseline: list[dict[str, Any]]) -> list[BenchTrial]:
    """Every robot of the 10 failing once, mid-move, with n_thres 3 so that a group of 3 losing a
    member must borrow one (7b). The failure time comes from the same seed's run without failure
    (Table 1's first order), which the failure run repeats exactly up to that moment."""
    base = {r["seed"]: r for r in baseline if r["experiment"] == "table1" and r["x"] == [1, 2, 3]}
    out = []
    for s in range(c.first_seed, c.first_seed + c.help_seeds):
        run = base[s]
        if not math.isfinite(run["enclosed"]):
            continue
        at = round(run["grouped"] + HELP_AT * (run["enclosed"] - run["grouped"]), 2)
        for i in range(10):
            failure = {"robot": f"r{i + 1}", "at": at, "reason": "bench: fails mid-move"}
            out.append(BenchTrial("help", f"r{i + 1}", s, scene(failures=[failure]), {"n_thres": 3},
                                  c.max_time))
    return out
