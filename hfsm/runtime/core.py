"""What ends a whole run at once, and the bound on state entries in one tick that does."""

from __future__ import annotations

MAX_ENTRIES = 1000


class FatalError(Exception):
    """Ends the whole run at once (exit 1): an error at the top, too many entries in one tick."""

    def __init__(
        self,
        agent: str,
        message: str,
        traceback: str = "",
        origin: str = "",
        where: tuple[str | int, ...] = (),
    ) -> None:
        super().__init__(message)
        self.agent = agent
        self.traceback = traceback
        self.origin = origin  # the path of the state (or region) where it happened, when known
        self.where = where  # the path of the expression that failed, in that state's machine file
