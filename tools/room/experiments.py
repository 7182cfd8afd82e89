"""The campaign as trials: rooms drawn by the generator (hfsm_sim.roomgen), the same number in each
stratum, seeds first_seed.. in each. Seeds 1-99 were used while developing; 10000 and above are
held for measurement (docs/ROOM.md)."""

from __future__ import annotations

from dataclasses import dataclass

from hfsm_sim.roomgen import STRATA, draw
from tools.room.trials import RoomTrial

DEVELOP = range(1, 100)  # the seeds looked at while developing
HELD = 10000  # the first seed held for measurement


@dataclass(frozen=True)
class Config:
    rooms: int = 25  # per stratum
    strata: tuple[str, ...] = tuple(STRATA)
    max_time: float = 2100.0  # the 35 simulated minutes
    first_seed: int = HELD


QUICK = Config(rooms=1, strata=("open", "failures"), max_time=20.0, first_seed=1)


def trials(c: Config) -> list[RoomTrial]:
    """Stratum by stratum, seed by seed: trial i is always the same room for the same Config."""
    return [RoomTrial(stratum, stratum, seed, draw(seed, stratum), max_time=c.max_time)
            for stratum in c.strata for seed in range(c.first_seed, c.first_seed + c.rooms)]
