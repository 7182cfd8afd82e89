"""The campaign as trials: the issue's target rooms, time against K and N (with and without a failure),
failure rates (the scenario's `rate:` form) and radio loss (the same rooms at 0, 0.1 and 0.3)."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from tools.room.scenes import room
from tools.room.trials import RoomTrial

TARGET = "target"  # 3 tables, 6 to 8 robots, one random failure each, lossless: issue 10's target
GRID = "kn"  # K = 2..5 tables, N = 2K..2K+3 robots
RATE = "rate"  # K = 3, N = 7, every robot at risk at a rate (failures per robot per minute)
LOSS = "loss"  # the first target rooms again, at a radio loss


@dataclass(frozen=True)
class Config:
    target_rooms: int = 40  # seeds first_seed.. , N cycling 6, 7, 8
    ks: tuple[int, ...] = (2, 3, 4, 5)
    extra: tuple[int, ...] = (0, 1, 2, 3)  # N = 2K + extra
    kn_seeds: int = 2  # per (K, N): the first without failure, the others with one failure each
    rates: tuple[float, ...] = (0.02, 0.05)  # failures per robot per minute
    rate_seeds: int = 3
    losses: tuple[float, ...] = (0.1, 0.3)
    loss_rooms: int = 4  # the first target rooms, each again at every loss
    max_time: float = 2100.0  # target rooms: the 35 simulated minutes
    other_max_time: float = 600.0  # the other sets (every room cleared so far ended by 400 s): wall time
    fail_window: tuple[float, float] = (5.0, 150.0)
    first_seed: int = 1


QUICK = Config(target_rooms=1, ks=(2,), extra=(0,), kn_seeds=1, rates=(), losses=(), max_time=20.0,
               other_max_time=20.0)


def _rated(scenario: dict[str, Any], rate: float) -> dict[str, Any]:
    return {**scenario, "failures": [{"rate": rate, "reason": "bench: failure rate"}]}


def trials(c: Config) -> list[RoomTrial]:
    s0, window = c.first_seed, c.fail_window
    target = [RoomTrial(TARGET, 6 + i % 3, s0 + i, room(s0 + i, 3, 6 + i % 3, failure=True,
                                                        fail_window=window), max_time=c.max_time)
              for i in range(c.target_rooms)]
    grid = [RoomTrial(GRID, (k, 2 * k + e), s, room(s, k, 2 * k + e, failure=j > 0, fail_window=window),
                      max_time=c.other_max_time)
            for k in c.ks for e in c.extra for j, s in enumerate(range(s0 + 100, s0 + 100 + c.kn_seeds))]
    rated = [RoomTrial(RATE, rate, s, _rated(room(s, 3, 7), rate), max_time=c.other_max_time)
             for rate in c.rates for s in range(s0 + 200, s0 + 200 + c.rate_seeds)]
    lossy = [replace(t, experiment=LOSS, x=loss, radio_loss=loss, max_time=c.other_max_time)
             for loss in c.losses for t in target[:c.loss_rooms]]
    return target + grid + rated + lossy
