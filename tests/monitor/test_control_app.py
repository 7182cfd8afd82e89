"""The control endpoint without a browser: the token, the Origin, bad requests, a recorded run's page
(no controls), and static files that cannot leave their folder."""

from __future__ import annotations

import json
import urllib.error
import urllib.request
from collections.abc import Iterator
from dataclasses import dataclass
from json import dumps
from typing import Any

import pytest

from hfsm.monitor.control import Control
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server


@dataclass
class Answer:
    status_code: int
    text: str

    def json(self) -> Any:
        return json.loads(self.text)


class Client:
    """A few HTTP requests to a monitor served on 127.0.0.1 (no third-party HTTP client)."""

    def __init__(self, base: str) -> None:
        self.base = base

    def _send(self, request: urllib.request.Request) -> Answer:
        try:
            with urllib.request.urlopen(request, timeout=10) as answer:
                return Answer(answer.status, answer.read().decode())
        except urllib.error.HTTPError as error:
            return Answer(error.code, error.read().decode())

    def get(self, path: str) -> Answer:
        return self._send(urllib.request.Request(self.base + path))

    def post(self, path: str, json: Any, headers: dict[str, str] | None = None) -> Answer:
        data = dumps(json).encode()
        return self._send(
            urllib.request.Request(self.base + path, data=data, headers=headers or {}, method="POST")
        )


SERVED: list[Server] = []
ORIGIN = ""


@pytest.fixture(autouse=True)
def _stop_servers() -> Iterator[None]:
    yield
    while SERVED:
        SERVED.pop().stop()


def client(control: Control | None) -> Client:
    global ORIGIN
    server = Server(Hub(live=control is not None), {}, "t", 0, control=control)
    server.start()
    SERVED.append(server)
    ORIGIN = f"http://127.0.0.1:{server.port}"
    return Client(ORIGIN)


def control() -> Control:
    return Control(["robot"], [])


def test_a_decision_with_the_token_and_origin_is_queued() -> None:
    c = control()
    http = client(c)
    answer = http.post("/api/control", json={"do": "force", "agent": "robot", "event": "done"},
                            headers={"X-HFSM-Token": c.token, "Origin": ORIGIN})  # fmt: skip
    assert answer.status_code == 200
    queued = c.queue.get_nowait()
    assert (queued.do, queued.agent, queued.event) == ("force", "robot", "done")


def test_refusals_change_nothing() -> None:
    c = control()
    http = client(c)
    cases = [
        ({"X-HFSM-Token": "nope", "Origin": ORIGIN}, {"do": "pause"}, 403),
        ({"X-HFSM-Token": c.token}, {"do": "pause"}, 403),
        ({"X-HFSM-Token": c.token, "Origin": "http://127.0.0.1:8001"}, {"do": "pause"}, 403),
        ({"X-HFSM-Token": c.token, "Origin": ORIGIN}, {"do": "force", "agent": "robot"}, 400),
        ({"X-HFSM-Token": c.token, "Origin": ORIGIN}, {"do": "accept", "agent": "<script>"}, 400),
        ({"X-HFSM-Token": c.token, "Origin": ORIGIN}, {"do": "break", "spec": "nope"}, 400),
    ]
    for headers, body, status in cases:
        assert http.post("/api/control", json=body, headers=headers).status_code == status, body
    assert c.queue.empty() and c.breaks == []


def test_a_recorded_run_has_no_controls() -> None:
    http = client(None)
    assert http.get("/api/meta").json()["control"] is None
    assert http.post("/api/control", json={"do": "pause"}).status_code == 404


def test_breakpoints_are_added_and_cleared() -> None:
    c = control()
    http = client(c)
    headers = {"X-HFSM-Token": c.token, "Origin": ORIGIN}
    assert http.post("/api/control", json={"do": "break", "spec": "enter:*/lift@r1"}, headers=headers).json()[
        "breaks"
    ] == ["enter:*/lift@r1"]
    assert (
        http.post("/api/control", json={"do": "break", "spec": "clear"}, headers=headers).json()["breaks"]
        == []
    )


def test_static_files_cannot_leave_their_folder() -> None:
    http = client(None)
    for path in (
        "/static/../app.py",
        "/static/%2e%2e/app.py",
        "/static/..%2fapp.py",
        "/static/%2e%2e%2fcontrol.py",
    ):
        answer = http.get(path)
        assert answer.status_code == 404 or "create_app" not in answer.text, path
