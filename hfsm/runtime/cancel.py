"""Cancelling what runs below a state: every frame and region, innermost first, each cleaning up."""

from __future__ import annotations

from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.ledger import Ledger


class Cancelling:
    def __init__(self, ledger: Ledger) -> None:
        self.ledger = ledger

    def cancel_below(self, frame: Frame, reason: str) -> str:
        """Cancel whatever runs below `frame`'s state; a problem as text (a swallowed cancel), or ''."""
        below = frame.below
        frame.below = None
        frame.retry_at = None
        if below is None:
            return ""
        cls = below.__class__
        if cls is Frame:
            problem = self.cancel_below(below, reason)
            self.ledger.leave(below, reason)
            return problem
        if cls is list:
            problem = ""
            for region in reversed(below):  # last started, first ended, as SCXML exits a parallel
                if region.result is None:
                    problem = self.cancel_region(region, reason) or problem
            return problem
        text: str = below.cancel()
        return text

    def cancel_region(self, region: Region, reason: str) -> str:
        below = region.below
        region.below = None
        problem = ""
        if below.__class__ is Frame:
            problem = self.cancel_below(below, reason)
            self.ledger.leave(below, reason)
        elif below is not None:
            problem = below.cancel()
        self.ledger.region_left(region, reason)
        return problem

    def cancelled(self, frame: Frame, reason: str, event: Event) -> Event:
        """Cancel below `frame` for `event`; a cancel that was swallowed makes it the event `error`."""
        problem = self.cancel_below(frame, reason)
        return Event("error", error=problem) if problem else event

    def stop(self, agent: Agent, reason: str = "stopped") -> None:
        """End an agent that has not ended: cancel what runs, close its trace."""
        if not agent.started or agent.root is None:
            return
        root = agent.root
        self.cancel_below(root, reason)
        self.ledger.leave(root, reason)
        agent.root = None
        self.ledger.emit(agent, [agent.top], "exit", outcome=None)
