"""A tick's time as the trace writes it: `encode(round(k * dt, 9))`, the JSON of RunClock.time."""

from __future__ import annotations

from math import gcd

NANO = 10**9


def seconds_text(ticks: int, dt: float) -> str:
    """`encode(round(ticks * dt, 9))`.

    `round` and `f"{x:.9f}"` make the same correctly rounded 9 decimals; from 1e-4 to 1e6 s they have
    at most 15 digits, so `repr` of the rounded float writes them back, without an exponent: the
    rounding's float and its `repr` are not needed (half the cost)."""
    x = ticks * dt
    if 1e-4 <= x < 1e6:
        text = f"{x:.9f}".rstrip("0")
        return text + "0" if text[-1] == "." else text
    return float.__repr__(round(x, 9))


class TickTimes:
    """`seconds_text(k, dt)` for every tick k of one dt, from a table when dt has at most 9 decimals.

    Then k * dt is exactly `k * ns` nanoseconds (ns = dt in ns, an integer) once rounded to 9
    decimals: below 1e6 s the product's error is under 2e-10 s. The decimals repeat every `period`
    ticks (1e9 / gcd(1e9, ns)), each period adding `whole` seconds; the table holds, for each tick of
    a period, its whole seconds and its decimals as text (`.05`, `.0`). Written back by `repr`, such a
    number of at most 15 digits in [1e-4, 1e6) is those digits, without trailing zeros."""

    PERIOD = 4096  # the longest table made

    def __init__(self, dt: float) -> None:
        self.dt = dt
        ns = round(dt * NANO)
        period = NANO // gcd(NANO, ns) if ns > 0 else 0
        if ns > 0 and ns / NANO == dt and dt >= 1e-4 and period <= self.PERIOD:
            self.period = period
            self.whole = period * ns // NANO
            self.limit = -(-(10**6 * NANO) // ns)  # the first tick at 1e6 s or later
            self.table = [_split(r * ns) for r in range(period)]
        else:
            self.period, self.whole, self.limit, self.table = 1, 0, 0, []

    def heads(self, tick: int, count: int) -> list[str]:
        """`{"t": ` and the time of `tick` and of the ticks after it, `count` at most: as many as its
        table's period holds after it (a whole second's text made once for them)."""
        if tick >= self.limit:
            return ['{"t": ' + seconds_text(tick, self.dt)]
        q, r = divmod(tick, self.period)
        base = q * self.whole
        wholes: dict[int, str] = {}
        out = []
        for whole, decimals in self.table[r : min(self.period, r + count, r + self.limit - tick)]:
            text = wholes.get(whole)
            if text is None:
                text = wholes[whole] = f'{{"t": {base + whole}'
            out.append(text + decimals)
        return out

    def text(self, tick: int) -> str:
        if tick < self.limit:
            q, r = divmod(tick, self.period)
            whole, decimals = self.table[r]
            return f"{q * self.whole + whole}{decimals}"
        return seconds_text(tick, self.dt)


def _split(ns: int) -> tuple[int, str]:
    whole, rest = divmod(ns, NANO)
    return whole, (f".{rest:09d}".rstrip("0") if rest else ".0")
