"""hfsm-graph: machines drawn as diagrams (model, extraction, trace overlay, DOT, rendering)."""
