"""The monitor's web application: the page, the run's machines as SVG, its records as JSON and as a
stream of server-sent events. Everything it serves is local: no file is fetched from the network."""

from __future__ import annotations

import asyncio
import json
from collections.abc import AsyncIterator, Mapping
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import FileResponse, JSONResponse, Response, StreamingResponse
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from hfsm.monitor.control import Control, control_route
from hfsm.monitor.hub import Hub

STATIC = Path(__file__).parent / "static"
POLL = 0.1  # seconds between looks at a live hub


def create_app(
    hub: Hub, svgs: Mapping[str, str], title: str, video: Path | None = None, control: Control | None = None
) -> Starlette:
    async def page(request: Request) -> Response:
        return FileResponse(STATIC / "index.html", headers={"Cache-Control": "no-store"})

    async def meta(request: Request) -> Response:
        shown = "/video" if video is not None and video.is_file() else None
        controls = control.state() if control is not None else None
        return JSONResponse(
            {"title": title, "live": hub.live, "machines": dict(svgs), "video": shown, "control": controls}
        )

    async def movie(request: Request) -> Response:
        if video is None or not video.is_file():
            return Response(status_code=404)
        return FileResponse(video)

    async def records(request: Request) -> Response:
        start = _int(request.query_params.get("from"), 0)
        batch = hub.since(start)
        return JSONResponse(
            {"records": batch, "next": start + len(batch), "ended": hub.ended, "dropped": hub.dropped}
        )

    async def stream(request: Request) -> Response:
        start = _int(request.query_params.get("from"), 0)
        return StreamingResponse(
            _events(hub, start, request),
            media_type="text/event-stream",
            headers={"Cache-Control": "no-store"},
        )

    routes = [
        Route("/", page),
        Route("/api/meta", meta),
        Route("/api/records", records),
        Route("/api/stream", stream),
        control_route(control),
        Route("/video", movie),
        Mount("/static", StaticFiles(directory=STATIC), name="static"),
    ]
    return Starlette(routes=routes)


async def _events(hub: Hub, start: int, request: Request) -> AsyncIterator[str]:
    """Batches of new records as `data:` events, then one `end` event when the run is over."""
    sent = start
    while True:
        batch = hub.since(sent)
        if batch:
            sent += len(batch)
            yield f"data: {json.dumps(batch, default=str)}\n\n"
        elif hub.ended:
            yield "event: end\ndata: {}\n\n"
            return
        elif await request.is_disconnected():
            return
        else:
            await asyncio.sleep(POLL)


def _int(text: Any, default: int) -> int:
    try:
        return max(0, int(text))
    except (TypeError, ValueError):
        return default
