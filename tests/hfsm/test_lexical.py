"""Names resolved where their file lies (docs/REFERENCE.md#a-machine and #hfsm-run): a user's machine shadows a library
machine or a primitive for user files only; library files never look in user folders."""

from __future__ import annotations

import json
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest

from hfsm import plugins
from hfsm.load import load
from hfsm.primitive import Context, Outcome, primitive
from hfsm.registry import GROUP, Registry
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions, run
from hfsm.world import NullWorld
from tests.helpers import hfsm_run, write

# A behaviour ported from XABSL with the stand-ins it was written against in `stubs/`: its own
# `hold` (a head motion of the soccer code), which is also the name of a primitive of our simulator.
BODY_CONTROL = """
    doc: Ported from a XABSL option; `hold` is the stub beside it, not the simulator's primitive.
    outcomes: [done]
    vars: {world: ""}
    outputs: {world: "${vars.world}"}
    states:
      stand:
        do: hold
        with: {ms: 100}
        save: {world: world}
        on: {held: kick}
      kick:
        do: kick_ball
        on: {kicked: done}
"""
HOLD = """
    outcomes: [held]
    params: {ms: {type: int}}
    outputs: {world: "stub world"}
    states:
      a: {do: wait, with: {seconds: "${params.ms / 1000}"}, on: {done: held}}
"""
KICK = """
    outcomes: [kicked]
    states:
      a: {do: log, with: {text: kick}, on: {done: kicked}}
"""


@pytest.fixture
def ported(tmp_path: Path) -> Path:
    stubs = tmp_path / "stubs"
    stubs.mkdir()
    write(stubs, "hold", HOLD)
    write(stubs, "kick_ball", KICK)
    return write(tmp_path, "body_control", BODY_CONTROL)


def test_a_users_machine_shadows_a_primitive_with_a_warning(
    ported: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(ported.parent)
    code, _, err = hfsm_run(capsys, ported.name, "--lib", "stubs", "--check")
    assert code == 0, err
    assert "W406" in err and "machine 'hold' (stubs/hold.yaml) shadows the primitive 'hold'" in err
    assert "needs param" not in err and "has no output" not in err


def test_the_shadowing_machine_runs_in_a_world_free_run(ported: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = hfsm_run(capsys, ported, "--lib", ported.parent / "stubs", "--json", "--quiet")
    assert code == 0, err
    assert json.loads(out) == {"outcome": "done", "outputs": {"world": "stub world"}, "time": 0.1}


def test_strict_makes_the_shadowing_an_error(ported: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = hfsm_run(capsys, ported, "--lib", ported.parent / "stubs", "--check", "--strict")
    assert code == 2 and "W406" in err


@primitive(outcomes=["done"], outputs=["who"])
def probe(ctx: Context) -> Outcome:
    return Outcome("done", who="primitive")


def ending(who: str) -> str:
    """A machine that ends at once with the output `who`."""
    return f'outcomes: [done]\noutputs: {{who: "{who}"}}\nstates:\n  a: {{do: log, with: {{text: x}}, on: {{done: done}}}}\n'


def team_library(root: Path) -> Path:
    """A plug-in's library: `team` calls `probe` and `helper`, both its own names."""
    lib = root / "plugin_machines"
    lib.mkdir()
    write(
        lib,
        "team",
        """
        outcomes: [done]
        vars: {a: "", b: ""}
        outputs: {probe: "${vars.a}", helper: "${vars.b}"}
        states:
          p: {do: probe, save: {a: who}, on: {done: h}}
          h: {do: helper, save: {b: who}, on: {done: done}}
        """,
    )
    write(lib, "helper", ending("library helper"))
    return lib


USER_TOP = """
    outcomes: [done]
    vars: {mine: "", helper: "", lib: {}}
    outputs: {mine: "${vars.mine}", helper: "${vars.helper}", lib: "${vars.lib}"}
    states:
      p: {do: probe, save: {mine: who}, on: {done: h}}
      h: {do: helper, save: {helper: who}, on: {done: t}}
      t: {do: team, save: {lib: probe}, on: {done: done}}
"""


def test_library_files_never_see_user_folders(tmp_path: Path) -> None:
    registry = Registry([probe])
    registry.machine_folders.append(team_library(tmp_path))
    user = tmp_path / "user"
    user.mkdir()
    write(user, "probe", ending("user probe"))
    write(user, "helper", ending("user helper"))
    top = write(user, "top", USER_TOP)
    loaded = load([top], registry=registry)
    keys = sorted(loaded.machines)
    assert keys == ["helper", "helper@plugin_machines", "probe@user", "team", "top"]
    team = loaded.machines["team"].model.states
    assert [s.do for s in team.values()] == ["probe", "helper@plugin_machines"]  # type: ignore[union-attr]
    warned = [f.message for f in loaded.warnings if f.code == "W406"]
    assert len(warned) == 2
    assert any("shadows the primitive 'probe'" in w for w in warned)
    assert any("shadows the library machine" in w and "plugin_machines/helper.yaml" in w for w in warned)
    program = Program(loaded.machines, registry, 0.05)
    result = run(program, NullWorld(), RunOptions("top", ["robot"], {}))
    outputs = result.agents["robot"].outputs
    assert outputs == {"mine": "user probe", "helper": "user helper", "lib": "primitive"}


def test_a_library_that_gains_a_machine_does_not_change_a_user_file(tmp_path: Path) -> None:
    registry = Registry()
    lib = tmp_path / "lib"
    lib.mkdir()
    registry.machine_folders.append(lib)
    user = tmp_path / "user"
    user.mkdir()
    write(user, "greet", ending("mine"))
    top = write(user, "top", 'outcomes: [done]\nvars: {w: ""}\noutputs: {w: "${vars.w}"}\nstates:\n  a: {do: greet, save: {w: who}, on: {done: done}}\n')
    before = load([top], registry=registry)
    write(lib, "greet", 'outcomes: [hi]\nstates:\n  a: {do: wait, with: {seconds: 0}, on: {done: hi}}\n')
    after = load([top], registry=registry)
    assert before.machines["top"].model == after.machines["top"].model
    assert sorted(after.machines) == ["greet", "top"]


def test_two_primitives_of_one_name_are_an_error_naming_both_plugins(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    eps = [
        EntryPoint("first", "plugin_samples:register_nod", GROUP),
        EntryPoint("second", "plugin_samples:register_nod_and_wave", GROUP),
    ]
    monkeypatch.setattr(plugins, "entry_points", lambda group: eps if group == GROUP else [])
    top = write(tmp_path, "top", "outcomes: [done]\nstates:\n  a: {do: nod, on: {done: done}}\n")
    code, _, err = hfsm_run(capsys, top, "--check")
    assert code == 2
    assert "3:10: error[E350]" in err or "E350" in err
    assert "'nod' is a primitive of two plug-ins, 'first' and 'second'" in err
