"""A run drawn over its figures: counts come from traces written by the engine itself."""

from __future__ import annotations

from typing import Any

from helpers import execute

from hfsm.diagram.extract import ANY_NODE, TIMER, machine_figure
from hfsm.diagram.model import Cluster, Edge, Figure, Node, walk
from hfsm.diagram.overlay import apply, collect

from .helpers_diagram import DATA, data_sources


def _item(fig: Figure, item_id: str) -> Node | Cluster:
    return next(i for i in walk(fig.items) if i.id == item_id)


def _edge(fig: Figure, source: str, label: str) -> Edge:
    return next(e for e in fig.edges if e.source == source and label in e.labels)


def _trace(name: str, **kwargs: Any) -> list[dict[str, Any]]:
    _, records = execute(DATA / f"{name}.yaml", **kwargs)
    return records


def test_visits_time_and_arcs_of_a_successful_run() -> None:
    src = data_sources()
    stats = collect(_trace("move_table", agents=("a", "b")), src.machines)
    fig = apply(machine_figure("move_table", src), "move_table", stats)
    assert _item(fig, "lift").stats == ("\u00d76, 3.3 s",)
    assert _item(fig, "check").stats == ("\u00d76",)
    assert _edge(fig, "check", "else").count == 4
    assert _edge(fig, "lift", "lifted").count == 6
    failure = _edge(fig, "lift", "failure")
    assert failure.count is None and failure.emphasis == "faded"
    at_wall = _item(fig, "at_wall")
    assert at_wall.emphasis == "ended" and isinstance(at_wall, Node)
    assert at_wall.stats == ("\u00d72", "end: a, b")  # a line in the node: an xlabel could overlap
    assert _item(fig, "failure").emphasis == "faded"
    assert fig.notes == ("a: ended in 'at_wall' at t = 3.15 s", "b: ended in 'at_wall' at t = 3.15 s")


def test_a_callee_figure_counts_every_call_and_inline_clusters_too() -> None:
    src = data_sources()
    stats = collect(_trace("move_table", agents=("a", "b")), src.machines)
    lift = apply(machine_figure("lift", src), "lift", stats)
    assert _item(lift, "hold").stats == ("\u00d76, 3 s",)
    assert _item(lift, "lifted").stats == ("\u00d76",)
    assert _edge(lift, "wait_peer", "received").count == 6
    inline = apply(machine_figure("move_table", src, depth=1), "move_table", stats)
    assert _item(inline, "cluster_lift").stats == ("\u00d76, 3.3 s",)
    assert _item(inline, "lift/hold").stats == ("\u00d76, 3 s",)
    assert _edge(inline, "lift/lifted", "lifted").count == 6


def test_timeouts_any_arcs_and_agents_that_did_not_end() -> None:
    src = data_sources()
    # one agent alone: nobody answers 'ready', the state timer fires, the run fails and retries
    stats = collect(_trace("move_table", agents=("solo",)), src.machines)
    fig = apply(machine_figure("move_table", src), "move_table", stats)
    assert _edge(fig, TIMER, "timeout").count == 1
    assert _item(fig, "timeout").emphasis == "ended"
    lift = apply(machine_figure("lift", src), "lift", stats)
    assert (_edge(lift, "wait_peer", "timeout").count or 0) >= 10
    stopped = collect(_trace("move_table", agents=("solo",), max_time=2), src.machines)
    fig = apply(machine_figure("move_table", src), "move_table", stopped)
    assert _item(fig, "lift").emphasis == "ended"
    assert fig.notes[0].startswith("solo: did not end; last in move_table/lift/wait_peer")
    assert _edge(fig, ANY_NODE, "stop").emphasis == "faded"


def test_any_arcs_count_the_events_no_state_maps() -> None:
    src = data_sources()
    records = [
        {"t": 0, "agent": "r", "path": ["move_table"], "kind": "enter"},
        {"t": 0, "agent": "r", "path": ["move_table", "land"], "kind": "enter", "do": "wait"},
        {
            "t": 0.2,
            "agent": "r",
            "path": ["move_table", "land"],
            "kind": "event",
            "event": "stop",
            "target": "failure",
        },
        {"t": 0.2, "agent": "r", "path": ["move_table", "land"], "kind": "exit", "event": "stop"},
        {"t": 0.2, "agent": "r", "path": ["move_table"], "kind": "exit", "outcome": "failure"},
    ]
    fig = apply(machine_figure("move_table", src), "move_table", collect(records, src.machines))
    assert _edge(fig, ANY_NODE, "stop").count == 1
    assert _item(fig, "land").stats == ("\u00d71, 0.2 s",)
    assert _item(fig, "failure").stats == ("\u00d71", "end: r")


def test_records_of_other_machines_leave_the_figure_faded() -> None:
    src = data_sources()
    stats = collect(
        [{"t": 0, "agent": "r", "path": ["elsewhere", "x"], "kind": "enter"}, {"kind": "exit"}], src.machines
    )
    fig = apply(machine_figure("lift", src), "lift", stats)
    assert all(i.emphasis == "faded" for i in walk(fig.items) if isinstance(i, Node) and i.role == "builtin")
