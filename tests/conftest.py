"""Fixtures shared by all tests; helpers live in tests/helpers.py."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from helpers import write
from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile(
    "stress", max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("ci")


@pytest.fixture
def machine(tmp_path: Path) -> Callable[..., Path]:
    """Write a machine file: machine('name', '''yaml''') -> its path."""
    return lambda name, text: write(tmp_path, name, text)


def pytest_configure(config: pytest.Config) -> None:
    """Collect tests/machines/*.test.yaml also where the plug-in's entry point is not installed yet."""
    from hfsm.testing import plugin

    if not config.pluginmanager.is_registered(plugin):
        config.pluginmanager.register(plugin, "hfsm.testing.plugin")
