"""The `hfsm.worlds` entry point for `--world sim` (the adapter lands with sim/)."""

from __future__ import annotations

import argparse

from hfsm.errors import UsageError
from hfsm.world import World


class SimWorldFactory:
    name = "sim"

    def add_arguments(self, group: argparse._ArgumentGroup) -> None:
        pass

    def create(self, args: argparse.Namespace, seed: int) -> World:
        raise UsageError("--world sim is not available yet")
