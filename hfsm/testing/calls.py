"""Who calls whom in machine models: what a test runs once stand-ins replace some behaviours."""

from __future__ import annotations

from collections.abc import Iterator, Mapping

from hfsm.model import CallState, Machine, ParallelState


def callees(model: Machine) -> Iterator[str]:
    """The behaviours a machine's states and regions call."""
    for state in model.states.values():
        if isinstance(state, CallState):
            yield state.do
        elif isinstance(state, ParallelState):
            yield from (region.do for region in state.parallel.values())


def reachable(models: Mapping[str, Machine], top: str, stand_ins: set[str]) -> set[str]:
    """The machines a run of `top` enters: calls into a stand-in go no further."""
    seen = {top}
    pending = [top]
    while pending:
        for callee in callees(models[pending.pop()]):
            if callee in models and callee not in stand_ins and callee not in seen:
                seen.add(callee)
                pending.append(callee)
    return seen
