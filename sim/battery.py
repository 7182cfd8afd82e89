"""A robot's battery: a charge in 0..1 that time and walking use up (coefficients from the scenario)."""

from __future__ import annotations

from sim.scenario import Battery as BatterySpec


class Battery:
    def __init__(self, spec: BatterySpec) -> None:
        self._idle = spec.idle
        self._walk = spec.walk
        self.level = spec.start

    def drain(self, seconds: float, metres: float) -> None:
        self.level = max(0.0, self.level - self._idle * seconds - self._walk * metres)

    @property
    def empty(self) -> bool:
        return self.level <= 0.0
