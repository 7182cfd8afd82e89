"""Parallel states (docs/REFERENCE.md#parallel-states): regions started in order, stepped in order, joined by
the first rule."""

from __future__ import annotations

from hfsm.runtime.agent import Event, Frame, Region
from hfsm.runtime.arcs import Arcs


class Parallel(Arcs):
    def _start_regions(self, frame: Frame) -> Event | None:
        """Start every region in order, each taking its turn of this tick; then try the join once."""
        regions: list[Region] = []
        frame.below = regions
        agent = frame.agent
        for spec in frame.state.regions:
            region = Region(spec, frame)
            regions.append(region)
            if self.trace is not None:
                self.emit(agent, region.path(), "enter", do=spec.do)
            event = self._start_call(frame, spec, region)
            if event is not None:
                self._region_ended(region, event)
                if event.name == "error":
                    return self._region_failed(frame, event)
        return self._join(frame, regions)

    def _step_regions(self, frame: Frame, regions: list[Region]) -> None:
        """Each region's turn of this tick, in order, as if it ran alone at this depth; then the join."""
        k = self.tick
        ended = False
        for region in regions:
            if region.result is not None:
                continue
            below = region.below
            if below.__class__ is Frame:
                self.step(below)
            elif below is not None and (below.deadline is None or below.deadline <= k):
                event = below.advance(k)
                if event is not None:
                    self._region_ended(region, event)
            if region.result is not None:
                ended = True
                if region.result.name == "error" and frame.held is None:
                    self._settle(frame, self._region_failed(frame, region.result))
                    return
        if ended and frame.held is None:
            event = self._join(frame, regions)
            if event is not None:
                self._settle(frame, event)

    def _region_ended(self, region: Region, event: Event) -> None:
        region.below = None
        region.result = event
        if region.owner.state.watches:
            self.wake = True  # a watch may read what the region saved or set
        if event.name == "error":
            if not event.origin:
                event.origin = "/".join(region.path())
                self.emit(region.owner.agent, region.path(), "error", message=event.error)
        elif region.spec.save and event.outputs:
            self._save(region.owner, region.spec.save, event.outputs)
        self._region_left(region, event.name)

    def _region_failed(self, frame: Frame, event: Event) -> Event:
        """An error in a region cancels the others and is the parallel state's `error`."""
        self._cancel_below(frame, "error")
        return event

    def _join(self, frame: Frame, regions: list[Region]) -> Event | None:
        """The first rule that holds, as the event that takes its arc; the regions still running cancelled."""
        state = frame.state
        for rule in state.join:
            if rule.is_else:
                holds = all(regions[i].result is not None for i in state.awaited)
            else:
                holds = True
                for i, outcomes in rule.when:
                    result = regions[i].result
                    if result is None or result.name not in outcomes:
                        holds = False
                        break
            if holds:
                return self._cancelled(frame, "join", Event(rule.text, goto=rule.target))
        return None

    def step(self, frame: Frame) -> None:
        raise NotImplementedError
