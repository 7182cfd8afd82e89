"""hfsm-monitor: one web page for a live run and for the replay of its trace.

`hub` holds the records (a trace sink with a bounded queue, so the run is never slowed or
changed), `figures` draws each machine with hfsm-graph's renderer, `app` is the Starlette
application (the page, the records as JSON, new records as server-sent events) and `serve` runs it
with uvicorn on 127.0.0.1 in a thread beside the run.
"""
