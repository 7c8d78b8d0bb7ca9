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

from . import cp1e_dt, fc6a_hour, fx5_compare, fx5_tadd
from .cp1e_dt import CP1ETimeCompare
from .fc6a_hour import HourMeter
from .fx5_compare import FX5CompareMachine
from .fx5_tadd import TADDMachine
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
    "fx5-time-compare": (FX5CompareMachine, ("TM",)),
    "fx5-date-compare": (FX5CompareMachine, ("DT",)),
    "fx5-time-add": (TADDMachine, ()),
    "fc6a-hour-meter": (HourMeter, ()),
    "cp1e-time-compare": (CP1ETimeCompare, ()),
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


__all__ = [
    "run_vector", "make_machine", "MACHINES", "DEFAULTS", "ALTERNATIVES", "DeviceMemory",
    "FX5CompareMachine", "TADDMachine", "HourMeter", "CP1ETimeCompare",
]
