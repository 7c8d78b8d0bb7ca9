"""Case families: what each vector tests, derived from the spec; expectations come from the engine."""
from plcvec.cases.clock_add_cases import clock_add_cases
from plcvec.cases.hour_meter_cases import hour_meter_cases
from plcvec.cases.masked_compare_cases import masked_compare_cases

CASE_FAMILIES = {
    "masked_compare": masked_compare_cases,
    "clock_add": clock_add_cases,
    "hour_meter": hour_meter_cases,
}
