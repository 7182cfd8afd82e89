"""A robot's battery: a charge in 0..1 that time, walking and radio use up (coefficients from the
scenario), by one of two models:

* `linear`: a real battery, monotone: idle * seconds + walk * metres walked + read * messages read.
* `eq5`: TARARC's eq. 5, bounded as docs/TARARC.md and hfsm_behaviours/tararc/formulas.energy bound it:
  S = w_tim (1+tim)^m + w_dist (1+dist)^n + w_sped (1+sped)^t, with tim the messages read, dist
  the distance from the start and sped the mean speed since the start (each over its unit). Like
  the paper's, it is not monotone: a robot back at its start, or resting, regains energy.
"""

from __future__ import annotations

import math

from hfsm_sim.specs import Eq5Battery, LinearBattery


class Battery:
    def __init__(self, spec: LinearBattery | Eq5Battery) -> None:
        self.spec = spec
        self.level = spec.start if isinstance(spec, LinearBattery) else 1.0
        self.seconds = 0.0
        self.walked = 0.0
        self.read = 0

    def drain(self, seconds: float, metres: float, from_start: float = 0.0, read: int = 0) -> None:
        """Time passed, metres walked and messages read since the last call; `from_start` is the
        distance from the start now."""
        self.seconds += seconds
        self.walked += metres
        self.read += read
        spec = self.spec
        if isinstance(spec, LinearBattery):
            self.level = max(0.0, self.level - spec.idle * seconds - spec.walk * metres - spec.read * read)
            return
        sped = self.walked / self.seconds if self.seconds > 0 else 0.0
        terms = ((spec.w_tim, self.read / spec.tim_unit, spec.m),
                 (spec.w_dist, from_start / spec.dist_unit, spec.n),
                 (spec.w_sped, sped / spec.sped_unit, spec.t))
        self.level = math.fsum(w * math.pow(1.0 + x, e) for w, x, e in terms)

    @property
    def empty(self) -> bool:
        floor = self.spec.empty if isinstance(self.spec, Eq5Battery) else 0.0
        return self.level <= floor
