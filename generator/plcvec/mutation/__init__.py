"""The decision inventory proven complete by mutation (`plcvec mutation`).

cosmic-ray's operators make every one-place change of the engine (generator/plcvec/engine) that they
can (mutants.py). Each mutant is judged by the vectors it changes (oracle.py): the families its file
reaches are built with the mutant in place, in a process of its own, and compared with the committed
vectors. A mutant that changes them must touch a decision of review/decisions.yaml (touch.py says what
"touch" means: a line shared with a decision's `old` text); one that touches none is a missing
decision. run.py runs them, at most --jobs at a time and each within a timeout; report.py counts.
"""
