"""The campaign as trials: the issue's target rooms, then time against K and N, then radio loss."""

from __future__ import annotations

from dataclasses import dataclass

from tools.room.scenes import room
from tools.room.trials import RoomTrial

TARGET = "target"  # 3 tables, 6 to 8 robots, one random failure each, lossless: issue 10's target


@dataclass(frozen=True)
class Config:
    target_rooms: int = 14  # seeds first_seed.. , N cycling 6, 7, 8
    ks: tuple[int, ...] = (2, 3, 4, 5)  # time against K: N = 2K, no failure
    k_seeds: int = 1
    ns: tuple[int, ...] = (6, 7, 8, 9)  # time against N: K = 3, no failure
    loss_rooms: int = 2  # K = 3, N = 7, 30 % radio loss: one without failure, one with
    max_time: float = 2100.0  # the 35 simulated minutes
    fail_window: tuple[float, float] = (5.0, 150.0)
    first_seed: int = 1


QUICK = Config(target_rooms=1, ks=(2,), k_seeds=1, ns=(), loss_rooms=0, max_time=20.0)


def trials(c: Config) -> list[RoomTrial]:
    s0 = c.first_seed
    window = c.fail_window
    out = [RoomTrial(TARGET, 6 + i % 3, s0 + i, room(s0 + i, 3, 6 + i % 3, failure=True, fail_window=window),
                     max_time=c.max_time) for i in range(c.target_rooms)]
    out += [RoomTrial("k", k, s, room(s, k, 2 * k), max_time=c.max_time)
            for k in c.ks for s in range(s0 + 100, s0 + 100 + c.k_seeds)]
    out += [RoomTrial("n", n, s0 + 200, room(s0 + 200, 3, n), max_time=c.max_time) for n in c.ns]
    out += [RoomTrial("loss", 0.3, s, room(s, 3, 7, failure=i % 2 == 1, fail_window=window), radio_loss=0.3,
                      max_time=c.max_time) for i, s in enumerate(range(s0 + 300, s0 + 300 + c.loss_rooms))]
    return out
