"""The operator's controls of a live run: pause, resume, step, answer or force an arc,
change the autonomy level, send an agent a message, set a breakpoint.

Each request carries the run's token (printed in the page's address at start) and comes from the
page's own origin, so that another page open in the same browser cannot drive the robots. What it
asks is checked as an `--operator` record is, then queued: the run takes it at the start of its
next tick and writes it to the trace as an `operator` record.
"""

from __future__ import annotations

import queue
import secrets
from collections.abc import Mapping, Sequence
from typing import Any

from starlette.requests import Request
from starlette.responses import JSONResponse, Response
from starlette.routing import Route

from hfsm.autonomy import Decision, decision_of, decision_problems
from hfsm.runtime.breaks import Breakpoint, parse

KEYS = ("do", "agent", "event", "level", "message", "data")


class Control:
    def __init__(self, agents: Sequence[str], breaks: list[Breakpoint]) -> None:
        self.agents = list(agents)
        self.token = secrets.token_urlsafe(18)
        self.queue: queue.Queue[Decision] = queue.Queue()
        self.breaks = breaks  # the run's own list: a breakpoint added here acts from the next record
        self.origins: frozenset[str] = frozenset()

    def serve_at(self, host: str, port: int) -> None:
        self.origins = frozenset({f"http://{host}:{port}", f"http://localhost:{port}"})

    def refused(self, token: str | None, origin: str | None) -> str:
        """Why a request may not act ('' when it may)."""
        if not token or not secrets.compare_digest(token, self.token):
            return "a control request needs this run's token (the one in the page's address)"
        if origin not in self.origins:
            return f"a control request must come from the monitor's page, not from {origin or 'no origin'}"
        return ""

    def ask(self, body: Mapping[str, Any]) -> list[str]:
        """Queue what the page asks; the problems with it, if any (then nothing is queued)."""
        if body.get("do") == "break":
            return self._break(body.get("spec"))
        item = {k: body[k] for k in KEYS if body.get(k) is not None}
        item["t"] = 0
        problems = [f"{key}: {message}" for key, message in decision_problems(item, self.agents)]
        if not problems:
            self.queue.put(decision_of(item))
        return problems

    def _break(self, spec: Any) -> list[str]:
        if spec == "clear":
            self.breaks.clear()
            return []
        try:
            self.breaks.append(parse(str(spec)))
        except ValueError as exc:
            return [str(exc)]
        return []

    def state(self) -> dict[str, Any]:
        return {"agents": self.agents, "breaks": [b.text for b in self.breaks]}


def control_route(control: Control | None) -> Route:
    """POST /api/control: one of the operator's decisions, as JSON, from the page of a live run."""

    async def act(request: Request) -> Response:
        if control is None:
            return JSONResponse({"error": "this page shows a recorded run: nothing to control"}, 404)
        why = control.refused(request.headers.get("x-hfsm-token"), request.headers.get("origin"))
        if why:
            return JSONResponse({"error": why}, 403)
        try:
            body = await request.json()
        except ValueError:
            body = None
        if not isinstance(body, dict):
            return JSONResponse({"error": "a control request is a JSON object"}, 400)
        problems = control.ask(body)
        if problems:
            return JSONResponse({"error": "; ".join(problems)}, 400)
        return JSONResponse({"queued": True, **control.state()})

    return Route("/api/control", act, methods=["POST"])
