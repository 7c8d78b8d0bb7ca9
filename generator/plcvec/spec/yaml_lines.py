"""Safe YAML loading that keeps the line of every value and rejects duplicate keys.

Plain PyYAML keeps the last of two equal keys without a word; a spec must never silently lose a fact,
so the node tree is walked here and every mapping is built by hand.
"""
import yaml

from plcvec.errors import SpecError


def load_with_lines(path, text):
    """Return (data, lines) where lines maps a path tuple (keys and indexes) to its 1-based line."""
    loader = yaml.SafeLoader(text)
    try:
        node = loader.get_single_node()
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else None
        raise SpecError(path, line, f"YAML syntax error: {exc.problem or exc.context}") from None
    except yaml.YAMLError as exc:
        raise SpecError(path, None, f"YAML error: {exc}") from None
    finally:
        loader.dispose()
    if node is None:
        raise SpecError(path, 1, "the file is empty")
    lines = {}
    data = _build(node, (), lines, path, loader)
    return data, lines


def _build(node, where, lines, path, loader):
    lines[where] = node.start_mark.line + 1
    if isinstance(node, yaml.MappingNode):
        out = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, yaml.ScalarNode):
                raise SpecError(path, key_node.start_mark.line + 1, "a mapping key must be a plain scalar")
            if key_node.tag == "tag:yaml.org,2002:merge":
                raise SpecError(path, key_node.start_mark.line + 1, "merge keys (<<) are not allowed in a spec")
            key = loader.construct_object(key_node)
            if not isinstance(key, (str, int)) or isinstance(key, bool):
                raise SpecError(path, key_node.start_mark.line + 1, f"mapping key {key!r} must be a string")
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
    try:
        return loader.construct_object(node, deep=True)
    except yaml.YAMLError as exc:
        raise SpecError(path, node.start_mark.line + 1, f"bad scalar: {exc}") from None
