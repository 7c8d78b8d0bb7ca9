/* The roll-up by reading (TEXT.md, "The roll-up by reading"), printed after the failure blocks. */
#ifndef PLCVEC_ROLLUP_H
#define PLCVEC_ROLLUP_H

#include <stdio.h>

#include "infer.h"

/* How the `declare:` lines are written: as a C implementer declares (TEXT.md's table:
 * {PLCVEC_INTERP_X, PLCVEC_X_ALT}, ...), or as `plcvec verify --choose` takes them (the shared
 * cases' expected text, and the text compared with plcvec verify's). */
typedef enum plcvec_declaration_form { PLCVEC_DECLARE_C, PLCVEC_DECLARE_CHOOSE } plcvec_declaration_form;
void plcvec_rollup_declaration_form(plcvec_declaration_form form);
/* The declaration of the alternatives choice[i] of the interpretations of `which` (bit i), sorted
 * by id, in the form in use (TEXT.md, "The declaration in each runner"). Returns the length it
 * needed (truncated to size). */
size_t plcvec_declaration_text(char *buf, size_t size, uint64_t which, const uint8_t *choice);

/* The roll-up of a run's vectors: READINGS (failing vectors another alternative explains, grouped
 * by their smallest change, each group marked partial where failures of its families stay
 * unexplained), NOT EXPLAINED (the rest, by the clauses they cite), KNOWN FAILURES (known failures
 * another alternative explains, and the file to remove them from). `known` is where the known
 * failures are listed. -1 when out of memory. */
int plcvec_rollup_lines(FILE *log, plcvec_judged *judged, size_t n, const uint8_t *followed,
                        const plcvec_known_failure *known, size_t n_known);

#endif
