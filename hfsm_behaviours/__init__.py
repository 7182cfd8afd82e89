"""Primitive actions: the only code that joins the engine (hfsm) to the world (sim)."""
