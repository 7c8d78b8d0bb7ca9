/* The closing lines of a run's text (TEXT.md, "Skips by reason", "The summary lines"). */
#ifndef PLCVEC_REPORTS_H
#define PLCVEC_REPORTS_H

#include <stdio.h>

#include "plcvec/plcvec.h"

/* `SKIPPED s of n vectors (p%):` and one line per reason, most vectors first. */
void plcvec_skipped_lines(FILE *log, const char *const *reasons, size_t n_skipped, size_t selected);
/* Why a run without failures did not pass (exit 5). */
void plcvec_not_passed_line(FILE *log, const plcvec_summary *sum);
/* An empty line, the header, the interpretations followed (of `families`, bit f), the declared CPU
 * writes and the totals with the run's seconds. */
void plcvec_summary_lines(FILE *log, const plcvec_judge *j, uint32_t families, const plcvec_summary *sum,
                          double seconds);

#endif
