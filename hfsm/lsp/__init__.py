"""`hfsm-lsp`: a language server for machine files and behaviour-test files (docs/EDITORS.md).

One module per job: `analysis` (the open documents and what the checks found), `diagnostics`,
`locate` (what the cursor is on), `hover`, `completion`, `navigation` (definition, references,
rename, symbols), `actions` (quick fixes) and `server` (the wiring to pygls, over stdio).
"""
