"""Device addresses, operand words, and the field encodings a spec can name."""
import re

_ADDRESS = re.compile(r"^([A-Za-z_]+)(\d+)$")


class DeviceRangeError(Exception):
    """An operand's words run past the end of its device range."""


def split_address(address):
    m = _ADDRESS.match(address)
    if not m:
        return address, None
    return m.group(1), int(m.group(2))


def word_address(head, offset):
    """The address `offset` words after `head`, written as the manual writes it (D100 + 2 -> D102)."""
    prefix, number = split_address(head)
    return f"{prefix}{number + offset}"


def in_device_range(head, words, device_sizes):
    prefix, number = split_address(head)
    size = device_sizes.get(prefix)
    return size is None or number is None or number + words <= size


def operand_words(head, words):
    return [word_address(head, k) for k in range(words)]


def decode(raw, encoding, width):
    """The value a field's raw bits stand for, or None when they are not a valid encoding (non-BCD)."""
    if encoding == "signed16":
        return raw - (1 << width) if raw >= (1 << (width - 1)) else raw
    if encoding == "unsigned16":
        return raw
    value, scale = 0, 1
    for _ in range(width // 4):
        digit = raw & 0xF
        if digit > 9:
            return None
        value += digit * scale
        raw >>= 4
        scale *= 10
    return value


def encode(value, encoding, width):
    if encoding in ("signed16", "unsigned16"):
        return value & ((1 << width) - 1)
    raw = 0
    for shift in range(0, width, 4):
        raw |= (value % 10) << shift
        value //= 10
    return raw


class FieldCodec:
    """Reads and writes the fields of a multi-word operand as the spec's data.fields lay them out."""

    def __init__(self, fields):
        self.fields = fields
        self.names = [f["name"] for f in fields]

    def raw(self, words, field):
        return (words[field["word"]] >> field["lsb"]) & ((1 << field["width"]) - 1)

    def read(self, state, head):
        """{field name: decoded value or None}."""
        count = 1 + max(f["word"] for f in self.fields)
        words = [state[a] for a in operand_words(head, count)]
        return {f["name"]: decode(self.raw(words, f), f["encoding"], f["width"]) for f in self.fields}

    def pack(self, values):
        """The words that hold `values` (field name -> value); fields not given are 0."""
        count = 1 + max(f["word"] for f in self.fields)
        words = [0] * count
        for f in self.fields:
            raw = encode(values.get(f["name"], 0), f["encoding"], f["width"])
            words[f["word"]] |= raw << f["lsb"]
        return words

    def write(self, state, head, values):
        for address, word in zip(operand_words(head, len(self.pack(values))), self.pack(values)):
            state[address] = word

    def in_range(self, field, value):
        return value is not None and field["min"] <= value <= field["max"]

    def radices(self):
        """Mixed radix of the fields, least significant last: each field counts max + 1 units of the next."""
        return [f["max"] + 1 for f in self.fields]

    def to_units(self, values):
        total = 0
        for f, radix in zip(self.fields, self.radices()):
            total = total * radix + values[f["name"]]
        return total

    def from_units(self, total):
        out = {}
        for f, radix in reversed(list(zip(self.fields, self.radices()))):
            total, out[f["name"]] = divmod(total, radix)
        return out

    def modulus(self):
        m = 1
        for r in self.radices():
            m *= r
        return m
