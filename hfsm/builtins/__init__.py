"""The built-in behaviours (docs/REFERENCE.md#built-in-behaviours): one module each, declaring its
signature, its traits and its running code; registered here, in the order `hfsm-run --list` shows."""

from hfsm.builtins import assign, barrier, log, send, wait, wait_for
from hfsm.builtins.registry import BUILTINS, REGISTRY, Builtin, register, unregister

for _builtin in (wait.WAIT, send.SEND, wait_for.WAIT_FOR, assign.SET, log.LOG, barrier.BARRIER):
    register(_builtin)

__all__ = ["BUILTINS", "REGISTRY", "Builtin", "register", "unregister"]
