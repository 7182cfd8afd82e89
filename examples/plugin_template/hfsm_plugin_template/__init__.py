"""A template for hfsm plug-ins: one primitive (`count_down`) and one machine (`launch`)."""
