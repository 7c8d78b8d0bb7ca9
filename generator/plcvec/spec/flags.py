"""The flags, error devices and error registers of a family, by the name the reference tables give them.

One list serves the reference tables (`plcvec export`) and the interpretation alternatives that leave
devices unjudged (`unjudged.flags` names rows of it), so a name means the same devices in both.
"""


def flag_groups(doc) -> list[dict]:
    """Every flag, error device and error register the family's vectors may list, with its meaning:
    [{"name", "devices", "clause"}] in the order the tables show them."""
    out = []
    flags = doc.get("flags") or {}
    if doc["kind"] == "clock_add":
        for name in ("carry", "zero"):
            out.append({"name": name, "devices": flags[name]["devices"], "clause": flags[name]["clause"]})
        out.append({"name": "error code", "devices": doc["errors"]["registers"]["devices"],
                    "clause": doc["errors"]["registers"]["clause"]})
    elif doc["kind"] == "masked_compare":
        error = doc["validity"]["error"]
        out.append({"name": "error", "devices": [error["device"]], "clause": error.get("clause", "")})
        for symbol, device in (flags.get("devices") or {}).items():
            out.append({"name": f"comparison {symbol}", "devices": [device], "clause": flags["clause"]})
    elif doc["kind"] == "hour_meter":
        out.append({"name": "error", "devices": [doc["error"]["device"]], "clause": doc["error"]["clause"]})
    return out
