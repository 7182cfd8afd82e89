"""TARARC (Han et al.): task allocation by collaboration history, as pure deterministic Python.

`formulas` (eqs. 1-5), `grouping` (steps 2-4), `allocation` (step 5), `help` (step 7a/7b),
`history` and `history_file` (the collaboration history and its file). No simulator, no engine:
primitives wrap these so that every robot computes the same answer from the same broadcasts.
"""
