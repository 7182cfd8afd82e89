"""What changes in an engine between two ticks, apart from the parts that wire it together.

`Engine.snapshot()` gives it, `restore_engine` builds an engine from it, and an engine pickles as it
(hfsm-verify's states): the parts (loop, calls, arcs, timers, regions, holds, the radio) are made
again on restore rather than copied with every state. The agents' trees, the world, the clock and
the team (which built-ins waiting in a barrier hold) are held as they are: a snapshot is a view,
copying it (a pickle) copies them.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from hfsm.runtime.agent import Agent
from hfsm.runtime.clock import RunClock
from hfsm.runtime.scopes import Radio
from hfsm.runtime.team import Team
from hfsm.world import World


class EngineState(NamedTuple):
    agents: list[Agent]
    world: World
    clock: RunClock  # the tick, and whether the next is due though no timer says so
    team: Team  # barriers' rounds, notices heard, agents waiting (built-ins hold it)
    running: int  # agents whose top machine has not ended
    level: int  # the run's autonomy level
    approved: Any  # the event the operator answered last (an Event), or None
    sent: int  # messages sent so far (a `send` record's id)
    radios: list[Radio]  # each agent's radio outside its machines (a scope under `--scope`)
