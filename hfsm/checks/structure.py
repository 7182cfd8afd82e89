"""Checks of one machine's own shape: names, targets, initial state, failures, untraced vars, choices."""

from __future__ import annotations

from hfsm.checks.context import CheckContext, choice_states
from hfsm.library import MachineFile
from hfsm.model import ChoiceState, ElseBranch, IfBranch, JoinRule, ParallelState
from hfsm.names import RESERVED_MESSAGES, RESERVED_OUTCOMES, did_you_mean, did_you_mean_kinds


def check_reserved_names(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    for i, outcome in enumerate(m.outcomes):
        if outcome in RESERVED_OUTCOMES:
            ctx.error(mf, ("outcomes", i), "E202", f"outcome '{outcome}' is reserved")
        if outcome in m.states:
            message = f"'{outcome}' is both a state and an outcome"
            ctx.error(mf, ("states", outcome), "E315", message, key=True)
    for i, message_name in enumerate(m.receives):
        if message_name in RESERVED_MESSAGES:
            ctx.error(mf, ("receives", i), "E202", f"message name '{message_name}' is reserved")


def check_initial(ctx: CheckContext, mf: MachineFile) -> None:
    initial = mf.model.initial
    if initial is not None and initial not in mf.model.states:
        hint = did_you_mean(initial, mf.model.states)
        ctx.error(mf, ("initial",), "E316", f"initial state '{initial}' does not exist{hint}")


def check_failures(ctx: CheckContext, mf: MachineFile) -> None:
    outcomes = set(mf.model.all_outcomes)
    for i, name in enumerate(mf.model.failures or []):
        if name not in outcomes:
            ctx.error(
                mf,
                ("failures", i),
                "E318",
                f"failure '{name}' is not an outcome{did_you_mean(name, outcomes)}",
            )


def check_untraced(ctx: CheckContext, mf: MachineFile) -> None:
    declared = mf.model.vars
    for i, name in enumerate(mf.model.untraced):
        if name not in declared:
            message = f"untraced '{name}' is not one of the machine's vars{did_you_mean(name, declared)}"
            ctx.error(mf, ("untraced", i), "E333", message)


def _check_target(ctx: CheckContext, mf: MachineFile, path: tuple[str | int, ...], target: str) -> None:
    m = mf.model
    if target not in m.states and target not in m.all_outcomes:
        hint = did_you_mean_kinds(target, {"state": m.states, "outcome": m.all_outcomes})
        ctx.error(mf, path, "E301", f"unknown target '{target}': not a state or outcome{hint}")


def check_targets(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    for event, target in m.any.items():
        _check_target(ctx, mf, ("any", event), target)
    for i, watch in enumerate(m.watch):
        _check_target(ctx, mf, ("watch", i, "then"), watch.then)
    for name, state in m.states.items():
        if isinstance(state, ChoiceState):
            continue
        for event, target in state.on.items():
            _check_target(ctx, mf, ("states", name, "on", event), target)
        for i, watch in enumerate(state.watch):
            _check_target(ctx, mf, ("states", name, "watch", i, "then"), watch.then)
        if isinstance(state, ParallelState):
            for i, rule in enumerate(state.join):
                key = "then" if isinstance(rule, JoinRule) else "else"
                target = rule.then if isinstance(rule, JoinRule) else rule.else_
                _check_target(ctx, mf, ("states", name, "join", i, key), target)
    for name, choice in choice_states(m):
        for i, branch in enumerate(choice.choose):
            key = "then" if isinstance(branch, IfBranch) else "else"
            target = branch.then if isinstance(branch, IfBranch) else branch.else_
            _check_target(ctx, mf, ("states", name, "choose", i, key), target)


def check_choice_else(ctx: CheckContext, mf: MachineFile) -> None:
    for name, choice in choice_states(mf.model):
        last = len(choice.choose) - 1
        for i, branch in enumerate(choice.choose):
            if isinstance(branch, ElseBranch) and i != last:
                ctx.error(mf, ("states", name, "choose", i), "E311", "'else' must be the last branch")
        if not isinstance(choice.choose[last], ElseBranch):
            ctx.error(
                mf,
                ("states", name, "choose"),
                "E311",
                f"choice '{name}' must end with an 'else' branch",
                key=True,
            )


def check_any(ctx: CheckContext, mf: MachineFile) -> None:
    receives = set(mf.model.receives)
    for event in mf.model.any:
        if event != "error" and event not in receives:
            hint = did_you_mean(event, [*receives, "error"])
            message = f"'any' maps '{event}', which is not a message in 'receives' nor 'error'{hint}"
            ctx.error(mf, ("any", event), "E303", message, key=True)
