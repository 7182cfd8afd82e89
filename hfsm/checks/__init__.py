"""The checks run before anything runs (docs/CHECKS.md): each small, named, with stable codes.

Errors E1xx are the reader's, E2xx schema and names, E3xx meaning; warnings W4xx become errors
with `--strict`. docs/CHECKS.md lists every code.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from hfsm.checks.autonomy import check_autonomy
from hfsm.checks.calls import check_calls
from hfsm.checks.context import CheckContext
from hfsm.checks.expressions import check_expressions, check_param_defaults
from hfsm.checks.forgotten import check_forgotten_wraps
from hfsm.checks.graphs import check_recursion, check_state_graph
from hfsm.checks.parallel import check_parallel
from hfsm.checks.scopes import check_scopes
from hfsm.checks.structure import (
    check_any,
    check_choice_else,
    check_failures,
    check_initial,
    check_reserved_names,
    check_targets,
    check_untraced,
)
from hfsm.checks.waits import check_regions
from hfsm.errors import Finding, Severity, UserError
from hfsm.library import MachineFile
from hfsm.registry import Registry
from hfsm.world import InputSpec

MachineCheck = Callable[[CheckContext, MachineFile], None]

MACHINE_CHECKS: tuple[MachineCheck, ...] = (
    check_reserved_names,
    check_initial,
    check_failures,
    check_untraced,
    check_targets,
    check_choice_else,
    check_any,
    check_param_defaults,
    check_calls,
    check_parallel,
    check_expressions,
    check_state_graph,
    check_regions,
    check_forgotten_wraps,
    check_autonomy,
    check_scopes,
)


def run_checks(
    machines: dict[str, MachineFile], registry: Registry, inputs: Mapping[str, InputSpec] | None = None
) -> list[Finding]:
    """Every check over the loaded machines; `inputs`: what the run's world declares (None: unknown)."""
    ctx = CheckContext(machines, registry, inputs)
    for mf in machines.values():
        for check in MACHINE_CHECKS:
            check(ctx, mf)
    check_recursion(ctx)
    return sorted(set(ctx.findings))


def enforce(findings: list[Finding], *, strict: bool) -> list[Finding]:
    """Raise UserError when any finding is an error (warnings too, when strict); return the warnings."""
    if strict:
        findings = [f.as_error() for f in findings]
    errors = [f for f in findings if f.severity is Severity.ERROR]
    if errors:
        raise UserError(findings)
    return findings
