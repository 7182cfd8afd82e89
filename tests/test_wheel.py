"""A wheel of the project, and of the plug-in template, installed in a fresh venv: the paper's task
and the template's machine run by name from a folder that is no checkout (issue 12.3).

The fresh venv takes the other dependencies (pybullet, pydantic, ...) from this one through a
`.pth` line, so nothing is downloaded; its own site-packages come first, so `hfsm`, `hfsm_behaviours`
and `hfsm_sim` are the wheel's, not this checkout's.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SKIPPED = shutil.ignore_patterns(
    ".git", ".venv", ".venv-latest", "build", "*.egg-info", "__pycache__", ".*_cache", ".hypothesis", "out", "tests",
    "tools"
)


def left_out(folder: str, names: list[str]) -> set[str]:
    """What the copy leaves out: of docs/, all but the schemas (hfsm/schemas links to them)."""
    skipped = set(SKIPPED(folder, names))
    if Path(folder).name == "docs" and Path(folder).parent == ROOT:
        skipped |= {n for n in names if not n.endswith(".schema.json")}
    return skipped


def sh(*argv: str | Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in argv], cwd=cwd, capture_output=True, text=True, timeout=300, check=False)


@pytest.mark.slow
def test_wheels_run_the_task_and_the_template_from_any_folder(tmp_path: Path) -> None:
    source = tmp_path / "src"
    shutil.copytree(ROOT, source, symlinks=True, ignore=left_out)
    dist = tmp_path / "dist"
    built = sh(sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "-w", dist,
               source, source / "examples" / "plugin_template", cwd=tmp_path)
    assert built.returncode == 0, built.stderr
    (ours,) = dist.glob("hfsm-*.whl")
    with zipfile.ZipFile(ours) as wheel:
        top = {name.split("/")[0] for name in wheel.namelist() if ".dist-info/" not in name}
        assert top == {"hfsm", "hfsm_sim", "hfsm_behaviours"}
        top_level = [n for n in wheel.namelist() if n.endswith(".dist-info/top_level.txt")]
        assert all(set(wheel.read(n).decode().split()) <= top for n in top_level)
    venv = tmp_path / "venv"
    assert sh(sys.executable, "-m", "venv", "--without-pip", venv, cwd=tmp_path).returncode == 0
    site = next((venv / "lib").glob("python3*/site-packages"))
    (site / "deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    python = venv / "bin" / "python"
    installed = sh(sys.executable, "-m", "pip", "--python", python, "install", "-q", "--no-deps", "--no-index",
                   *sorted(dist.glob("*.whl")), cwd=tmp_path)
    assert installed.returncode == 0, installed.stderr
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    where = sh(python, "-c", "import hfsm.cli.run, hfsm_behaviours.registry as b; print(hfsm.cli.run.__file__, b.machines())",
               cwd=elsewhere)
    assert where.stdout.count(str(site)) == 2, where.stdout

    hfsm_run = venv / "bin" / "hfsm-run"
    checked = sh(hfsm_run, "move_furniture", "--check", cwd=elsewhere)
    assert checked.returncode == 0 and "move_furniture.yaml: ok (" in checked.stderr, checked.stderr
    ran = sh(hfsm_run, "move_furniture", "--max-time", "2", "--no-video", "--json", "--out", "o", cwd=elsewhere)
    result = json.loads(ran.stdout)
    assert ran.returncode == 1 and result["score"]["robot_collisions"] == 0, ran.stderr
    assert (elsewhere / "o" / "opposite_long_side-seed0.jsonl").is_file()

    launched = sh(hfsm_run, "launch", "--param", "start=2", "--json", "--quiet", cwd=elsewhere)
    assert json.loads(launched.stdout) == {"outcome": "done", "outputs": {"counted": 2}, "time": 1.0}, launched.stderr
    listed = sh(hfsm_run, "--list", cwd=elsewhere).stdout
    assert "### `count_down`" in listed and "### `launch`" in listed and "### `move_furniture`" in listed

    drawn = sh(venv / "bin" / "hfsm-graph", "leader", "-o", "figures", "--format", "svg", cwd=elsewhere)
    assert drawn.returncode == 0 and (elsewhere / "figures" / "leader.svg").is_file(), drawn.stderr
    misspelt = sh(venv / "bin" / "hfsm-graph", "leadr", cwd=elsewhere)
    assert misspelt.returncode == 2 and "did you mean 'leader'?" in misspelt.stderr
    misspelt = sh(hfsm_run, "move_furnture", cwd=elsewhere)
    assert misspelt.returncode == 2 and "did you mean 'move_furniture'?" in misspelt.stderr
    listed = sh(hfsm_run, "--list", "tararc_t", cwd=elsewhere).stdout
    assert "### `tararc_task`" in listed and "### `move_furniture`" not in listed and "regenerate" not in listed

    made = sh(hfsm_run, "--new-plugin", "mine", cwd=elsewhere)
    assert made.returncode == 0, made.stderr
    template = ROOT / "examples" / "plugin_template"
    assert (elsewhere / "mine" / "hfsm_plugin_template" / "primitives.py").read_text() == (
        template / "hfsm_plugin_template" / "primitives.py").read_text()
    checked = sh(hfsm_run, "mine/hfsm_plugin_template/machines/launch.yaml", "--check", cwd=elsewhere)
    assert checked.returncode == 0, checked.stderr

    schema = sh(hfsm_run, "--schema", cwd=elsewhere)
    assert schema.stdout == (ROOT / "docs" / "machine.schema.json").read_text()
    installed = site / "hfsm" / "schemas" / "machine.schema.json"
    assert f"$schema={installed}" in schema.stderr and installed.read_text() == schema.stdout
    assert (site / "hfsm" / "schemas" / "test.schema.json").is_file()
    for done in (ran, drawn, made, schema):
        assert "pybullet" not in done.stdout + done.stderr
