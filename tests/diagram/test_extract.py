from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import strategies as st

from hfsm.builtins import BUILTINS
from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import ANY_NODE, START, TIMER, Sources, machine_figure, overview
from hfsm.diagram.model import Cluster, Edge, Figure, Node, nodes, walk
from hfsm.model import Machine
from hfsm.spec import BehaviourSpec

from .helpers_diagram import data_sources, declared


def _node(figure: Figure, node_id: str) -> Node:
    return next(n for n in nodes(figure) if n.id == node_id)


def _edges(figure: Figure, source: str) -> list[Edge]:
    return [e for e in figure.edges if e.source == source]


def test_one_node_per_state_and_outcome_with_its_role() -> None:
    fig = machine_figure("move_table", data_sources())
    roles = {n.id: n.role for n in nodes(fig)}
    assert roles["lift"] == "machine"
    assert roles["step"] == "builtin"
    assert roles["check"] == "choice"
    assert roles["at_wall"] == "success"
    assert roles["failure"] == "failure"
    assert roles["timeout"] == "failure"
    assert roles[TIMER] == "timer" and roles[START] == "start" and roles[ANY_NODE] == "any"
    assert fig.bottom == ("at_wall", "failure", "timeout")
    assert _node(fig, "lift").lines == ("lift(hold=0.5)",)


def test_arcs_are_labelled_and_styled_by_their_event() -> None:
    fig = machine_figure("move_table", data_sources())
    styles = {(e.source, e.target, e.labels): e.style for e in fig.edges}
    assert styles[("lift", "step", ("lifted",))] == "success"
    assert styles[("lift", "land", ("failure",))] == "failure"
    assert styles[(ANY_NODE, "failure", ("stop",))] == "message"
    assert styles[(ANY_NODE, "failure", ("error",))] == "failure"
    assert styles[(TIMER, "timeout", ("timeout",))] == "failure"
    assert styles[("check", "at_wall", ("1: vars.n >= params.steps",))] == "success"
    assert styles[("check", "lift", ("else",))] == "success"
    assert _edges(fig, START) == [Edge(START, "lift", (), "start")]
    assert _node(fig, TIMER).xlabel == "60 s"


def test_a_state_timer_shows_on_the_state() -> None:
    fig = machine_figure("lift", data_sources())
    assert _node(fig, "wait_peer").lines == ('wait_for(message="ready")', "timer 5 s")
    styles = {e.labels: e.style for e in _edges(fig, "wait_peer")}
    assert styles == {("received",): "success", ("timeout",): "failure", ("abort",): "message"}


def test_arcs_of_one_style_between_two_nodes_are_merged() -> None:
    src = data_sources()
    m = Machine.model_validate(
        {
            "outcomes": ["ok", "failure"],
            "states": {"s": {"do": "lift", "on": {"lifted": "ok", "failure": "ok"}}},
        }
    )
    merged = Sources({**src.machines, "m": m}, src.specs)
    fig = machine_figure("m", merged)
    assert [(e.labels, e.style) for e in _edges(fig, "s")] == [
        (("lifted",), "success"),
        (("failure",), "failure"),
    ]
    m2 = Machine.model_validate(
        {
            "outcomes": ["ok"],
            "timer": 5,
            "states": {
                "s": {
                    "do": "wait_for",
                    "with": {"message": "x"},
                    "timer": 1,
                    "on": {"received": "ok", "timeout": "ok"},
                }
            },
        }
    )
    both = machine_figure("m2", Sources({"m2": m2}, BUILTINS))
    assert [e.labels for e in _edges(both, "s")] == [("received",), ("timeout",)]


def test_primitives_and_links() -> None:
    src = data_sources()
    walk_spec = BehaviourSpec("walk", "primitive", {}, ("done",))
    m = Machine.model_validate(
        {
            "outcomes": ["ok"],
            "states": {
                "go": {"do": "walk", "on": {"done": "up"}},
                "up": {"do": "lift", "on": {"lifted": "ok", "failure": "ok"}},
            },
        }
    )
    fig = machine_figure(
        "m", Sources({**src.machines, "m": m}, {**src.specs, "walk": walk_spec}), links={"lift"}
    )
    assert _node(fig, "go").role == "primitive"
    assert _node(fig, "up").link == "lift"
    assert _node(fig, "go").link == ""


def test_depth_draws_callees_as_clusters() -> None:
    src = data_sources()
    flat = machine_figure("relay", src)
    assert not any(isinstance(i, Cluster) for i in walk(flat.items))
    one = machine_figure("relay", src, depth=1)
    clusters = [i for i in walk(one.items) if isinstance(i, Cluster)]
    assert [c.id for c in clusters] == ["cluster_move"]
    two = machine_figure("relay", src, depth=2)
    ids = {i.id for i in walk(two.items)}
    assert {"cluster_move", "cluster_move/lift", "move/lift/signal", "move/lift/lifted", "move/@timer"} <= ids
    edges = {(e.source, e.target, e.labels, e.ltail) for e in two.edges}
    assert (START, "wait_go", (), "") in edges
    assert ("wait_go", "move/lift/signal", ("done",), "") in edges  # into the callee's initial state
    assert ("move/at_wall", "done", ("at_wall",), "") in edges  # out of the callee's outcome
    assert ("move/lift/lifted", "move/step", ("lifted",), "") in edges
    assert ("move/check", "move/lift/signal", ("else",), "") in edges
    assert ("move/timeout", "report", ("timeout",), "") in edges


def test_arcs_that_are_not_callee_outcomes_leave_the_cluster_border() -> None:
    fig = machine_figure("move_table", data_sources(), depth=1)
    stop = [e for e in fig.edges if e.labels == ("stop",)]
    assert stop == [Edge(ANY_NODE, "failure", ("stop",), "message", ("*",), ("stop",))]
    lift = machine_figure("lift", data_sources(), depth=1)
    assert not any(isinstance(i, Cluster) for i in walk(lift.items))


def test_the_overview_leaves_builtins_out() -> None:
    fig = overview(data_sources(), ["relay", "move_table", "lift"], links={"lift"})
    assert [n.id for n in nodes(fig)] == ["relay", "move_table", "lift"]
    assert [(e.source, e.target, e.labels) for e in fig.edges] == [
        ("relay", "move_table", ("move",)),
        ("move_table", "lift", ("lift",)),
    ]
    assert [n.link for n in nodes(fig)] == ["", "", "lift"]


_NAMES = [f"s{i}" for i in range(8)]
_OUTCOMES = ["ok", "failure", "gave_up"]


@st.composite
def machines(draw: st.DrawFn) -> Machine:
    """Random machines of built-in calls and choices; every target a state or an outcome."""
    count = draw(st.integers(1, len(_NAMES)))
    names = _NAMES[:count]
    outcomes = _OUTCOMES[: draw(st.integers(1, len(_OUTCOMES)))]
    targets = st.sampled_from(names + outcomes)
    states: dict[str, Any] = {}
    for name in names:
        if draw(st.booleans()):
            conditions = draw(st.lists(st.just("vars.x > 0"), max_size=2))
            states[name] = {
                "choose": [*({"if": c, "then": draw(targets)} for c in conditions), {"else": draw(targets)}]
            }
        else:
            timed = draw(st.booleans())
            on = {"done": draw(targets), **({"timeout": draw(targets)} if timed else {})}
            states[name] = {"do": "wait", "on": on, **({"timer": 1.5} if timed else {})}
    spec: dict[str, Any] = {"outcomes": outcomes, "vars": {"x": 0}, "states": states}
    if draw(st.booleans()):
        spec["timer"] = 10
    if draw(st.booleans()):
        spec["any"] = {"error": draw(targets)}
    return Machine.model_validate(spec)


@given(machines())
def test_the_dot_output_covers_every_state_and_outcome_exactly_once(m: Machine) -> None:
    dot = to_dot(machine_figure("m", Sources({"m": m}, BUILTINS)))
    counts = declared(dot)
    for name in [*m.states, *m.all_outcomes]:
        assert counts[name] == 1, name
    assert all(n == 1 for n in counts.values())
    edges = dot.count(" -> ")
    assert edges >= len(m.states)  # every state has at least one arc out (or the start arc in)


def test_a_scope_shows_on_its_state(tmp_path: Any) -> None:
    from hfsm.load import load
    from hfsm.registry import Registry

    (tmp_path / "talk.yaml").write_text("outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    top = tmp_path / "team.yaml"
    top.write_text(
        "outcomes: [done]\nstates:\n"
        "  pair: {do: talk, scope: {name: \"${'pair_' + agent.id}\", agents: []}, timer: 5, "
        "on: {done: both, timeout: done}}\n"
        "  both:\n    parallel: {x: {do: talk}}\n    join: [{else: done}]\n    scope: {name: crew, agents: []}\n"
    )
    registry = Registry()
    fig = machine_figure("team", Sources.from_loaded(load([top], registry=registry), registry))
    assert _node(fig, "pair").lines == ("talk()", "scope: pair_\u2026", "timer 5 s")
    assert _node(fig, "both").lines == ("scope: crew",)
