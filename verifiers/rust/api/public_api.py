#!/usr/bin/env python3
"""The public API of the `plcvec` crate, read from rustdoc's JSON output, against a previous release.

    public_api.py list NEW.json                           # one line per public item
    public_api.py diff OLD.json NEW.json --changes CHANGES.md --version 0.2.0 [--fragments DIR]

`diff` lists every change a user of OLD can trip over (an item removed, renamed or moved; a changed
signature; a field added to a struct a user can build; a variant added to an enum a user can match
exhaustively; a method a trait's implementers must now write), and exits 1 when one of them is not
named in the Breaking section of that version in CHANGES.md or in the `### Breaking` section of a
news fragment in DIR not yet folded into it: each change must be
named by its item's own name (`shard_of`, `reference`), as a word of that text; what goes with a removed
item (the functions of a removed module) is named by that item.

Why this and not cargo-semver-checks: that tool is some 300 crates to build, more than CI's whole
budget on a fresh machine; this reads the same rustdoc JSON (`cargo rustdoc -- --output-format
json`, which rustdoc writes on the stable toolchain with RUSTC_BOOTSTRAP=1) with the standard
library alone. It checks the kinds of change above, not every lint of that tool (trait bounds,
auto traits, `#[must_use]`).
"""
from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path


def render(t) -> str:
    """A type as text, by the names users write (never rustdoc's ids)."""
    if t is None:
        return "()"
    if not isinstance(t, dict):
        return str(t)
    (kind, v), = t.items()
    if kind == "resolved_path":
        name = v.get("path") or v.get("name", "")
        return name.split("::")[-1] + render_args(v.get("args"))
    if kind == "borrowed_ref":
        return "&" + ("mut " if v.get("is_mutable") or v.get("mutable") else "") + render(v["type"])
    if kind in ("primitive", "generic"):
        return v
    if kind == "tuple":
        return "(" + ", ".join(render(x) for x in v) + ")"
    if kind == "slice":
        return "[" + render(v) + "]"
    if kind == "array":
        return f"[{render(v['type'])}; {v['len']}]"
    if kind in ("impl_trait", "dyn_trait"):
        bounds = v if isinstance(v, list) else v.get("traits", [])
        names = []
        for b in bounds:
            tb = b.get("trait_bound", b)
            trait = tb.get("trait", {})
            names.append((trait.get("path") or trait.get("name", "")).split("::")[-1] + render_args(trait.get("args")))
        return ("impl " if kind == "impl_trait" else "dyn ") + " + ".join(n for n in names if n)
    if kind == "qualified_path":
        return f"<{render(v.get('self_type'))}>::{v.get('name')}"
    return kind


def render_args(args) -> str:
    if not args or "angle_bracketed" not in args:
        return ""
    out = []
    for a in args["angle_bracketed"].get("args", []):
        if isinstance(a, dict) and "type" in a:
            out.append(render(a["type"]))
    return "<" + ", ".join(out) + ">" if out else ""


def signature(fn) -> str:
    sig = fn.get("sig") or fn.get("decl", {})
    inputs = ", ".join(render(t) for _, t in sig.get("inputs", []))
    generics = [p["name"] for p in fn.get("generics", {}).get("params", []) if "type" in p.get("kind", {})]
    head = "fn" + (f"<{', '.join(generics)}>" if generics else "")
    return f"{head}({inputs}) -> {render(sig.get('output'))}"


def hidden(item) -> bool:
    return any("doc(hidden)" in json.dumps(a) for a in item.get("attrs", []))


def non_exhaustive(item) -> bool:
    return any("non_exhaustive" in json.dumps(a) for a in item.get("attrs", []))


class Api:
    """path -> description of every public item, and the facts the breaking rules need."""

    def __init__(self, doc: dict):
        self.index = {str(k): v for k, v in doc["index"].items()}
        self.items: dict[str, str] = {}
        self.constructible: set[str] = set()   # structs a user can build with a literal
        self.exhaustive: set[str] = set()      # enums a user can match without a wildcard
        self.trait_required: dict[str, set[str]] = {}
        self.aliases: dict[str, str] = {}      # a type alias's name -> the struct or enum it names
        self.module(str(doc["root"]), "")

    def get(self, id_):
        return self.index.get(str(id_))

    def module(self, id_: str, path: str) -> None:
        item = self.get(id_)
        for child in item["inner"]["module"]["items"]:
            c = self.get(child)
            if c is None or c.get("visibility") != "public" or hidden(c):
                continue
            if "use" in c["inner"]:
                use = c["inner"]["use"]
                target = self.get(use.get("id")) if use.get("id") is not None else None
                name = f"{path}{use['name']}"
                if target is None:
                    self.items[name] = f"use {use['source']}"
                elif not hidden(target):
                    self.item(target, name, use.get("id"))
                continue
            self.item(c, f"{path}{c['name']}", child)

    def item(self, c, name: str, id_) -> None:
        (kind, inner), = ((k, v) for k, v in c["inner"].items())
        if kind == "module":
            self.items[name] = "mod"
            self.module(str(id_), name + "::")
        elif kind == "function":
            self.items[name] = signature(inner)
        elif kind == "struct":
            self.structure(name, inner)
        elif kind == "enum":
            self.items[name] = "enum"
            if not non_exhaustive(c):
                self.exhaustive.add(name)
            for v in inner.get("variants", []):
                variant = self.get(v)
                self.items[f"{name}::{variant['name']}"] = "variant " + json.dumps(variant["inner"]["variant"]["kind"] if isinstance(variant["inner"]["variant"].get("kind"), str) else sorted(variant["inner"]["variant"].get("kind", {})))
            self.impls(name, inner.get("impls", []))
        elif kind == "trait":
            self.items[name] = "trait"
            required = set()
            for m in inner.get("items", []):
                method = self.get(m)
                if method is None or hidden(method):
                    continue
                (mk, mi), = method["inner"].items()
                text = signature(mi) if mk == "function" else mk
                self.items[f"{name}::{method['name']}"] = text
                if mk == "function" and not mi.get("has_body", True):
                    required.add(method["name"])
            self.trait_required[name] = required
        elif kind in ("constant", "static"):
            self.items[name] = f"{kind} {render(inner.get('type'))}"
        elif kind == "type_alias" and self.aliased(inner) is not None:
            # `pub type Old = New;` (a rename's deprecated old name) is the struct or enum itself
            # to a user: its fields, literals, patterns and methods work through the old name.
            target = self.aliased(inner)
            self.aliases[c["name"]] = target["name"]
            self.item(target, name, inner["type"]["resolved_path"]["id"])
        else:
            self.items[name] = kind

    def aliased(self, inner):
        """The struct or enum a type alias names without generic arguments, else None."""
        path = (inner.get("type") or {}).get("resolved_path")
        args = (path or {}).get("args") or {}
        if not isinstance(path, dict) or "parenthesized" in args or (args.get("angle_bracketed") or {}).get("args"):
            return None
        target = self.get(path.get("id"))
        if target is None or not any(k in target["inner"] for k in ("struct", "enum")):
            return None
        return target

    def structure(self, name: str, inner) -> None:
        self.items[name] = "struct"
        shape = inner.get("kind", {})
        if isinstance(shape, dict) and "plain" in shape:
            plain = shape["plain"]
            fields = [self.get(f) for f in plain.get("fields", [])]
            if not plain.get("has_stripped_fields") and not non_exhaustive({"attrs": []}):
                self.constructible.add(name)
            for f in fields:
                if f is not None and f.get("visibility") == "public":
                    self.items[f"{name}.{f['name']}"] = "field " + render(f["inner"]["struct_field"])
        elif isinstance(shape, dict) and "tuple" in shape:
            if any(f is None for f in shape["tuple"]):
                pass
            else:
                self.constructible.add(name)
        self.impls(name, inner.get("impls", []))

    def impls(self, name: str, impls) -> None:
        for i in impls:
            imp = self.get(i)
            if imp is None:
                continue
            body = imp["inner"]["impl"]
            if body.get("is_synthetic") or body.get("blanket_impl") is not None:
                continue
            trait = body.get("trait")
            if trait is not None:
                self.items[f"{name} impl {(trait.get('path') or trait.get('name', '')).split('::')[-1]}"] = "impl"
                continue
            for m in body.get("items", []):
                method = self.get(m)
                if method is None or method.get("visibility") != "public" or hidden(method):
                    continue
                (mk, mi), = method["inner"].items()
                self.items[f"{name}::{method['name']}"] = signature(mi) if mk == "function" else mk


def breaking(old: Api, new: Api) -> list[tuple[str, str]]:
    """(item path, what changed) for every change a user of `old` can trip over."""
    out = []
    for path, what in sorted(old.items.items()):
        # A type renamed with its old name kept as an alias is the same type in a signature.
        for alias, target in new.aliases.items():
            what = re.sub(rf"\b{re.escape(alias)}\b", target, what)
        if path not in new.items:
            out.append((path, f"removed ({what})"))
        elif new.items[path] != what:
            out.append((path, f"changed: {what}  ->  {new.items[path]}"))
    for path in sorted(set(new.items) - set(old.items)):
        owner, sep, _ = path.rpartition("." if "." in path.split("::")[-1] else "::")
        if sep == "." and owner in old.constructible:
            out.append((path, "a field added to a struct users build with a literal"))
        if sep == "::" and owner in old.exhaustive and new.items[path].startswith("variant"):
            out.append((path, "a variant added to an enum users match exhaustively"))
    for trait, required in sorted(new.trait_required.items()):
        for method in sorted(required - old.trait_required.get(trait, required)):
            out.append((f"{trait}::{method}", "a method every implementer must now write"))
    return out


def breaking_text(changes: Path, version: str, fragments: Path | None) -> str:
    """The Breaking section of `version` in CHANGES.md, with the Breaking sections of the news
    fragments the coordinator has not folded into it yet."""
    out = []
    if changes.is_file():
        text = changes.read_text(encoding="utf-8")
        section = re.search(rf"^##+ [^\n]*\b{re.escape(version)}\b[^\n]*\n(.*?)(?=^## |\Z)", text, re.M | re.S)
        if section:
            breaking = re.search(r"^###+ Breaking\s*\n(.*?)(?=^##|\Z)", section.group(1), re.M | re.S)
            out.append(breaking.group(1) if breaking else "")
    for fragment in sorted(fragments.glob("*.md")) if fragments and fragments.is_dir() else []:
        m = re.search(r"^###+ Breaking\s*\n(.*?)(?=^##|\Z)", fragment.read_text(encoding="utf-8"), re.M | re.S)
        if m:
            out.append(m.group(1))
    return "\n".join(out)


def covering(path: str, changes: list[tuple[str, str]]) -> str:
    """The item whose removal takes `path` with it (`reference` for `reference::Reference::new`,
    when `reference` is removed), else `path` itself: the entry names that one."""
    removed = {p for p, what in changes if what.startswith("removed")}
    parts = re.split(r"(::|\.| impl )", path)
    for end in range(1, len(parts), 2):
        ancestor = "".join(parts[:end])
        if ancestor in removed:
            return ancestor
    return path


def named(path: str, text: str) -> bool:
    """Whether `text` names the item: its own name (the last segment), as a word."""
    name = re.split(r"::|\.| impl ", path)[-1]
    return re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", text) is not None


def load(path: str) -> Api:
    try:
        return Api(json.loads(Path(path).read_text(encoding="utf-8")))
    except (OSError, ValueError, KeyError) as e:
        raise SystemExit(f"public_api.py: {path}: not rustdoc's JSON of a crate ({e})")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)
    listing = sub.add_parser("list")
    listing.add_argument("json")
    diff = sub.add_parser("diff")
    diff.add_argument("old")
    diff.add_argument("new")
    diff.add_argument("--changes", type=Path, required=True)
    diff.add_argument("--version", required=True)
    diff.add_argument("--fragments", type=Path)
    args = p.parse_args(argv)
    if args.command == "list":
        for path, what in sorted(load(args.json).items.items()):
            print(f"{path}: {what}")
        return 0
    changes = breaking(load(args.old), load(args.new))
    text = breaking_text(args.changes, args.version, args.fragments)
    unlisted = [(path, what) for path, what in changes if not named(covering(path, changes), text)]
    for path, what in unlisted:
        print(f"public API: {path}: {what}; not named under Breaking for {args.version}", file=sys.stderr)
    if unlisted:
        print(f"public_api.py: {len(unlisted)} of {len(changes)} breaking changes are not listed under Breaking "
              f"in {args.changes} (version {args.version}); list each, with what to do, or keep a deprecated alias",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
