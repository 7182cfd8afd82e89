"""Broken plug-ins are named with their fix and left out; the rest keeps working."""

from __future__ import annotations

import logging
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest

from hfsm import plugins
from hfsm.cli.run import main
from hfsm.registry import GROUP, Registry

ROOT = Path(__file__).resolve().parents[2]


def install(monkeypatch: pytest.MonkeyPatch, **targets: str) -> None:
    eps = [EntryPoint(name, f"plugin_samples:{target}", GROUP) for name, target in targets.items()]
    monkeypatch.setattr(plugins, "entry_points", lambda group: eps if group == GROUP else [])


def warnings_of(caplog: pytest.LogCaptureFixture) -> str:
    return "\n".join(r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING)


def test_an_entry_point_naming_a_primitive_is_named_with_the_fix(
    monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    install(monkeypatch, a_good="register_wave", b_wrong="nod")
    assert Registry.discover().names() == ["wave"]
    text = warnings_of(caplog)
    assert "plug-in 'b_wrong' (plugin_samples:nod" in text
    assert "names the primitive 'nod', not a register function" in text and "register(registry)" in text


def test_two_plugins_registering_one_name_keep_the_first(
    monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    install(monkeypatch, first="register_nod", second="register_nod_and_wave", third="register_wave")
    assert Registry.discover().names() == ["nod", "wave"]
    text = warnings_of(caplog)
    assert "plug-in 'second'" in text and "registers 'nod', which plug-in 'first' registered first" in text
    assert "rename the primitive" in text and "'third'" not in text


@pytest.mark.parametrize(
    ("target", "words"),
    [
        ("NOT_CALLABLE", "not a register function"),
        ("register_broken", "failed (RuntimeError: no robot here)"),
        ("nowhere_at_all", "cannot be imported (AttributeError"),
    ],
)
def test_other_broken_plugins_are_named(
    monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture, target: str, words: str
) -> None:
    install(monkeypatch, good="register_wave", bad=target)
    assert Registry.discover().names() == ["wave"]
    assert words in warnings_of(caplog) and "plug-in 'bad'" in warnings_of(caplog)


def test_commands_that_do_not_need_a_broken_plugin_keep_working(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    install(monkeypatch, bad="nod", twice="register_nod_and_wave", again="register_nod")
    assert main([str(ROOT / "examples" / "hello.yaml"), "--check"]) == 0
    err = capsys.readouterr().err
    assert "ok (1 machines checked)" in err and "Traceback" not in err


def fake_distribution(folder: Path, entry_points: str, modules: dict[str, str]) -> None:
    """An installed distribution as importlib.metadata finds it: a *.dist-info on sys.path."""
    info = folder / "old_plugin-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: old-plugin\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(entry_points)
    for name, text in modules.items():
        (folder / f"{name}.py").write_text(text)


@pytest.mark.parametrize(("entry", "module", "says"), [
    ("behaviours.registry:register", "", "names the module 'behaviours', which hfsm renamed 'hfsm_behaviours'"),
    ("sim.world:register", "", "names the module 'sim', which hfsm renamed 'hfsm_sim'"),
    ("old_plug:register", "from behaviours.body import Body\n\ndef register(registry):\n    pass\n",
     "imports the module 'behaviours', which hfsm renamed 'hfsm_behaviours'"),
    ("old_plug:register", "import sim.robot\n\ndef register(registry):\n    pass\n",
     "imports the module 'sim', which hfsm renamed 'hfsm_sim'"),
])
def test_a_plugin_naming_the_old_packages_gets_the_new_names(
    entry: str, module: str, says: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
    caplog: pytest.LogCaptureFixture,
) -> None:
    fake_distribution(tmp_path, f"[{GROUP}]\nold = {entry}\n", {"old_plug": module} if module else {})
    monkeypatch.syspath_prepend(str(tmp_path))
    registry = Registry.discover()
    assert "wave" not in registry.names() and "scan_for_table" in registry.names()  # ours still load
    text = warnings_of(caplog)
    assert f"plug-in 'old' ({entry}, entry-point group {GROUP})" in text and says in text, text
    assert "Traceback" not in text
    assert main([str(ROOT / "examples" / "hello.yaml"), "--check"]) == 0  # the run goes on without it
