"""Consistency checks a JSON Schema cannot express: references, ranges, bit layouts, unique ids."""
from plcvec.engine.undefined import UNDEFINED
from plcvec.spec.flags import flag_groups
from plcvec.spec.model_checks import check_model
from plcvec.spec.tags import TAGS

# The value range each word encoding can hold at all, by field width; a field range outside it is a typo.
_ENCODING_LIMITS = {
    "signed16": lambda width: (-(1 << (width - 1)), (1 << (width - 1)) - 1),
    "unsigned16": lambda width: (0, (1 << width) - 1),
    "bcd": lambda width: (0, 10 ** (width // 4) - 1),
}


def _walk(node, where=()):
    if isinstance(node, dict):
        yield where, node
        for k, v in node.items():
            yield from _walk(v, where + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _walk(v, where + (i,))


def _unique(fam, items, where, what):
    seen = {}
    for i, item in enumerate(items):
        key = item["id"] if "id" in item else item.get("name")
        if key in seen:
            raise fam.error(where + (i,), f"duplicate {what} id {key!r} (first used on line {fam.line_of(*where, seen[key])})")
        seen[key] = i


def check_family(fam):
    doc = fam.doc
    _unique(fam, doc["clauses"], ("clauses",), "clause")
    _unique(fam, doc["interpretations"], ("interpretations",), "interpretation")
    _unique(fam, doc["errata"], ("errata",), "erratum")
    _unique(fam, doc.get("examples", []), ("examples",), "example")
    _check_references(fam)
    _check_coverage(fam)
    check_model(fam)
    _check_interpretations(fam)
    _check_unjudged(fam)
    _check_fields(fam)
    if fam.kind == "masked_compare":
        _check_selector(fam)
        _check_compare_examples(fam)
    if fam.kind == "clock_add":
        for i, check in enumerate(doc["errors"]["checks"]):
            for j, op in enumerate(check["operands"]):
                if op not in doc["operands"]:
                    raise fam.error(("errors", "checks", i, "operands", j), f"unknown operand {op!r}")
    for key, name in doc.get("nonexistent_dates", {}).get("calendar", {}).items():
        if name not in {f["name"] for f in doc["data"]["fields"]}:
            raise fam.error(("nonexistent_dates", "calendar", key), f"calendar {key} names no field {name!r}")
    placement = doc["generation"]["placement"]
    for op in doc["operands"]:
        if op not in placement:
            raise fam.error(("generation", "placement"), f"no placement for operand {op!r}")
    if "special_relay" in doc["generation"] and "special_relays" not in doc:
        raise fam.error(("generation", "special_relay"), "a special relay for the vectors needs a special_relays section")


def _check_references(fam):
    for where, node in _walk(fam.doc):
        for key, value in node.items():
            if key in ("clause",) or key.endswith("_clause"):
                if value not in fam.clauses:
                    raise fam.error(where + (key,), f"unknown clause {value!r}")
            if key.endswith("_clauses"):  # field_clauses, device_clauses: {name: clause id}
                for f, c in value.items():
                    if c not in fam.clauses:
                        raise fam.error(where + (key, f), f"unknown clause {c!r}")
                    if key == "device_clauses" and f not in node.get("devices", []):
                        raise fam.error(where + (key, f), f"device {f!r} is not one of the devices {node.get('devices', [])}")
            if key == "interpretation" and len(node) == 1:
                if value not in fam.interpretations:
                    raise fam.error(where + (key,), f"unknown interpretation {value!r}")
                interp = fam.interpretations[value]
                param = where[-1]
                index = list(fam.interpretations).index(value)
                for k, alt in enumerate(interp["alternatives"]):
                    if param not in alt["sets"]:
                        raise fam.error(("interpretations", index, "alternatives", k, "sets"),
                                        f"interpretation {value!r} alternative {alt['id']!r} does not set {param!r}, "
                                        f"which {'.'.join(map(str, where))} takes from it")


def _check_coverage(fam):
    """The coverage section names clauses and generator tags; a typo would silently cite nothing."""
    coverage = fam.doc.get("coverage", {})
    for i, c in enumerate(coverage.get("every_vector", [])):
        if c not in fam.clauses:
            raise fam.error(("coverage", "every_vector", i), f"unknown clause {c!r}")
    for tag, c in coverage.get("by_tag", {}).items():
        if tag not in TAGS:
            raise fam.error(("coverage", "by_tag", tag), f"unknown tag {tag!r} (known: {', '.join(sorted(TAGS))})")
        if c not in fam.clauses:
            raise fam.error(("coverage", "by_tag", tag), f"unknown clause {c!r}")
    cited = set(coverage.get("every_vector", [])) | set(coverage.get("by_tag", {}).values())
    for i, entry in enumerate(coverage.get("no_vectors", [])):
        if entry["clause"] in cited:
            raise fam.error(("coverage", "no_vectors", i, "clause"),
                            f"clause {entry['clause']!r} is said to have no vectors but the coverage section cites it in vectors")


def _check_interpretations(fam):
    for i, interp in enumerate(fam.doc["interpretations"]):
        ids = [a["id"] for a in interp["alternatives"]]
        if len(set(ids)) != len(ids):
            raise fam.error(("interpretations", i, "alternatives"), f"interpretation {interp['id']!r} repeats an alternative id")
        if interp["default"] not in ids:
            raise fam.error(("interpretations", i, "default"),
                            f"default {interp['default']!r} is not one of the alternatives {ids}")
        first = sorted(interp["alternatives"][0]["sets"])
        for k, alt in enumerate(interp["alternatives"][1:], 1):
            if sorted(alt["sets"]) != first:
                raise fam.error(("interpretations", i, "alternatives", k, "sets"),
                                f"alternative {alt['id']!r} of {interp['id']!r} sets {sorted(alt['sets'])}, "
                                f"but {interp['alternatives'][0]['id']!r} sets {first}: alternatives must set the same parameters")
        used = any(n.get("interpretation") == interp["id"] for _, n in _walk(fam.doc) if len(n) == 1)
        if not used:
            raise fam.error(("interpretations", i), f"interpretation {interp['id']!r} is not referenced by any rule parameter")


def _check_unjudged(fam):
    """An alternative that leaves devices unjudged names operands and flag groups the family has, is
    never the default (a vector's own expectation judges every device it lists), and is exactly an
    alternative that sets a parameter to `undefined`, the value at which the engine says so."""
    operands = fam.doc["operands"]
    flags = [g["name"] for g in flag_groups(fam.doc)]
    for i, interp in enumerate(fam.doc["interpretations"]):
        for k, alt in enumerate(interp["alternatives"]):
            where = ("interpretations", i, "alternatives", k)
            unjudged = alt.get("unjudged")
            sets_undefined = UNDEFINED in alt["sets"].values()
            if unjudged is None:
                if sets_undefined:
                    raise fam.error(where + ("sets",), f"alternative {alt['id']!r} of {interp['id']!r} sets {UNDEFINED!r} "
                                                       "but does not say which devices it leaves unjudged (unjudged:)")
                continue
            if not sets_undefined:
                raise fam.error(where + ("unjudged",), f"alternative {alt['id']!r} of {interp['id']!r} leaves devices "
                                                       f"unjudged but sets no parameter to {UNDEFINED!r}, so no execution says where")
            if alt["id"] == interp["default"]:
                raise fam.error(where + ("unjudged",), f"the default of {interp['id']!r} leaves devices unjudged; "
                                                       "a default must judge every device a vector lists")
            for j, name in enumerate(unjudged.get("operands", ())):
                if name not in operands:
                    raise fam.error(where + ("unjudged", "operands", j), f"unknown operand {name!r} (known: {', '.join(operands)})")
            for j, name in enumerate(unjudged.get("flags", ())):
                if name not in flags:
                    raise fam.error(where + ("unjudged", "flags", j), f"unknown flag {name!r} (known: {', '.join(flags)})")


def _check_fields(fam):
    doc = fam.doc
    fields = doc["data"]["fields"]
    _unique(fam, fields, ("data", "fields"), "field")
    data_words = [o.get("words", 0) for o in doc["operands"].values() if o["role"] in ("data", "addend", "result", "preset", "measured")]
    words = min(data_words) if data_words else 0
    used_bits = {}
    for i, f in enumerate(fields):
        where = ("data", "fields", i)
        if f["min"] > f["max"]:
            raise fam.error(where, f"field {f['name']!r}: min {f['min']} is greater than max {f['max']}")
        if f["lsb"] + f["width"] > 16:
            raise fam.error(where, f"field {f['name']!r}: bits {f['lsb']}..{f['lsb'] + f['width'] - 1} do not fit a 16-bit word")
        if f["encoding"] == "bcd" and f["width"] % 4:
            raise fam.error(where, f"field {f['name']!r}: width {f['width']} is not a whole number of 4-bit BCD digits")
        if f["encoding"] in ("signed16", "unsigned16") and f["width"] != 16:
            raise fam.error(where, f"field {f['name']!r}: encoding {f['encoding']} needs width 16")
        lo, hi = _ENCODING_LIMITS[f["encoding"]](f["width"])
        if f["min"] < lo or f["max"] > hi:
            raise fam.error(where, f"field {f['name']!r}: range {f['min']}..{f['max']} does not fit {f['encoding']} ({lo}..{hi})")
        if f["word"] >= words:
            raise fam.error(where, f"field {f['name']!r}: word {f['word']} is past the operands' {words} words")
        for b in range(f["lsb"], f["lsb"] + f["width"]):
            if (f["word"], b) in used_bits:
                raise fam.error(where, f"field {f['name']!r} overlaps field {used_bits[(f['word'], b)]!r} at word {f['word']} bit {b}")
            used_bits[(f["word"], b)] = f["name"]


def _check_selector(fam):
    doc = fam.doc
    sel = doc["selector"]
    names = [f["name"] for f in doc["data"]["fields"]]
    if sel["operand"] not in doc["operands"]:
        raise fam.error(("selector", "operand"), f"unknown operand {sel['operand']!r}")
    if set(sel["field_bits"]) != set(names):
        raise fam.error(("selector", "field_bits"), f"field_bits must name exactly the fields {sorted(names)}")
    if set(sel["field_clauses"]) != set(names):
        raise fam.error(("selector", "field_clauses"), f"field_clauses must name exactly the fields {sorted(names)}")
    owner = {}
    bits = [(b, f"field {f}", ("selector", "field_bits", f)) for f, b in sel["field_bits"].items()]
    bits += [(b, "reserved", ("selector", "reserved_bits", j)) for j, b in enumerate(sel["reserved_bits"])]
    if "source_bit" in sel:
        bits.append((sel["source_bit"]["bit"], "current-clock bit", ("selector", "source_bit", "bit")))
    for b, who, where in bits:
        if b in owner:
            other, other_where = owner[b]
            raise fam.error(where, f"bit {b} is assigned twice ({who} here, {other} on line {fam.line_of(*other_where)})")
        owner[b] = who, where
    if "source_bit" in sel:
        clock = doc.get("current_clock", {}).get("fields")
        if clock is None:
            raise fam.error(("selector", "source_bit"), "a current-clock bit needs a current_clock section")
        if sorted(clock) != sorted(names):
            raise fam.error(("current_clock", "fields"), f"current_clock must name the fields {sorted(names)}")
    if "flags" in doc:
        for key, row in doc["flags"]["table"].items():
            if set(row) != set(doc["flags"]["devices"]):
                raise fam.error(("flags", "table", key), f"flags.table.{key} must name the same flag symbols as flags.devices")


def _check_compare_examples(fam):
    names = {f["name"]: f for f in fam.doc["data"]["fields"]}
    symbols = {c["symbol"] for c in fam.doc["instructions"]["conditions"]}
    for i, ex in enumerate(fam.doc["examples"]):
        where = ("examples", i)
        for label, values in ex.get("values", {}).items():
            for k, v in values.items():
                if k not in names:
                    raise fam.error(where + ("values", label, k), f"unknown field {k!r}")
                if not names[k]["min"] <= v <= names[k]["max"]:
                    raise fam.error(where + ("values", label, k), f"{label}.{k} = {v} is outside {names[k]['min']}..{names[k]['max']}")
        if "table" in ex:
            if ex.get("condition") not in symbols:
                raise fam.error(where + ("condition",), f"unknown condition {ex.get('condition')!r}")
            pairs = ex.get("pairs", {})
            for name, pair in pairs.items():
                for label in pair:
                    if label not in ex.get("values", {}):
                        raise fam.error(where + ("pairs", name), f"pair {name!r} names unknown value {label!r}")
            for j, row in enumerate(ex["table"]):
                if len(row["printed"]) != len(pairs):
                    raise fam.error(where + ("table", j, "printed"), f"{len(row['printed'])} printed cells for {len(pairs)} pairs")
        for j, name in enumerate(ex.get("compared", [])):
            if name not in names:
                raise fam.error(where + ("compared", j), f"unknown field {name!r}")
