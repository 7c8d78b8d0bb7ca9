"""Regression cases (spec/regressions/<family>.yaml) as vectors: the inputs are the case's, the
expectations the engine's, the id a hash of the inputs (`<family>/<instruction>/regression/<hash>`)."""
from plcvec.cases.build import GeneratorBug
from plcvec.spec.regressions import TAG, case_key


def regression_cases(fam, builder):
    regs = fam.regressions
    for i, case in enumerate(regs.cases if regs else []):
        try:
            yield builder.vector(case["instruction"], case_key(case), tags=[TAG], description=case["note"],
                                 operands=case["operands"], devices=case["devices"], steps=case["steps"],
                                 scratch=case.get("scratch", ()))
        except GeneratorBug as exc:
            raise regs.error((i,), f"this case cannot be run: {exc}") from None
        except KeyError as exc:
            raise regs.error((i, "devices"), f"this case cannot be run: the instruction reads {exc.args[0]}, "
                                             "which is not among its devices") from None
