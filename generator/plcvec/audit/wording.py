"""How findings write values, cells and lists, close to the way the manual prints them."""


def listing(items):
    """"a", "a and b", "a, b, and c" (the manual's own serial comma)."""
    items = [str(i) for i in items]
    if len(items) <= 2:
        return " and ".join(items)
    return ", ".join(items[:-1]) + ", and " + items[-1]


def field_values(values, fields):
    """"year 2006, month 2, day 30": every field in the spec's order (most significant first)."""
    return ", ".join(f"{f['name']} {values[f['name']]}" for f in fields if f["name"] in values)


def clock(values, fields):
    """A clock value as the manual writes a time: the top field as it is, the others with two digits (14:20:50)."""
    parts = [values[f["name"]] for f in fields]
    return ":".join([str(parts[0])] + [f"{p:02d}" for p in parts[1:]])


def on_off(state):
    return "mixed (its devices disagree)" if state is None else ("on" if state else "off")


def contact(state, legend):
    """A continuity result in the table's own symbols (○ / ×) when the spec records its legend."""
    if legend:
        return legend["continuity"] if state else legend["non_continuity"]
    return "continuity" if state else "non-continuity"


def words(operand, offsets):
    """"(s1)+2 and (s1)+2": word offsets of an operand as the manual names them."""
    if not offsets:
        return "no word"
    return listing(f"({operand})" if k == 0 else f"({operand})+{k}" for k in offsets)


def cell_sets(sets):
    """"{Day, A<B; Day, B<C}" for each set of cell names."""
    return ", ".join("{" + "; ".join(s) + "}" for s in sets)
