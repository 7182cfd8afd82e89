"""Checks of what a test gives its team: the machine's params, for every agent and per agent, and
the scripted partners that meet the agents at barriers."""

from __future__ import annotations

from typing import Any, Protocol

from hfsm.model import Machine
from hfsm.names import did_you_mean
from hfsm.spec import coerce, shown, type_ok
from hfsm.testing.model import Case, PartnerAt, TestFile
from hfsm.yamlio import Path_


class Checker(Protocol):
    file: TestFile

    def error(self, path: Path_, code: str, message: str, *, key: bool = False) -> None: ...

    def _pick(self, case: Case, name: str, case_path: Path_) -> tuple[Any, Path_]: ...


def team_params(
    checker: Checker, model: Machine, top: str, case: Case, at: Path_, agents: list[str]
) -> tuple[dict[str, Any], dict[str, dict[str, Any]]]:
    """The params of every agent, and of each agent that `agent_params` gives its own (T303, T311)."""
    given: dict[str, tuple[Any, Path_]] = {
        k: (v, ("params", k)) for k, v in (checker.file.params or {}).items()
    }
    given.update({k: (v, (*at, "params", k)) for k, v in (case.params or {}).items()})
    own: dict[str, dict[str, tuple[Any, Path_]]] = {}
    for where, by_agent in (
        (("agent_params",), checker.file.agent_params),
        ((*at, "agent_params"), case.agent_params),
    ):
        for agent, params in (by_agent or {}).items():
            if agent not in agents:
                hint = did_you_mean(agent, agents) or f" (agents: {', '.join(agents)})"
                checker.error((*where, agent), "T311", f"no agent '{agent}' in this test{hint}", key=True)
            mine = own.setdefault(agent, {})
            mine.update({k: (v, (*where, agent, k)) for k, v in params.items()})
    everyones = set.intersection(*(set(own.get(a, {})) for a in agents))  # given per agent, to each
    common = _typed(checker, model, top, given, at, given_apart=everyones)
    per_agent = {
        agent: {**common, **_typed(checker, model, top, mine, at, fill=False)}
        for agent, mine in own.items()
        if agent in agents
    }
    return common, per_agent


def _typed(
    checker: Checker,
    model: Machine,
    top: str,
    given: dict[str, tuple[Any, Path_]],
    at: Path_,
    *,
    fill: bool = True,
    given_apart: set[str] | frozenset[str] = frozenset(),
) -> dict[str, Any]:
    """The params given, typed; with `fill`, the defaults of the others (a required one: T303)."""
    params: dict[str, Any] = {}
    for key, (value, where) in given.items():
        param = model.params.get(key)
        if param is None:
            hint = (
                did_you_mean(key, model.params) or f" ('{top}' takes: {', '.join(model.params) or 'nothing'})"
            )
            checker.error(where, "T303", f"'{top}' has no param '{key}'{hint}", key=True)
        elif not type_ok(value, param.type):
            checker.error(where, "T303", f"param '{key}' of '{top}' takes {param.type}, not {shown(value)}")
        else:
            params[key] = coerce(value, param.type)
    for key, param in model.params.items():
        if key in given or not fill:
            continue
        if param.required and key not in given_apart:
            checker.error(
                at, "T303", f"'{top}' needs param '{key}' ({param.type}): give it in `params:`", key=True
            )
        elif not param.required:
            params[key] = param.default
    return params


def team_partners(checker: Checker, case: Case, at: Path_, agents: list[str]) -> list[PartnerAt]:
    """Scripted barrier partners: each a name that is not an agent of the test (T314)."""
    partners, where = checker._pick(case, "partners", at)
    for i, partner in enumerate(partners or []):
        if partner.agent in agents:
            checker.error(
                (*where, i, "agent"),
                "T314",
                f"'{partner.agent}' is an agent of the test: a partner is a team mate the test scripts",
            )
    return list(partners or [])
