"""Shared device memory and the vector runner.

This module knows nothing about any instruction.  It holds the device image
(word devices as unsigned 16-bit integers, bit devices as booleans), knows the
size of each device (from the vector's `assumes.device_sizes`), and runs the
steps of a vector through a family machine's `execute`.
"""
from __future__ import annotations

import copy
import re
from functools import lru_cache

_ADDR = re.compile(r"^([A-Z]+)(\d+)$")


@lru_cache(maxsize=None)  # a program names few devices; parse each name once
def split_address(address: str):
    """'D100' -> ('D', 100).  Names without a number (P_EQ) -> (name, None)."""
    m = _ADDR.match(address)
    if not m:
        return address, None
    return m.group(1), int(m.group(2))


@lru_cache(maxsize=None)
def offset_address(base: str, offset: int) -> str:
    """'D100', 2 -> 'D102'."""
    kind, number = split_address(base)
    if number is None:
        raise ValueError(f"{base} is not a numbered device")
    return f"{kind}{number + offset}"


def to_signed16(word: int) -> int:
    """A word read as "16-bit signed binary"."""
    word &= 0xFFFF
    return word - 0x10000 if word & 0x8000 else word


def to_word(value: int) -> int:
    """A Python integer stored into a 16-bit word."""
    return value & 0xFFFF


class DeviceMemory:
    """A dict of device address -> value, plus the number of points of each device."""

    def __init__(self, devices: dict, device_sizes: dict | None = None):
        self.values = dict(devices)
        self.sizes = dict(device_sizes or {})

    def address(self, base: str, offset: int) -> str:
        return offset_address(base, offset)

    def block_in_range(self, base: str, words: int) -> bool:
        """True when base .. base+words-1 all exist in the device."""
        kind, number = split_address(base)
        size = self.sizes.get(kind)
        if size is None:          # a device whose size the vector does not state: assume it exists
            return True
        return 0 <= number and number + words <= size

    def read(self, address: str):
        return self.values.get(address, 0)

    def read_block(self, base: str, words: int) -> list[int]:
        return [self.read(self.address(base, i)) for i in range(words)]

    def write(self, address: str, value):
        self.values[address] = value

    def write_block(self, base: str, words: list[int]):
        for i, w in enumerate(words):
            self.write(self.address(base, i), to_word(w))


def operand_value(mem: DeviceMemory, operand: dict) -> int:
    """A one-word operand: a constant (K/H) or the word in a device."""
    if "constant" in operand:
        return to_word(operand["constant"])
    return mem.read(operand["device"])


def run_steps(machine, vector: dict, scratch=()):
    """Run every step of `vector` on `machine`; return (step_expects, final_devices).

    Each step: apply `set`, snapshot, execute, and report the devices whose
    value differs from the snapshot (plus `result` for contact instructions).
    """
    mem = machine.mem
    instruction = vector["instruction"]
    operands = vector["initial"]["operands"]
    expects = []
    for step in vector["steps"]:
        for addr, value in (step.get("set") or {}).items():
            mem.write(addr, value)
        before = copy.deepcopy(mem.values)
        result = machine.execute(instruction, operands, step)
        changed = {a: v for a, v in mem.values.items()
                   if a not in scratch and (a not in before or before[a] != v)}
        expect = {"devices": changed}
        if machine.CONTACT:
            expect["result"] = result
        expects.append(expect)
    final = {a: v for a, v in mem.values.items() if a not in scratch}
    return expects, final
