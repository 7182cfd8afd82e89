"""The room-clearing campaign (issue 10): generated rooms, one trial each, the report in docs/ROOM.md."""
