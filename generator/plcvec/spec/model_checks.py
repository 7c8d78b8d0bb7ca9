"""Checks of a family's coverage model (`coverage.model`) that a JSON Schema cannot express: each
dimension's derivation exists for the family's kind and has the facts it derives from, and every
dimension and class named by a condition, a product or an exclusion is one the model has."""
import fnmatch

from plcvec.coverage.derive import DERIVATIONS, NEEDS


def check_model(fam):
    model = fam.doc.get("coverage", {}).get("model")
    if model is None:
        return
    where = ("coverage", "model")
    derive, needs = DERIVATIONS[fam.kind], NEEDS[fam.kind]
    classes = {}
    for i, d in enumerate(model["dimensions"]):
        at = where + ("dimensions", i)
        if d["id"] in classes:
            raise fam.error(at + ("id",), f"dimension {d['id']!r} is defined twice")
        if d["derive"] not in derive:
            raise fam.error(at + ("derive",), f"unknown derivation {d['derive']!r} for kind {fam.kind} "
                                              f"(known: {', '.join(sorted(derive))})")
        path = needs.get(d["derive"])
        if path and _lookup(fam.doc, path) is None:
            raise fam.error(at + ("derive",), f"derivation {d['derive']!r} needs {'.'.join(path)}, which this spec does not have")
        for gov, wanted in d.get("when", {}).items():
            if gov not in classes:
                raise fam.error(at + ("when", gov), f"dimension {d['id']!r} depends on {gov!r}, which is not a dimension defined before it")
            _known_classes(fam, at + ("when", gov), gov, classes[gov], wanted, patterns=False)
        classes[d["id"]] = derive[d["derive"]](fam.doc)
    for i, p in enumerate(model.get("products", [])):
        at = where + ("products", i)
        for j, dim in enumerate(p["dimensions"]):
            if dim not in classes:
                raise fam.error(at + ("dimensions", j), f"unknown dimension {dim!r} (known: {', '.join(classes)})")
        for dim, wanted in p.get("classes", {}).items():
            if dim not in p["dimensions"]:
                raise fam.error(at + ("classes", dim), f"{dim!r} is not one of this product's dimensions {p['dimensions']}")
            _known_classes(fam, at + ("classes", dim), dim, classes[dim], wanted, patterns=False)
    for i, e in enumerate(model.get("exclude", [])):
        at = where + ("exclude", i)
        for dim, wanted in e["classes"].items():
            if dim not in classes:
                raise fam.error(at + ("classes", dim), f"unknown dimension {dim!r} (known: {', '.join(classes)})")
            _known_classes(fam, at + ("classes", dim), dim, classes[dim], wanted, patterns=True)


def _known_classes(fam, at, dim, known, wanted, patterns):
    for w in [wanted] if isinstance(wanted, str) else wanted:
        hit = [c for c in known if fnmatch.fnmatchcase(c, w)] if patterns else [c for c in known if c == w]
        if not hit:
            raise fam.error(at, f"{w!r} names no class of dimension {dim!r} (its classes: {', '.join(known)})")


def _lookup(doc, path):
    node = doc
    for key in path:
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    return node
