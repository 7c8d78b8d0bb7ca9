"""`plcvec review`: the whole spec for a reviewer, rule beside manual quote, as HTML and Markdown.

model.py gathers the data (layouts, rules, interpretations, errata, coverage, audit findings),
quotes.py checks every provenance quote against the manual text, coverage.py matches clauses to
the vectors that exercise them, render.py fills the templates, command.py is the CLI.
"""
