"""Resolve rule parameters that depend on an interpretation to the value of a chosen alternative.

With a `consulted` set, the resolved document also records which interpretations the engine reads:
every mapping that holds a value an interpretation chose is a `Consulting` dict, and reading such a
value adds the interpretation's id to the set. The builder uses it to run a vector only under the
combinations of the interpretations its executions actually consulted (see plcvec.engine).
"""
import copy


class Consulting(dict):
    """A mapping some of whose values an interpretation chose; reading one adds the interpretation to `sink`.

    `by_key` maps each such key to its interpretation. When `whole` names an interpretation, the
    whole mapping is that interpretation's value (e.g. `logic: {interpretation: ...}`): every read of
    it, its size included, consults the interpretation, while handing the mapping itself around does
    not. Anything that enumerates the values (items, values, iteration, dict(...), copying) records
    every interpretation it could see, so nothing is read unrecorded.
    """

    __slots__ = ("_by_key", "_sink", "_whole")

    def __init__(self, items, by_key, sink, whole=None):
        super().__init__(items)
        self._by_key, self._sink, self._whole = by_key, sink, whole

    def _all(self):
        self._sink.update(self._by_key.values())

    def __getitem__(self, key):
        iid = self._by_key.get(key)
        if iid is not None:
            self._sink.add(iid)
        return dict.__getitem__(self, key)

    def get(self, key, default=None):
        if self._whole is not None:
            self._sink.add(self._whole)
        iid = self._by_key.get(key)
        if iid is not None:
            self._sink.add(iid)
        return dict.get(self, key, default)

    def __contains__(self, key):
        if self._whole is not None:
            self._sink.add(self._whole)
        return dict.__contains__(self, key)

    def __len__(self):
        if self._whole is not None:
            self._sink.add(self._whole)
        return dict.__len__(self)

    def __iter__(self):
        self._all()
        return dict.__iter__(self)

    def items(self):
        self._all()
        return dict.items(self)

    def values(self):
        self._all()
        return dict.values(self)

    def keys(self):
        self._all()
        return dict.keys(self)

    def __eq__(self, other):
        self._all()
        return dict.__eq__(self, other)

    __hash__ = None

    def __reduce_ex__(self, protocol):
        self._all()
        return dict, (dict(dict.items(self)),)


def resolve(doc, choices, consulted=None):
    """A copy of the spec document with every {interpretation: ID} replaced by the chosen alternative's value.

    `choices` maps interpretation id to alternative id; interpretations not named take their default.
    With a set `consulted`, reading a chosen value from the copy adds its interpretation to that set.
    The parts of the document no interpretation chooses are the document's own (see Resolver).
    """
    return Resolver(doc).resolve(choices, consulted)


class Resolver:
    """resolve() of one document under many sets of choices.

    Which parts of the document hold a choice is found once; only those are copied for each set of
    choices, and every other part is the document's own, shared by every copy: a resolved document
    is read, never changed (an engine keeps no state in it, see plcvec.engine), so a copy of what no
    choice changes would only cost time (the specs are large; a family is resolved a few dozen times).
    """

    def __init__(self, doc):
        self.doc = doc
        self._top = {k: v for k, v in doc.items() if k != "interpretations"}
        self._holds = set()   # ids of the dicts and lists of `doc` with a choice somewhere inside
        self._find(self._top)

    def _find(self, node):
        """Whether `node` holds a choice; the containers that do are recorded in _holds."""
        if isinstance(node, dict):
            if _is_choice(node):
                return True
            inside = [self._find(v) for v in node.values()]
        elif isinstance(node, list):
            inside = [self._find(v) for v in node]
        else:
            return False
        if any(inside):
            self._holds.add(id(node))
            return True
        return False

    def resolve(self, choices, consulted=None):
        doc, holds = self.doc, self._holds
        alts = {}
        for interp in doc["interpretations"]:
            chosen = choices.get(interp["id"], interp["default"])
            alts[interp["id"]] = next(a for a in interp["alternatives"] if a["id"] == chosen)

        def chosen_value(iid, key):
            value = copy.deepcopy(alts[iid]["sets"][key])
            if consulted is not None and isinstance(value, dict):
                return Consulting(value, {k: iid for k in value}, consulted, whole=iid)
            return value

        def walk(node, key):
            if isinstance(node, dict):
                if len(node) == 1 and "interpretation" in node:
                    return chosen_value(node["interpretation"], key)
                if id(node) not in holds:
                    return node
                out = {k: walk(v, k) for k, v in node.items()}
                if consulted is None:
                    return out
                # A chosen mapping records its own reads; any other chosen value is recorded when read from here.
                by_key = {k: v["interpretation"] for k, v in node.items()
                          if _is_choice(v) and not isinstance(out[k], Consulting)}
                return Consulting(out, by_key, consulted) if by_key else out
            if isinstance(node, list):
                return [walk(v, key) for v in node] if id(node) in holds else node
            return node

        return walk(self._top, None)


def _is_choice(node):
    return isinstance(node, dict) and len(node) == 1 and "interpretation" in node
