"""Cancelling what runs below a state: every frame and region, innermost first, each cleaning up."""

from __future__ import annotations

from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.core import Core


class Cancelling(Core):
    def _cancel_below(self, frame: Frame, reason: str) -> str:
        """Cancel whatever runs below `frame`'s state; a problem as text (a swallowed cancel), or ''."""
        below = frame.below
        frame.below = None
        frame.retry_at = None
        if below is None:
            return ""
        cls = below.__class__
        if cls is Frame:
            problem = self._cancel_below(below, reason)
            self._leave(below, reason)
            return problem
        if cls is list:
            problem = ""
            for region in reversed(below):  # last started, first ended, as SCXML exits a parallel
                if region.result is None:
                    problem = self._cancel_region(region, reason) or problem
            return problem
        text: str = below.cancel()
        return text

    def _cancel_region(self, region: Region, reason: str) -> str:
        below = region.below
        region.below = None
        problem = ""
        if below.__class__ is Frame:
            problem = self._cancel_below(below, reason)
            self._leave(below, reason)
        elif below is not None:
            problem = below.cancel()
        self._region_left(region, reason)
        return problem

    def _cancelled(self, frame: Frame, reason: str, event: Event) -> Event:
        """Cancel below `frame` for `event`; a cancel that was swallowed makes it the event `error`."""
        problem = self._cancel_below(frame, reason)
        return Event("error", error=problem) if problem else event

    def stop(self, agent: Agent, reason: str = "stopped") -> None:
        """End an agent that has not ended: cancel what runs, close its trace."""
        if not agent.started or agent.root is None:
            return
        root = agent.root
        self._cancel_below(root, reason)
        self._leave(root, reason)
        agent.root = None
        self.emit(agent, [agent.top], "exit", outcome=None)
