"""A quick yes to "is this document valid against this JSON Schema?", made from the schema itself.

jsonschema walks a vector file at about 2 ms a vector, 6 to 7 seconds for the golden set: the
whole of a first `plcvec verify` on a machine whose cache of valid files is empty (a CI container),
against under a second with it. The vector-file schema uses a small set of keywords, and
`compile_schema` turns a schema made only of those into one Python function per schema node, which
gives jsonschema's answer to "valid?" for those keywords, and nothing else: not the errors.

jsonschema stays the judge (validate.py): a True here skips it, and on a False jsonschema finds the
errors and words them. Each keyword is checked exactly as jsonschema checks it (1.0 is an integer,
true is not 1, a NaN passes a minimum), never merely "at least as strictly": under `not`, `oneOf`
or `if`, a stricter answer would turn into a looser one. A schema with any keyword this module does
not know, or a `$ref` it cannot follow, compiles to None: every document is then judged by
jsonschema alone.
"""
from __future__ import annotations

import re
from typing import Callable

Check = Callable[[object], bool]

# Keywords that say nothing about validity (annotations and identifiers).
_ANNOTATIONS = frozenset({"$schema", "$id", "$comment", "title", "description", "examples", "default",
                          "$defs", "definitions"})


class _Unknown(Exception):
    """The schema holds something this module does not check: leave the file to jsonschema."""


def compile_schema(schema: dict) -> Check | None:
    """A function of one document: True exactly when it is valid against `schema`; or None when the
    schema uses a keyword or a reference this module does not handle."""
    try:
        return _Compiler(schema).node(schema)
    except (_Unknown, TypeError, ValueError, AttributeError, RecursionError):
        return None   # a keyword it does not know, or a schema jsonschema will refuse with its reason


def _is_int(v) -> bool:
    # bool is a subclass of int in Python, not an integer in JSON; 1.0 is an integer in JSON Schema.
    return type(v) is int or type(v) is float and v.is_integer()


def _is_number(v) -> bool:
    return type(v) is int or type(v) is float


_TYPES: dict[str, Check] = {
    "object": lambda v: type(v) is dict,
    "array": lambda v: type(v) is list,
    "string": lambda v: type(v) is str,
    "boolean": lambda v: type(v) is bool,
    "null": lambda v: v is None,
    "integer": _is_int,
    "number": _is_number,
}


def json_equal(a, b) -> bool:
    """Equality as JSON Schema's const, enum and uniqueItems mean it: true is not 1, 1 is 1.0."""
    if type(a) is bool or type(b) is bool:
        return type(a) is type(b) and a == b
    if _is_number(a) and _is_number(b):
        return a == b
    if type(a) is not type(b):
        return False
    if type(a) is list:
        return len(a) == len(b) and all(json_equal(x, y) for x, y in zip(a, b))
    if type(a) is dict:
        return a.keys() == b.keys() and all(json_equal(a[k], b[k]) for k in a)
    return a == b


class _Compiler:
    def __init__(self, root: dict):
        self.root = root
        self.refs: dict[str, list] = {}   # a $ref's target, compiled once (a one-element cell: recursion)

    def node(self, schema) -> Check:
        if schema is True:
            return lambda v: True
        if schema is False:
            return lambda v: False
        if type(schema) is not dict:
            raise _Unknown
        checks = []
        for key, arg in schema.items():
            if key in _ANNOTATIONS or key == "then":
                continue
            make = getattr(self, "_" + key.replace("$", "dollar_"), None)
            if make is None:
                raise _Unknown
            checks.append(make(arg, schema))
        if len(checks) == 1:
            return checks[0]
        return lambda v: all(check(v) for check in checks)

    # -- each keyword: a check of the instance, applied only where the keyword applies -----------

    def _type(self, arg, _schema) -> Check:
        names = [arg] if type(arg) is str else arg
        if type(names) is not list or not names or any(n not in _TYPES for n in names):
            raise _Unknown
        tests = [_TYPES[n] for n in names]
        return tests[0] if len(tests) == 1 else (lambda v: any(t(v) for t in tests))

    def _const(self, arg, _schema) -> Check:
        return lambda v: json_equal(v, arg)

    def _enum(self, arg, _schema) -> Check:
        if type(arg) is not list:
            raise _Unknown
        return lambda v: any(json_equal(v, a) for a in arg)

    # The bounds as jsonschema words them (`instance < minimum` is the error), so a NaN passes both.
    def _minimum(self, arg, _schema) -> Check:
        if not _is_number(arg):
            raise _Unknown
        return lambda v: not _is_number(v) or not v < arg

    def _maximum(self, arg, _schema) -> Check:
        if not _is_number(arg):
            raise _Unknown
        return lambda v: not _is_number(v) or not v > arg

    def _minLength(self, arg, _schema) -> Check:
        return lambda v: type(v) is not str or len(v) >= arg   # code points, as JSON Schema counts

    def _maxLength(self, arg, _schema) -> Check:
        return lambda v: type(v) is not str or len(v) <= arg

    def _minItems(self, arg, _schema) -> Check:
        return lambda v: type(v) is not list or len(v) >= arg

    def _maxItems(self, arg, _schema) -> Check:
        return lambda v: type(v) is not list or len(v) <= arg

    def _minProperties(self, arg, _schema) -> Check:
        return lambda v: type(v) is not dict or len(v) >= arg

    def _maxProperties(self, arg, _schema) -> Check:
        return lambda v: type(v) is not dict or len(v) <= arg

    def _pattern(self, arg, _schema) -> Check:
        try:
            search = re.compile(arg).search   # unanchored, as jsonschema matches it
        except re.error:
            raise _Unknown from None
        return lambda v: type(v) is not str or search(v) is not None

    def _required(self, arg, _schema) -> Check:
        names = tuple(arg)
        return lambda v: type(v) is not dict or all(n in v for n in names)

    def _properties(self, arg, _schema) -> Check:
        props = {name: self.node(sub) for name, sub in arg.items()}
        return lambda v: type(v) is not dict or all(check(v[k]) for k, check in props.items() if k in v)

    def _additionalProperties(self, arg, schema) -> Check:
        if "patternProperties" in schema:
            raise _Unknown
        known = frozenset(schema.get("properties", ()))
        if arg is False:
            return lambda v: type(v) is not dict or known.issuperset(v)
        check = self.node(arg)
        return lambda v: type(v) is not dict or all(check(x) for k, x in v.items() if k not in known)

    def _propertyNames(self, arg, _schema) -> Check:
        check = self.node(arg)
        return lambda v: type(v) is not dict or all(check(k) for k in v)

    def _items(self, arg, schema) -> Check:
        if type(arg) is not dict and type(arg) is not bool or "prefixItems" in schema:
            raise _Unknown     # the array form of `items` is an older draft's tuple
        check = self.node(arg)
        return lambda v: type(v) is not list or all(map(check, v))

    def _uniqueItems(self, arg, _schema) -> Check:
        if arg is not True:
            return lambda v: True

        def unique(v):
            if type(v) is not list:
                return True
            return not any(json_equal(v[i], v[j]) for i in range(len(v)) for j in range(i + 1, len(v)))
        return unique

    def _oneOf(self, arg, _schema) -> Check:
        branches = [self.node(sub) for sub in arg]
        return lambda v: sum(1 for b in branches if b(v)) == 1

    def _anyOf(self, arg, _schema) -> Check:
        branches = [self.node(sub) for sub in arg]
        return lambda v: any(b(v) for b in branches)

    def _allOf(self, arg, _schema) -> Check:
        branches = [self.node(sub) for sub in arg]
        return lambda v: all(b(v) for b in branches)

    def _not(self, arg, _schema) -> Check:
        branch = self.node(arg)
        return lambda v: not branch(v)

    def _if(self, arg, schema) -> Check:
        test = self.node(arg)
        then = self.node(schema.get("then", True))
        return lambda v: not test(v) or then(v)

    def _dollar_ref(self, arg, _schema) -> Check:
        if type(arg) is not str or not arg.startswith("#/"):
            raise _Unknown
        if arg not in self.refs:
            cell: list = []
            self.refs[arg] = cell
            target = self.root
            for part in arg[2:].split("/"):
                part = part.replace("~1", "/").replace("~0", "~")
                if type(target) is not dict or part not in target:
                    raise _Unknown
                target = target[part]
            cell.append(self.node(target))
        cell = self.refs[arg]
        return lambda v: cell[0](v)
