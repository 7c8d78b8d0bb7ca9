"""How a contact-type instruction combines with the logic before it (LD starts, AND series, OR parallel)."""


def skipped(logic, rlo_in, knobs):
    """The result when the form is not executed at all for this preceding logic state, else None."""
    if logic == "and" and not rlo_in and knobs["and_skip_when_off"]:
        return False
    if logic == "or" and rlo_in and knobs["or_skip_when_on"]:
        return True
    return None


def combine(logic, rlo_in, contact):
    if logic == "load":
        return contact
    if logic == "and":
        return bool(rlo_in) and contact
    return bool(rlo_in) or contact
