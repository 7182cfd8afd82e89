"""`hfsm-run --new-plugin DIR`: a plug-in package to start from (one primitive, one machine, its
entry points), copied from the template installed with hfsm; and where the installed schemas are."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from hfsm.errors import UsageError

SKIP = shutil.ignore_patterns("__pycache__", "*.pyc", "build", "*.egg-info")
PACKAGE = Path(__file__).resolve().parents[1]  # the installed hfsm folder: a wheel installs files on disk


def new_plugin(folder: Path) -> int:
    if folder.exists() and (not folder.is_dir() or any(folder.iterdir())):
        raise UsageError(f"--new-plugin {folder}: already there and not an empty folder; name a new one")
    template = PACKAGE / "plugin_template"
    if not (template / "pyproject.toml").is_file():
        raise UsageError("--new-plugin: the plug-in template is not installed with this hfsm")
    try:
        shutil.copytree(template, folder, ignore=SKIP, dirs_exist_ok=True)
    except OSError as exc:
        raise UsageError(f"--new-plugin {folder}: cannot write: {exc.strerror or exc}") from None
    print(f"hfsm-run: wrote a plug-in package in {folder}: read {folder / 'README.md'}, then\n"
          f"  pip install -e {folder}\n  hfsm-run launch --param start=2", file=sys.stderr)
    return 0


def schema_path(name: str = "machine") -> Path | None:
    """The installed JSON Schema file (`machine` or `test`), when it is a file on disk."""
    path = PACKAGE / "schemas" / f"{name}.schema.json"
    return path if path.is_file() else None


def schema_hint(name: str = "machine") -> str:
    path = schema_path(name)
    if path is None:
        return ""
    return (f"hfsm-run: this schema is installed at {path}; to have an editor check {name} files as\n"
            "  you type (yaml-language-server: VS Code's YAML extension, Neovim, Helix, Emacs), make\n"
            f"  their first line  # yaml-language-server: $schema={path}\n"
            f"  or save it beside them (--schema > {name}.schema.json) and give its relative path")
