"""The derivations a coverage model's dimensions may name, per rule kind: each computes the classes of
a dimension from the spec's own facts, and its classifier puts each execution in one of them."""
from plcvec.coverage import add_cells, compare_cells, hour_cells

_BY_KIND = {"masked_compare": compare_cells, "clock_add": add_cells, "hour_meter": hour_cells}
DERIVATIONS = {kind: m.DERIVE for kind, m in _BY_KIND.items()}
NEEDS = {kind: m.NEEDS for kind, m in _BY_KIND.items()}
CLASSIFIERS = {"masked_compare": compare_cells.CompareClassifier, "clock_add": add_cells.AddClassifier,
               "hour_meter": hour_cells.HourClassifier}
