"""Run the monitor's application with uvicorn on 127.0.0.1, in a thread beside the run."""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Mapping
from pathlib import Path

import uvicorn

from hfsm.errors import UsageError
from hfsm.monitor.app import create_app
from hfsm.monitor.control import Control
from hfsm.monitor.hub import Hub

HOST = "127.0.0.1"


class Server:
    """A uvicorn server on HOST:port (port 0: a free one) running in a daemon thread."""

    def __init__(
        self,
        hub: Hub,
        svgs: Mapping[str, str],
        title: str,
        port: int = 0,
        video: Path | None = None,
        control: Control | None = None,
    ) -> None:
        self._socket = _bind(port)
        self.port = self._socket.getsockname()[1]
        self.control = control
        if control is not None:
            control.serve_at(HOST, self.port)
        config = uvicorn.Config(
            create_app(hub, svgs, title, video, control),
            log_level="warning",
            lifespan="off",
            timeout_graceful_shutdown=1,
        )
        self._server = uvicorn.Server(config)
        self._thread = threading.Thread(
            target=self._server.run, kwargs={"sockets": [self._socket]}, name="hfsm-monitor", daemon=True
        )

    @property
    def url(self) -> str:
        """The page's address; with the run's token when it may control the run."""
        token = f"?token={self.control.token}" if self.control is not None else ""
        return f"http://{HOST}:{self.port}/{token}"

    def start(self) -> None:
        self._thread.start()
        deadline = time.monotonic() + 10
        while not self._server.started and self._thread.is_alive() and time.monotonic() < deadline:
            time.sleep(0.01)

    def stop(self) -> None:
        self._server.should_exit = True
        self._thread.join(timeout=5)
        self._socket.close()


def hold(seconds: float | None) -> None:
    """Wait `seconds` (None or inf: until interrupted) while the server's thread serves."""
    deadline = None if seconds is None else time.monotonic() + seconds
    while deadline is None or time.monotonic() < deadline:
        time.sleep(0.2)


def _bind(port: int) -> socket.socket:
    if not 0 <= port <= 65535:
        raise UsageError(f"--port takes 0..65535 (0: any free port), not {port}")
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind((HOST, port))
    except OSError as exc:
        sock.close()
        raise UsageError(f"cannot serve on {HOST}:{port}: {exc.strerror or exc}") from None
    sock.listen(64)
    return sock
