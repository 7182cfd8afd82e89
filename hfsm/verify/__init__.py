"""`hfsm-verify`: every run of a machine, or a team running it, that the world's choices allow."""
