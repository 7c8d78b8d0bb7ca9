"""A family's instructions by the names the manual gives them: the vectors', the regression cases' and the
review's names. A masked-compare family writes its instructions as forms x conditions and a naming
pattern; the other kinds list them.
"""


def instruction_list(fam):
    """Every instruction of a family, with the names the manual gives it."""
    doc = fam.doc
    if fam.kind == "masked_compare":
        ins, naming = doc["instructions"], doc["instructions"]["naming"]
        out = []
        for form in ins["forms"]:
            for cond in ins["conditions"]:
                names = {"form_mnemonic": form["mnemonic"], "symbol": cond["symbol"],
                         "form_st": form["st"], "condition_st": cond["st"]}
                item = {"name": naming["ladder"].format(**names), "st": naming["st"].format(**names),
                        "form": form, "symbol": cond["symbol"], "naming_clause": naming["clause"]}
                if "function_code" in cond:
                    item["function_code"] = cond["function_code"]
                out.append(item)
        return out
    return [dict(i, name=i["mnemonic"]) for i in doc["instructions"]]
