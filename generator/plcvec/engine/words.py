"""Device addresses, operand words, and the field encodings a spec can name.

Addresses are parsed once per distinct (head, words) and field layouts once per codec: an engine
executes a vector many times over (every step, every combination of alternatives), and what an
address or a layout means does not change between executions.
"""
import re
from functools import lru_cache

_ADDRESS = re.compile(r"^([A-Za-z_]+)(\d+)$")
_MEMO_SIZE = 4096   # distinct operand words a codec remembers the reading of


class DeviceRangeError(Exception):
    """An operand's words run past the end of its device range."""


@lru_cache(maxsize=4096)
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


@lru_cache(maxsize=4096)
def word_addresses(head, words):
    """The addresses of an operand's words, as a tuple (parsed once per head and length)."""
    return tuple(word_address(head, k) for k in range(words))


def operand_words(head, words):
    return list(word_addresses(head, words))


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


@lru_cache(maxsize=None)
def decoder(encoding, width):
    """decode() of one encoding and width as a function of the raw bits: a table for BCD up to 16 bits
    (built once), the arithmetic itself otherwise."""
    if encoding == "bcd" and width <= 16:
        return [decode(raw, encoding, width) for raw in range(1 << width)].__getitem__
    if encoding == "unsigned16":
        return int
    return lambda raw: decode(raw, encoding, width)


class FieldCodec:
    """Reads and writes the fields of a multi-word operand as the spec's data.fields lay them out."""

    def __init__(self, fields):
        self.fields = fields
        self.names = [f["name"] for f in fields]
        self.count = 1 + max(f["word"] for f in fields)
        # (name, word, lsb, mask, encoding, width) per field: the layout, read once.
        self._layout = [(f["name"], f["word"], f["lsb"], (1 << f["width"]) - 1, f["encoding"], f["width"])
                        for f in fields]
        self._readers = [(name, word, lsb, mask, decoder(encoding, width))
                         for name, word, lsb, mask, encoding, width in self._layout]
        self._radices = [f["max"] + 1 for f in fields]
        self._mins, self._maxes = [f["min"] for f in fields], [f["max"] for f in fields]
        self._checked = {}   # words -> read_checked()
        self._modulus = 1
        for r in self._radices:
            self._modulus *= r

    def raw(self, words, field):
        return (words[field["word"]] >> field["lsb"]) & ((1 << field["width"]) - 1)

    def read(self, state, head):
        """{field name: decoded value or None}."""
        words = [state[a] for a in word_addresses(head, self.count)]
        return {name: dec((words[word] >> lsb) & mask) for name, word, lsb, mask, dec in self._readers}

    def read_checked(self, state, head):
        """(read(state, head), whether every field holds a valid encoding within its min..max).

        Both depend on the operand's words alone, so they are worked out once per distinct words (a
        bounded memo; a case runs the same data through many executions, the exhaustive tier through
        every selector value). The values are shared between calls: read them, never change them.
        """
        words = tuple(map(state.__getitem__, word_addresses(head, self.count)))
        known = self._checked.get(words)
        if known is None:
            values = {name: dec((words[word] >> lsb) & mask) for name, word, lsb, mask, dec in self._readers}
            known = (values, all(v is not None and lo <= v <= hi for v, lo, hi in zip(values.values(), self._mins, self._maxes)))
            if len(self._checked) >= _MEMO_SIZE:
                self._checked.clear()
            self._checked[words] = known
        return known

    def pack(self, values):
        """The words that hold `values` (field name -> value); fields not given are 0."""
        words = [0] * self.count
        for name, word, lsb, _, encoding, width in self._layout:
            words[word] |= encode(values.get(name, 0), encoding, width) << lsb
        return words

    def write(self, state, head, values):
        words = self.pack(values)
        for address, word in zip(word_addresses(head, len(words)), words):
            state[address] = word

    def read_field(self, state, head, field):
        """The value one field of the operand at `head` holds now (None when not a valid encoding)."""
        address = word_address(head, field["word"])
        return decode(self.raw([0] * field["word"] + [state[address]], field), field["encoding"], field["width"])

    def write_field(self, state, head, field, value):
        """Store `value` in one field of the operand at `head`, leaving the other bits of its word as they are."""
        address = word_address(head, field["word"])
        mask = ((1 << field["width"]) - 1) << field["lsb"]
        state[address] = (state[address] & ~mask) | (encode(value, field["encoding"], field["width"]) << field["lsb"] & mask)

    def units(self, field):
        """How many units of the least significant field one unit of `field` is worth."""
        weight = 1
        for f, radix in zip(reversed(self.fields), reversed(self._radices)):
            if f is field:
                return weight
            weight *= radix
        raise ValueError(f"{field['name']} is not a field of this codec")

    def in_range(self, field, value):
        return value is not None and field["min"] <= value <= field["max"]

    def radices(self):
        """Mixed radix of the fields, least significant last: each field counts max + 1 units of the next."""
        return list(self._radices)

    def to_units(self, values):
        total = 0
        for name, radix in zip(self.names, self._radices):
            total = total * radix + values[name]
        return total

    def from_units(self, total):
        out = {}
        for name, radix in zip(reversed(self.names), reversed(self._radices)):
            total, out[name] = divmod(total, radix)
        return out

    def modulus(self):
        return self._modulus
