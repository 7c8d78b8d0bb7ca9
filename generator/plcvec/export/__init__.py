"""`plcvec export --lang L`: render the vectors and the spec's names into a native verifier.

Each language has one jinja2 template set under `templates/<lang>/`, with an `export.yaml` that
says where each rendered file goes (see `targets.py`). What the templates see is built once from
the vector files, the product (see `model.py`), so every language gets the same names from the
same source and nothing the spec says is retyped in five languages.
"""
