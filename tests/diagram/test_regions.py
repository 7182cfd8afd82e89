"""Language v2 drawn: parallel states, join rules, watches, retries, barriers, and a run through regions."""

from __future__ import annotations

from typing import Any

from helpers import execute

from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import BORDER, WATCH_NODE, Sources, machine_figure
from hfsm.diagram.model import Cluster, Edge, Figure, Node, walk
from hfsm.diagram.overlay import apply, collect
from hfsm.graph import WATCH, arcs, call_graph, state_graph
from hfsm.model import Machine
from hfsm.spec import BehaviourSpec

from .helpers_diagram import DATA, data_sources


def _item(fig: Figure, item_id: str) -> Node | Cluster:
    return next(i for i in walk(fig.items) if i.id == item_id)


def _edges(fig: Figure, source: str) -> dict[tuple[str, ...], Edge]:
    return {e.labels: e for e in fig.edges if e.source == source}


def test_arcs_of_a_parallel_state_its_watches_and_its_retry() -> None:
    src = data_sources()
    m = src.machines["search"]
    kinds = {(a.source, a.event, a.kind, a.target) for a in arcs(m, src.specs)}
    assert (WATCH, "machine.time > params.limit * 2", "watch", "failure") in kinds
    assert ("search", "move=at_wall", "join", "lift") in kinds
    assert ("search", "move=failure, listen=received", "join", "failure") in kinds
    assert ("search", "else", "else", "failure") in kinds
    assert ("search", "stop", "message", "failure") in kinds
    assert ("lift", "failure", "retry", "lift") in kinds
    g = state_graph(m, arcs(m, src.specs))
    assert not g.has_edge(("state", "lift"), ("state", "lift"))  # a retry stays in its state
    assert g.has_edge(("state", "lift"), ("outcome", "failure"))  # the machine's watch, from each state
    assert call_graph(src.machines).edges["search", "move_table"]["states"] == ["search"]


def test_a_parallel_state_is_one_box_divided_into_its_lanes() -> None:
    fig = machine_figure("search", data_sources())
    node = _item(fig, "search")
    assert isinstance(node, Node) and node.role == "parallel"
    assert node.lines == ("timer params.limit (30 s)",)
    assert [(lane.title, lane.lines, lane.background) for lane in node.lanes] == [
        ("move", ("move_table(steps=2)",), False),
        ("listen", ('wait_for(message="go")',), False),
        ("blink", ("wait(seconds=0.5)", "background"), True),
    ]
    out = _edges(fig, "search")
    to_lift = next(e for labels, e in out.items() if "move=at_wall" in labels)
    assert to_lift.target == "lift" and to_lift.events[0] == "move=at_wall"
    assert any(label.startswith("[abs(vars.left") and label.endswith("]") for label in to_lift.labels)
    failing = next(e for labels, e in out.items() if "else" in labels)
    assert failing.labels == ("move=failure, listen=received", "else")
    dot = to_dot(fig)
    assert 'style="dashed" sides="TL"' in dot and "<i>background</i>" in dot


def test_the_machine_watches_leave_from_its_border_and_a_retry_loops() -> None:
    fig = machine_figure("search", data_sources())
    border = _item(fig, BORDER)
    assert isinstance(border, Cluster) and border.kind == "machine"
    assert {i.id for i in border.items} == {WATCH_NODE, "search", "lift"}  # outcomes outside it
    (watch,) = _edges(fig, WATCH_NODE).values()
    assert watch.labels == ("[machine.time > params.limit *\n2]",) and watch.ltail == BORDER
    (retry,) = [e for e in fig.edges if e.events == ("retry",)]
    assert (retry.source, retry.target, retry.style) == ("lift", "lift", "failure")
    assert retry.labels == ("retry \u00d7params.tries (3), 1 s\napart: failure",)


def test_depth_draws_each_region_in_a_dashed_box_side_by_side() -> None:
    fig = machine_figure("search", data_sources(), depth=1)
    par = _item(fig, "cluster_search")
    assert isinstance(par, Cluster) and par.kind == "parallel" and par.lines == ("timer params.limit (30 s)",)
    regions = [i for i in par.items if isinstance(i, Cluster)]
    assert [r.kind for r in regions] == ["region"] * 3
    assert regions[0].title == "move" and _item(fig, "search/move/lift").ref == ("search", "move", "lift")
    assert ("search/move/lift", "search/listen", "search/blink") in fig.rows
    start = next(e for e in fig.edges if e.source == "@start")
    assert start.lhead == "cluster_search"
    join = next(e for e in fig.edges if "move=at_wall" in e.events)
    assert join.ltail == "cluster_search"
    assert 'lhead="cluster_search"' in to_dot(fig) and 'style="dashed"' in to_dot(fig)


def test_a_barrier_is_a_synchronisation_bar_in_a_state_or_a_region() -> None:
    barrier = {"do": "barrier", "with": {"name": "lift"}}
    m = Machine.model_validate(
        {
            "outcomes": ["done"],
            "states": {
                "sync": {**barrier, "on": {"passed": "both"}},
                "both": {
                    "parallel": {
                        "meet": barrier,
                        "idle": {"do": "barrier", "with": {"name": "b"}, "background": True},
                    },
                    "join": [{"when": {"meet": "passed"}, "then": "done"}],
                },
            },
        }
    )
    src = Sources({"team": m}, {"barrier": BehaviourSpec("barrier", "builtin", {}, ("passed",))})
    fig = machine_figure("team", src)
    assert _item(fig, "sync").role == "barrier"  # type: ignore[union-attr]
    both = _item(fig, "both")
    assert isinstance(both, Node) and [lane.barrier for lane in both.lanes] == [True, True]
    assert to_dot(fig).count('bgcolor="black" height="5"') == 3
    deep = machine_figure("team", src, depth=1)
    assert _item(deep, "both/meet").role == "barrier"  # type: ignore[union-attr]


def _record(t: float, path: list[str], kind: str, **extra: Any) -> dict[str, Any]:
    return {"t": t, "agent": "a", "path": path, "kind": kind, **extra}


def test_a_run_through_regions_is_counted_where_it_went() -> None:
    src = data_sources()
    top = ["search", "search"]
    records = [
        _record(0, ["search"], "enter"),
        _record(0, top, "enter"),
        _record(0, [*top, "move"], "enter", do="move_table"),
        _record(0, [*top, "move", "lift"], "enter", do="lift"),
        _record(0, [*top, "move", "lift", "signal"], "enter", do="send"),
        _record(0.1, [*top, "move", "lift", "signal"], "event", event="sent", target="wait_peer"),
        _record(0, [*top, "listen"], "enter", do="wait_for"),
        _record(1, top, "event", event="move=at_wall", target="lift"),
        _record(1, top, "exit"),
        _record(1, ["search", "lift"], "enter", do="lift"),
        _record(2, ["search", "lift"], "event", event="retry", attempt=2, outcome="failure"),
        _record(3, ["search", "lift"], "event", event="lifted", target="done"),
        _record(3, ["search"], "exit", outcome="done"),
    ]
    stats = collect(records, src.machines)
    flat = apply(machine_figure("search", src), "search", stats)
    node = _item(flat, "search")
    assert isinstance(node, Node) and node.stats == ("\u00d71, 1 s",)
    assert [(lane.title, lane.emphasis) for lane in node.lanes] == [
        ("move", "normal"),
        ("listen", "normal"),
        ("blink", "faded"),
    ]
    assert next(e for e in flat.edges if "move=at_wall" in e.events).count == 1
    assert next(e for e in flat.edges if e.events == ("retry",)).count == 1
    deep = apply(machine_figure("search", src, depth=2), "search", stats)
    assert _item(deep, "search/move/lift/signal").emphasis == "normal"
    assert _item(deep, "search/move/lift/hold").emphasis == "faded"
    inner = next(e for e in deep.edges if e.source == "search/move/lift/signal")
    assert inner.count == 1
    lift = apply(machine_figure("lift", src), "lift", stats)  # the callee's figure counts it too
    assert _item(lift, "signal").stats == ("\u00d71, 0 s",)


def test_a_run_of_the_engine_through_regions_is_drawn_over_every_depth() -> None:
    src = data_sources()
    _, records = execute(DATA / "search.yaml", agents=("a", "b"))
    stats = collect(records, src.machines)
    flat = apply(machine_figure("search", src), "search", stats)
    node = _item(flat, "search")
    assert isinstance(node, Node) and node.stats[0].startswith("\u00d72, ")
    assert [lane.stats[0].split(",")[0] for lane in node.lanes] == ["\u00d72"] * 3
    assert next(e for e in flat.edges if "move=at_wall" in e.events).count == 2
    assert _item(flat, "done").stats == ("\u00d72", "end: a, b")
    deep = apply(machine_figure("search", src, depth=2), "search", stats)
    assert _item(deep, "search/move/lift/hold").stats[0].startswith("\u00d74, ")  # two agents, two lifts
    assert next(e for e in deep.edges if e.source == "search/move/check" and "else" in e.labels).count == 2


def test_each_lane_links_to_its_machines_figure() -> None:
    fig = machine_figure("search", data_sources(), links={"move_table", "search"})
    node = _item(fig, "search")
    assert isinstance(node, Node) and [lane.link for lane in node.lanes] == ["move_table", "", ""]
    assert 'sides="T" href="move_table.svg" title="move_table"' in to_dot(fig)
