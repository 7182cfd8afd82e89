"""Clearing a room (issue 10) as pure code: frames, claimed walls and the pairs' plan, on TARARC's plan."""
