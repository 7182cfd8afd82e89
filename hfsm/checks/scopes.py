"""A state's `scope:`: its expressions compile, and its literals are a name and a list of
names (E351, E352). What an expression gives is checked when the state is entered."""

from __future__ import annotations

from hfsm.checks.context import CheckContext, call_states, parallel_states
from hfsm.checks.expressions import IN_STATE, check_value
from hfsm.library import MachineFile
from hfsm.model import CallState, ParallelState
from hfsm.names import is_name


def _is_expression(value: object) -> bool:
    return isinstance(value, str) and "${" in value


def check_scopes(ctx: CheckContext, mf: MachineFile) -> None:
    states: list[tuple[str, CallState | ParallelState]] = [*call_states(mf.model), *parallel_states(mf.model)]
    for name, state in states:
        scope = state.scope
        if scope is None:
            continue
        where = ("states", name, "scope")
        check_value(ctx, mf, (*where, "name"), scope.name, IN_STATE)
        check_value(ctx, mf, (*where, "agents"), scope.agents, IN_STATE)
        if not _is_expression(scope.name) and not is_name(scope.name):
            message = f"scope name {scope.name!r} is not a name (a-z, 0-9, _; starting with a letter)"
            ctx.error(mf, (*where, "name"), "E351", message)
        agents = scope.agents
        if isinstance(agents, str):
            if not _is_expression(agents):
                message = f"scope agents must be a list of agent ids or an expression, not {agents!r}"
                ctx.error(mf, (*where, "agents"), "E352", message)
            continue
        for i, agent in enumerate(agents):
            if not _is_expression(agent) and not is_name(agent):
                message = f"scope agents must be agent ids (names), not {agent!r}"
                ctx.error(mf, (*where, "agents", i), "E352", message)
