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
from starlette.responses import FileResponse, Response, StreamingResponse
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from hfsm.monitor.control import Control, control_route
from hfsm.monitor.figures import Figures
from hfsm.monitor.hub import Hub

STATIC = Path(__file__).parent / "static"
POLL = 0.1  # seconds between looks at a live hub


def create_app(
    hub: Hub,
    svgs: Mapping[str, str] | Figures,
    title: str,
    video: Path | None = None,
    control: Control | None = None,
    video_rate: float = 5.0,
) -> Starlette:
    figures = svgs if isinstance(svgs, Figures) else Figures(svgs)

    def playable() -> bool:
        return video is not None and hub.video_ready and video.is_file()

    async def page(request: Request) -> Response:
        return FileResponse(STATIC / "index.html", headers={"Cache-Control": "no-store"})

    async def meta(request: Request) -> Response:
        while not figures.ready():  # a live run's drawings are being made
            await asyncio.sleep(0.05)
        shown = {"src": "/video", "rate": video_rate} if playable() else None
        # the operator's controls only while a live run goes: a replay, or a run over, has none
        controls = control.state() if control is not None and hub.live and not hub.ended else None
        pending = video is not None and not hub.video_ready  # a live run's, written when its world closes
        shown_meta = {"title": title, "live": hub.live, "machines": figures.svgs, "video": shown}
        return _json({**shown_meta, "video_pending": pending, "control": controls})

    async def movie(request: Request) -> Response:
        if video is None or not playable():
            return Response(status_code=404)
        return FileResponse(video)

    async def records(request: Request) -> Response:
        start = _int(request.query_params.get("from"), 0)
        batch, count = hub.since_json(start)
        tail = json.dumps({"next": start + count, "ended": hub.ended, "dropped": hub.dropped})[1:]
        return Response(b'{"records": ' + batch + b", " + tail.encode(), media_type="application/json")

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


async def _events(hub: Hub, start: int, request: Request) -> AsyncIterator[bytes]:
    """Batches of new records as `data:` events, then one `end` event when the run is over."""
    sent = start
    while True:
        batch, count = hub.since_json(sent)
        if count:
            sent += count
            yield b"data: " + batch + b"\n\n"
        elif hub.ended:
            yield b"event: end\ndata: {}\n\n"
            return
        elif await request.is_disconnected():
            return
        else:
            await asyncio.sleep(POLL)


def _json(value: Any) -> Response:
    """JSON in ASCII: a lone surrogate in a trace's text (valid JSON, not valid UTF-8) goes as its
    escape, as the stream's events do, instead of failing the response."""
    return Response(json.dumps(value, default=str), media_type="application/json")


def _int(text: Any, default: int) -> int:
    try:
        return max(0, int(text))
    except (TypeError, ValueError):
        return default
