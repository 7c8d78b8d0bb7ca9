"""`plcvec fuzz`: live differential testing of an implementation against the spec engine.

draw.py draws cases and builds them into vectors, run.py runs them through the adapter and judges the
answers with plcvec_verify, shrink.py shrinks a disagreement, report.py prints it, command.py is the
command line.
"""
