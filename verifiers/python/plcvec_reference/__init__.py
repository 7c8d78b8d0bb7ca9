"""plcvec_reference: an independent reference implementation ("second oracle").

Written from the vendor manual pages (/work/shared/manual/*.txt) and the list of
interpretations in spec/*.yaml, without the project's generator.  One module per
instruction family:

    fx5_compare  FX5 LDTM□/ANDTM□/ORTM□ and LDDT□/ANDDT□/ORDT□
    fx5_tadd     FX5 TADD/TADDP
    fc6a_hour    FC6A HOUR
    cp1e_dt      CP1E LD/AND/OR =DT ... >=DT
    machine      device memory and the vector runner

`run_vector(vector, choices)` runs one golden vector and returns
(step_expects, final_devices) in the vector's own shape.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from plcvec_verify._renamed import old_names

from . import cp1e_dt, fc6a_hour, fx5_compare, fx5_tadd
from .cp1e_dt import Cp1eTimeCompare
from .fc6a_hour import Fc6aHourMeter
from .fx5_compare import Fx5Compare
from .fx5_tadd import Fx5TimeAdd
from .machine import DeviceMemory, run_steps

DEFAULTS = {
    "fx5-time-compare": fx5_compare.DEFAULTS,
    "fx5-date-compare": fx5_compare.DEFAULTS,
    "fx5-time-add": fx5_tadd.DEFAULTS,
    "fc6a-hour-meter": fc6a_hour.DEFAULTS,
    "cp1e-time-compare": cp1e_dt.DEFAULTS,
}


ALTERNATIVES = {
    "fx5-time-compare": fx5_compare.ALTERNATIVES,
    "fx5-date-compare": fx5_compare.ALTERNATIVES,
    "fx5-time-add": fx5_tadd.ALTERNATIVES,
    "fc6a-hour-meter": fc6a_hour.ALTERNATIVES,
    "cp1e-time-compare": cp1e_dt.ALTERNATIVES,
}


# family -> (machine class, the constructor's arguments between device_sizes and choices)
MACHINES = {
    "fx5-time-compare": (Fx5Compare, ("TM",)),
    "fx5-date-compare": (Fx5Compare, ("DT",)),
    "fx5-time-add": (Fx5TimeAdd, ()),
    "fc6a-hour-meter": (Fc6aHourMeter, ()),
    "cp1e-time-compare": (Cp1eTimeCompare, ()),
}


def make_machine(family: str, devices: dict, device_sizes: dict, choices: dict | None = None, cls=None):
    """The machine an emulator would build for one instruction family.

    `cls`, a subclass of the family's machine class, is built instead (the mutants do this).
    """
    if family not in MACHINES:
        raise ValueError(f"unknown family {family}")
    base, args = MACHINES[family]
    return (cls or base)(devices, device_sizes, *args, choices)


def run_vector(vector: dict, choices: dict | None = None):
    """Run one vector; `choices` maps interpretation id -> alternative id.

    Returns (step_expects, final_devices): step_expects[i] is shaped like
    vector["steps"][i]["expect"], final_devices like vector["final"]["devices"].
    """
    family = vector["family"]
    for interpretation, alternative in (choices or {}).items():
        if interpretation not in ALTERNATIVES[family]:
            raise ValueError(f"{family} has no interpretation {interpretation}")
        if alternative not in ALTERNATIVES[family][interpretation]:
            raise ValueError(f"{interpretation} has no alternative {alternative}")
    machine = make_machine(family, vector["initial"]["devices"],
                           vector.get("assumes", {}).get("device_sizes", {}), choices)
    scratch = set(vector["initial"].get("scratch", ()))
    return run_steps(machine, vector, scratch)


# The machines' names until 0.3.0 (old -> new), deprecated until 0.4.0, with a DeprecationWarning; in
# __all__ still, so that `from plcvec_reference import *` gives them too.
RENAMED = {"FX5CompareMachine": "Fx5Compare", "TADDMachine": "Fx5TimeAdd", "HourMeter": "Fc6aHourMeter",
           "CP1ETimeCompare": "Cp1eTimeCompare"}
if TYPE_CHECKING:
    from .cp1e_dt import CP1ETimeCompare  # noqa: F401
    from .fc6a_hour import HourMeter  # noqa: F401
    from .fx5_compare import FX5CompareMachine  # noqa: F401
    from .fx5_tadd import TADDMachine  # noqa: F401
__getattr__ = old_names(__name__, RENAMED)

__all__ = [
    "run_vector", "make_machine", "MACHINES", "DEFAULTS", "ALTERNATIVES", "DeviceMemory",
    "Fx5Compare", "Fx5TimeAdd", "Fc6aHourMeter", "Cp1eTimeCompare", *RENAMED,
]
