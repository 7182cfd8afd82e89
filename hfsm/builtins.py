"""The built-in behaviours' signatures (docs/REFERENCE.md#built-in-behaviours). Their running code is in
runtime/builtins.py."""

from __future__ import annotations

from hfsm.spec import BehaviourSpec, ParamSpec

BUILTINS: dict[str, BehaviourSpec] = {
    spec.name: spec
    for spec in (
        BehaviourSpec(
            "wait",
            "builtin",
            {"seconds": ParamSpec("seconds", "float", required=False, doc="omit: until an event")},
            ("done",),
            doc="Wait for a span of seconds, or until an event or a timer.",
        ),
        BehaviourSpec(
            "send",
            "builtin",
            {
                "message": ParamSpec("message", "str"),
                "to": ParamSpec("to", "str", required=False, default="others"),
                "data": ParamSpec("data", "dict", required=False, default={}),
            },
            ("sent",),
            doc="Send a message to the others, all, or one agent.",
        ),
        BehaviourSpec(
            "wait_for",
            "builtin",
            {"message": ParamSpec("message", "str")},
            ("received",),
            outputs=None,
            doc="Wait until a message arrives; its data fields and `sender` are the outputs.",
        ),
        BehaviourSpec("set", "builtin", {}, ("done",), open_params=True, doc="Assign variables."),
        BehaviourSpec("log", "builtin", {"text": ParamSpec("text", "str")}, ("done",), doc="Log a line."),
        BehaviourSpec(
            "barrier",
            "builtin",
            {
                "name": ParamSpec("name", "str", doc="the barrier; agents meet at the same name"),
                "agents": ParamSpec(
                    "agents", "list", required=False, default=[], doc="agent ids; empty: every other agent"
                ),
                "at_least": ParamSpec(
                    "at_least", "int", required=False, default=0, doc="how many must arrive; 0: all"
                ),
            },
            ("passed",),
            outputs=frozenset({"arrived"}),
            doc="Wait until the named agents reach the barrier of the same name "
            "(docs/REFERENCE.md#barriers).",
        ),
    )
}
