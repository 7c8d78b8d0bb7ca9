"""Pieces shared by the case families: operand contents, slugs, placement."""
from plcvec.engine.words import FieldCodec, operand_words


def hexw(value):
    return f"{value & 0xFFFF:04X}H"


def signed_boundaries(field):
    """Values around a field's range and the extremes of its word: the boundary set of the issue."""
    lo, hi = field["min"], field["max"]
    if field["encoding"] == "bcd":
        return sorted({lo, hi} | ({lo - 1} if lo > 0 else set()) | ({hi + 1} if hi + 1 < 10 ** (field["width"] // 4) else set()))
    span = 1 << field["width"]
    word_lo, word_hi = (-(span // 2), span // 2 - 1) if field["encoding"] == "signed16" else (0, span - 1)
    return sorted(v for v in {lo, hi, lo - 1, hi + 1, -1, 0, word_lo, word_hi} if word_lo <= v <= word_hi)


_PACKED_MAX = 4096


class Operands:
    """Builds operand words from field values, with raw overrides for invalid encodings."""

    def __init__(self, fields):
        self.codec = FieldCodec(fields)
        self.fields = fields
        self.by_name = {f["name"]: f for f in fields}
        # Field values -> words: the golden cases pack the same few values over and over. Bounded, as a
        # fuzzing run packs new values without end.
        self._packed = {}

    def mid(self, name, offset=0):
        f = self.by_name[name]
        return (f["min"] + f["max"]) // 2 + offset

    def values(self, **overrides):
        v = {f["name"]: self.mid(f["name"]) for f in self.fields}
        v.update(overrides)
        return v

    def words(self, values, raw=None):
        """Words holding `values`; `raw` maps a field to raw bits placed as they are (e.g. non-BCD)."""
        key = tuple(values.items())
        packed = self._packed.get(key)
        if packed is None:
            if len(self._packed) >= _PACKED_MAX:
                self._packed.clear()
            packed = self._packed[key] = self.codec.pack(values)
        words = list(packed)
        for name, bits in (raw or {}).items():
            f = self.by_name[name]
            mask = ((1 << f["width"]) - 1) << f["lsb"]
            words[f["word"]] = (words[f["word"]] & ~mask) | ((bits << f["lsb"]) & mask)
        return words

    def place(self, devices, head, words):
        for address, word in zip(operand_words(head, len(words)), words):
            devices[address] = word & 0xFFFF


def top_head(prefix, size, words, beyond):
    """The head address whose words end `beyond` words past the top of the device range (0 = the last fit)."""
    return f"{prefix}{size - words + beyond}"
