"""Read a test file and check it: every problem at its `FILE:LINE:COL`, all at once (exit 2)."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

from hfsm import located
from hfsm.autonomy import Decision, decision_of, decision_problems
from hfsm.builtins import BUILTINS
from hfsm.checks.context import machine_spec
from hfsm.cli.quiet import stdout_to_stderr
from hfsm.errors import Finding, UserError
from hfsm.library import PROJECT_MACHINES, SUFFIXES, Library, shown
from hfsm.load import Loaded, load
from hfsm.names import did_you_mean
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec
from hfsm.testing.calls import callees, reachable
from hfsm.testing.check_expect import check_expect
from hfsm.testing.check_team import team_params, team_partners
from hfsm.testing.model import ByAgent, Case, Expect, FailAt, StandIn, Step, TestFile
from hfsm.testing.plan import CasePlan, StandInPlan
from hfsm.yamlio import Document, Path_, read_mapping

DEFAULT_DT = 0.05
DEFAULT_MAX_TIME = 3600.0


@functools.cache
def full_registry() -> Registry:
    """Every primitive installed, of every world: stand-ins are checked against their declarations."""
    with stdout_to_stderr():
        return Registry.discover()


def read_test_file(path: Path, registry: Registry | None = None, text: str | None = None) -> list[CasePlan]:
    """Every case of the file, checked (`text`: the file's text, when not the disk's)."""
    doc = read_mapping(shown(path), "a behaviour test", text=text)
    model = located.validate(TestFile, doc)
    checker = _FileChecker(path, doc, model, registry or full_registry())
    plans = [checker.case(name, case) for name, case in model.tests.items()]
    if checker.findings:
        raise UserError(checker.findings)
    return [p for p in plans if p is not None]


class _FileChecker:
    def __init__(self, path: Path, doc: Document, model: TestFile, registry: Registry) -> None:
        self.path = path
        self.doc = doc
        self.registry = registry
        self.file = model
        self.findings: list[Finding] = []
        self._loaded: dict[tuple[Path, tuple[Path, ...]], Loaded | None] = {}

    def error(self, path: Path_, code: str, message: str, *, key: bool = False) -> None:
        self.findings.append(self.doc.finding(path, code, message, key=key))

    def _pick(self, case: Case, name: str, case_path: Path_) -> tuple[Any, Path_]:
        """A setting and where it was written: the case's own, else the file's."""
        value = getattr(case, name)
        if value is not None:
            return value, (*case_path, name)
        return getattr(self.file, name), (name,)

    def case(self, name: str, case: Case) -> CasePlan | None:
        at: Path_ = ("tests", name)
        before = len(self.findings)
        machine, machine_at = self._pick(case, "machine", at)
        if machine is None:
            self.error(
                at, "T300", "no machine to test: give `machine:` here or at the top of the file", key=True
            )
            return None
        libs, _ = self._pick(case, "lib", at)
        loaded = self._load(machine, machine_at, libs or [])
        if loaded is None:
            return None
        top = loaded.roots[0]
        agents, agents_at = self._pick(case, "agents", at)
        agents = agents or ["robot"]
        if len(set(agents)) != len(agents):
            self.error(agents_at, "T301", "agent names must be distinct")
        params, agent_params = team_params(self, top.model, top.name, case, at, list(agents))
        partners = team_partners(self, case, at, list(agents))
        stand_ins = self._stand_ins(loaded, case, at, set(agents))
        pruned = self._world_free(loaded, top.name, stand_ins, machine_at)
        inputs, messages, fail = self._script(case, at, set(agents))
        decisions = self._decisions(case, at, list(agents))
        if (case.expect is None) == (case.verify is None):
            self.error(at, "T330", "a case needs `expect` (one run) or `verify` (every run)", key=True)
        given = case.expect or Expect()
        expect = check_expect(self, loaded, stand_ins, given, (*at, "expect"), set(agents))
        if len(self.findings) > before:
            return None
        return CasePlan(
            file=str(shown(self.path)),
            name=name,
            doc=self.doc,
            path=at,
            loaded=loaded,
            registry=self.registry,
            top=top.name,
            agents=list(agents),
            params=params,
            agent_params=agent_params,
            seed=self._pick(case, "seed", at)[0] or 0,
            dt=self._pick(case, "dt", at)[0] or DEFAULT_DT,
            max_time=self._pick(case, "max_time", at)[0] or DEFAULT_MAX_TIME,
            stand_ins=stand_ins,
            inputs=inputs,
            messages=messages,
            fail=fail,
            partners=partners,
            autonomy=self._pick(case, "autonomy", at)[0] or "full",
            decisions=decisions,
            expect=expect,
            expect_path=(*at, "expect"),
            pruned=pruned,
            verify=case.verify,
            scopes=self._scopes(case, at),
        )

    # --- the machine and its params ------------------------------------------------------------

    def _load(self, machine: str, at: Path_, libs: list[str]) -> Loaded | None:
        here = self.path.resolve().parent
        lib_paths = tuple(here / lib for lib in libs)
        path = self._find(machine, at, here, list(lib_paths))
        if path is None:
            return None
        key = (path.resolve(), lib_paths)
        if key not in self._loaded:
            try:
                self._loaded[key] = load([path], libs=list(lib_paths), registry=self.registry)
            except UserError as err:
                self.findings.extend(err.findings)
                self._loaded[key] = None
        return self._loaded[key]

    def _find(self, machine: str, at: Path_, here: Path, libs: list[Path]) -> Path | None:
        if "/" in machine or machine.endswith(SUFFIXES):
            path = here / machine
            if path.is_file():
                return path
            self.error(at, "T302", f"no machine file {machine} (paths are read from this file's folder)")
            return None
        library = Library([here, *libs, PROJECT_MACHINES], self.registry)
        found = library.find(machine)
        if found is None:
            names = {
                p.stem for d in library.search if d.is_dir() for p in d.iterdir() if p.suffix in SUFFIXES
            }
            hint = did_you_mean(machine, names)
            self.error(
                at,
                "T302",
                f"no machine '{machine}' in {', '.join(map(str, map(shown, library.search)))}{hint}",
            )
        return found

    # --- stand-ins -----------------------------------------------------------------------------

    def _stand_ins(self, loaded: Loaded, case: Case, at: Path_, agents: set[str]) -> dict[str, StandInPlan]:
        merged: dict[str, tuple[StandIn, Path_]] = {
            n: (s, ("stand_ins", n)) for n, s in (self.file.stand_ins or {}).items()
        }
        merged.update({n: (s, (*at, "stand_ins", n)) for n, s in (case.stand_ins or {}).items()})
        plans = {}
        for name, (stand_in, where) in merged.items():
            spec = self._spec(loaded, name, where)
            if spec is not None:
                plans[name] = StandInPlan(spec, self._scripts(spec, stand_in, where, agents))
        return plans

    def _spec(self, loaded: Loaded, name: str, where: Path_) -> BehaviourSpec | None:
        if name in BUILTINS:
            self.error(
                where, "T310", f"'{name}' is a built-in: script what it waits for, not the built-in", key=True
            )
            return None
        if name in loaded.machines:
            return machine_spec(loaded.machines[name])
        prim = self.registry.get(name)
        if prim is not None:
            return prim.spec
        known = set(loaded.machines) | set(self.registry.names())
        self.error(
            where, "T310", f"no behaviour '{name}' to stand in for{did_you_mean(name, known)}", key=True
        )
        return None

    def _scripts(
        self, spec: BehaviourSpec, stand_in: StandIn, where: Path_, agents: set[str]
    ) -> dict[str | None, list[Step]]:
        if isinstance(stand_in, ByAgent):
            scripts: dict[str | None, list[Step]] = {}
            for agent, script in stand_in.by_agent.items():
                if agent not in agents:
                    hint = did_you_mean(agent, agents) or f" (agents: {', '.join(sorted(agents))})"
                    self.error(
                        (*where, "by_agent", agent),
                        "T311",
                        f"no agent '{agent}' in this test{hint}",
                        key=True,
                    )
                steps = script if isinstance(script, list) else [script]
                scripts[agent] = self._steps(
                    spec, steps, (*where, "by_agent", agent), isinstance(script, list)
                )
            return scripts
        steps = stand_in if isinstance(stand_in, list) else [stand_in]
        return {None: self._steps(spec, steps, where, isinstance(stand_in, list))}

    def _steps(self, spec: BehaviourSpec, steps: list[Step], where: Path_, listed: bool) -> list[Step]:
        for i, step in enumerate(steps):
            at = (*where, i) if listed else where
            if step.outcome is not None and step.outcome not in spec.outcomes:
                hint = did_you_mean(step.outcome, spec.outcomes) or f" (it has: {', '.join(spec.outcomes)})"
                self.error((*at, "outcome"), "T312", f"'{spec.name}' has no outcome '{step.outcome}'{hint}")
            for output in step.outputs:
                if spec.outputs is not None and output not in spec.outputs:
                    declared = ", ".join(sorted(spec.outputs)) or "none"
                    hint = did_you_mean(output, spec.outputs) or f" (it declares: {declared})"
                    self.error(
                        (*at, "outputs", output),
                        "T312",
                        f"'{spec.name}' has no output '{output}'{hint}",
                        key=True,
                    )
        return steps

    def _world_free(self, loaded: Loaded, top: str, stand_ins: dict[str, StandInPlan], at: Path_) -> set[str]:
        """Machines that only stand-ins call (not run); an error names each world primitive left in."""
        models = {n: m.model for n, m in loaded.machines.items()}
        run = reachable(models, top, set(stand_ins))
        called = {c for m in run for c in callees(models[m])}
        worldly = sorted(
            n for n in called - set(stand_ins) if (p := self.registry.get(n)) is not None and p.spec.world
        )
        if worldly:
            world = self.registry.get(worldly[0]).spec.world  # type: ignore[union-attr]
            self.error(
                at, "T313",
                f"'{top}' calls primitives of world '{world}' with no stand-in: {', '.join(worldly)}; "
                "add each to `stand_ins:` (tests run without a world)",
            )  # fmt: skip
        return set(models) - run

    def _scopes(self, case: Case, at: Path_) -> dict[str, tuple[str, tuple[str, ...]]]:
        """Each agent's scope: the first of `scopes` that lists it."""
        scopes, _ = self._pick(case, "scopes", at)
        given: dict[str, tuple[str, tuple[str, ...]]] = {}
        for scope in scopes or []:
            for agent in scope.agents:
                given.setdefault(agent, (scope.name, tuple(scope.agents)))
        return given

    # --- scripted inputs and messages ----------------------------------------------------------

    def _known_agent(self, at: Path_, name: str | None, agents: set[str]) -> None:
        """T311 for an agent the test does not have (None: every agent, always known)."""
        if name is not None and name not in agents:
            self.error(at, "T311", f"no agent '{name}' in this test{did_you_mean(name, agents)}")

    def _script(self, case: Case, at: Path_, agents: set[str]) -> tuple[list[Any], list[Any], list[FailAt]]:
        inputs, inputs_at = self._pick(case, "inputs", at)
        messages, messages_at = self._pick(case, "messages", at)
        fail, fail_at = self._pick(case, "fail", at)
        named = ((fail_at, fail, "agent"), (inputs_at, inputs, "agent"), (messages_at, messages, "to"))
        for where, items, key in named:
            for i, item in enumerate(items or []):
                self._known_agent((*where, i, key), getattr(item, key), agents)
        return (
            [(e, (*inputs_at, i)) for i, e in enumerate(inputs or [])],
            [(m, (*messages_at, i)) for i, m in enumerate(messages or [])],
            list(fail or []),
        )

    def _decisions(self, case: Case, at: Path_, agents: list[str]) -> list[Decision]:
        """The operator's records, each checked as `--operator` checks them (T315)."""
        records, records_at = self._pick(case, "operator", at)
        decisions = []
        for i, record in enumerate(records or []):
            item = record.model_dump(exclude_none=True)
            problems = decision_problems(item, agents)
            for key, message in problems:
                self.error((*records_at, i, key), "T315", message)
            if not problems:
                decisions.append(decision_of(item))
        return decisions


TEST_SUFFIXES = (".test.yaml", ".test.yml")


def is_test_file(path: Path) -> bool:
    return path.name.endswith(TEST_SUFFIXES)


def find_test_files(paths: list[Path]) -> list[Path]:
    """The `*.test.yaml` files named, or found under the folders named, in order."""
    found: list[Path] = []
    for path in paths:
        if path.is_dir():
            found.extend(sorted(p for p in path.rglob("*.test.y*ml") if p.is_file() and is_test_file(p)))
        else:
            found.append(path)
    return found
