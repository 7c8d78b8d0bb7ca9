"""Safe YAML loading that keeps the line of every value and rejects duplicate keys.

Plain PyYAML keeps the last of two equal keys without a word; a spec must never silently lose a fact,
so the node tree is walked here and every mapping is built by hand.

Only plain YAML values are built: a tag outside the YAML core schema (`!!python/object`, `!!binary`,
a local `!tag`) is refused before anything is constructed, and so are aliases (`*name`), which could
share one value between two places or make a value contain itself.
"""
import functools

import yaml

from plcvec.errors import SpecError

_CORE = "tag:yaml.org,2002:"
_SCALAR_TAGS = {_CORE + t for t in ("str", "int", "float", "bool", "null", "timestamp")}
_COLLECTION_TAGS = {yaml.MappingNode: _CORE + "map", yaml.SequenceNode: _CORE + "seq"}

# Contexts PyYAML reports for a construct that was opened and never closed: the line that opened it
# is the one to fix, not the (often much later) line where the parser gave up.
_UNCLOSED = ("while parsing a flow", "while scanning a quoted scalar", "while scanning a block scalar")


_HINTS = (
    ("mapping values are not allowed here", "check the indentation, or quote a value that contains ': '"),
    ("found character '\\t'", "indent with spaces, not tabs"),
    ("expected <block end>", "check the indentation"),
)


class _AliasError(Exception):
    def __init__(self, mark, name):
        self.mark, self.name = mark, name


class _SpecLoader(yaml.SafeLoader):
    """PyYAML's SafeLoader, refusing aliases while composing."""

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()
            raise _AliasError(event.start_mark, event.anchor)
        return super().compose_node(parent, index)


# libyaml, where PyYAML was built with it, composes the node tree about ten times faster; every
# process that reads the spec pays for it. It is used only for a file it reads without complaint
# and without aliases; anything else is read again by _SpecLoader, whose errors the messages here
# are written for. Both give the same nodes, with the same lines (tests/test_spec_errors.py).
_FastLoader = getattr(yaml, "CSafeLoader", None)


# Keyed by the whole text: a process that loads the spec again (the review, the mutation run, a
# test session) composes each unchanged file once. The nodes are only read after this (by _built).
@functools.lru_cache(maxsize=32)
def _fast_node(text):
    """(True, node) from libyaml for a file that needs no error message; (False, None) otherwise."""
    if _FastLoader is None or yaml.reader.Reader.NON_PRINTABLE.search(text):
        return False, None
    loader = _FastLoader(text)
    try:
        node = loader.get_single_node()
    except yaml.YAMLError:
        return False, None
    finally:
        loader.dispose()
    return (False, None) if _shares_a_node(node) else (True, node)


def _shares_a_node(root) -> bool:
    """Whether a node appears twice in the tree: libyaml composes an alias as the anchored node itself."""
    seen, todo = set(), [root] if root is not None else []
    while todo:
        node = todo.pop()
        if id(node) in seen:
            return True
        seen.add(id(node))
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                todo += (key, value)
        elif isinstance(node, yaml.SequenceNode):
            todo += node.value
    return False


def _runaway_quote(text, line):
    """The start line of a quoted string that spans lines and ends on 0-based `line`, if any.

    A missing closing quote makes YAML read on to the next quote character, often lines later, and
    the parser only stumbles there; the line to fix is the one where the string opened.
    """
    found = None
    try:
        for token in yaml.scan(text, Loader=yaml.SafeLoader):
            if token.start_mark.line > line:
                break
            if (isinstance(token, yaml.ScalarToken) and token.style in ('"', "'")
                    and token.start_mark.line < token.end_mark.line == line):
                found = token.start_mark.line
    except yaml.YAMLError:
        pass
    return found


def _syntax_error(path, exc, text):
    problem, context = exc.problem, exc.context
    pmark, cmark = exc.problem_mark, exc.context_mark
    start = _runaway_quote(text, pmark.line) if pmark else None
    if start is not None:
        return SpecError(path, start + 1, f"YAML syntax error: the quoted string that starts on this line runs on to "
                                          f"line {pmark.line + 1}; is its closing quote missing? ({problem})")
    if context and cmark and context.startswith(_UNCLOSED) and (pmark is None or pmark.line != cmark.line):
        what = context.replace("while parsing ", "").replace("while scanning ", "")
        what = what[2:] if what.startswith("a ") else what
        detail = f"{problem} on line {pmark.line + 1}" if pmark else problem
        return SpecError(path, cmark.line + 1, f"YAML syntax error: the {what} that starts on this line is not closed ({detail})")
    mark = pmark or cmark
    text = problem or context or "cannot be parsed"
    for start, hint in _HINTS:
        if text.startswith(start):
            text += f" ({hint})"
            break
    if context and problem and mark is pmark and cmark is not None:
        text = f"{problem} ({context} on line {cmark.line + 1})"
    return SpecError(path, mark.line + 1 if mark else None, f"YAML syntax error: {text}")


def load_with_lines(path, text):
    """Return (data, lines) where lines maps a path tuple (keys and indexes) to its 1-based line."""
    fast, node = _fast_node(text)
    if fast:
        return _built(node, path, yaml.SafeLoader(""))   # the constructor only: the nodes are built
    loader = None
    try:
        loader = _SpecLoader(text)  # the reader checks every character here
        node = loader.get_single_node()
    except _AliasError as exc:
        raise SpecError(path, exc.mark.line + 1,
                        f"aliases (*{exc.name}) are not allowed in a spec: write the value out") from None
    except yaml.reader.ReaderError as exc:
        line = text.count("\n", 0, exc.position) + 1 if isinstance(exc.position, int) else None
        char = exc.character if isinstance(exc.character, str) else chr(exc.character)
        raise SpecError(path, line, f"character {ord(char):#06x} is not allowed in a YAML file") from None
    except yaml.MarkedYAMLError as exc:
        raise _syntax_error(path, exc, text) from None
    except yaml.YAMLError as exc:
        raise SpecError(path, None, f"YAML error: {exc}") from None
    finally:
        if loader is not None:
            loader.dispose()
    return _built(node, path, loader)


def _built(node, path, loader):
    if node is None:
        raise SpecError(path, 1, "the file is empty")
    lines = {}
    data = _build(node, (), lines, path, loader)
    return data, lines


def _check_tag(node, path):
    line = node.start_mark.line + 1
    allowed = _COLLECTION_TAGS.get(type(node))
    if (node.tag == allowed) if allowed else (node.tag in _SCALAR_TAGS):
        return
    if node.tag == _CORE + "value":
        raise SpecError(path, line, "a bare '=' must be quoted (\"=\")")
    shown = "!!" + node.tag[len(_CORE):] if node.tag.startswith(_CORE) else node.tag
    if "python/" in node.tag:
        raise SpecError(path, line, f"tag {shown} is not allowed in a spec: the loader never builds Python objects")
    raise SpecError(path, line, f"tag {shown} is not allowed in a spec: only plain YAML values (strings, numbers, booleans, null, lists, mappings)")


def _build(node, where, lines, path, loader):
    lines[where] = node.start_mark.line + 1
    _check_tag(node, path)
    if isinstance(node, yaml.MappingNode):
        out = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise SpecError(path, key_node.start_mark.line + 1, "a mapping key must be a plain scalar")
            if key_node.tag == _CORE + "merge":
                raise SpecError(path, key_node.start_mark.line + 1, "merge keys (<<) are not allowed in a spec")
            _check_tag(key_node, path)
            key = _construct(key_node, path, loader)
            if not isinstance(key, (str, int)) or isinstance(key, bool):
                raise SpecError(path, key_node.start_mark.line + 1,
                                f"mapping key {key_node.value!r} must be a string (quote it)")
            key = str(key)
            if key in out:
                first = lines[where + (key,)]
                raise SpecError(path, key_node.start_mark.line + 1,
                                f"duplicate key {key!r} (first defined on line {first})")
            lines[where + (key,)] = key_node.start_mark.line + 1
            out[key] = _build(value_node, where + (key,), lines, path, loader)
            lines[where + (key,)] = key_node.start_mark.line + 1
        return out
    if isinstance(node, yaml.SequenceNode):
        return [_build(item, where + (i,), lines, path, loader) for i, item in enumerate(node.value)]
    return _construct(node, path, loader)


def _construct(node, path, loader):
    try:
        return loader.construct_object(node, deep=True)
    except (yaml.YAMLError, ValueError, TypeError, OverflowError) as exc:
        problem = getattr(exc, "problem", None) or str(exc)
        raise SpecError(path, node.start_mark.line + 1, f"bad value {node.value!r}: {problem}") from None
