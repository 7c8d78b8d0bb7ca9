/* Selection's lists as the command line and the PLCVEC_* variables give them (selection.c). */
#ifndef PLCVEC_SELECTION_H
#define PLCVEC_SELECTION_H

#include "plcvec/plcvec.h"

enum { PLCVEC_F_FAMILY, PLCVEC_F_INSTRUCTION, PLCVEC_F_TAG, PLCVEC_F_ID, PLCVEC_F_INTERPRETATION, PLCVEC_N_FILTERS };
extern const char *const plcvec_filter_options[PLCVEC_N_FILTERS];     /* "--family", ... */
extern const char *const plcvec_filter_variables[PLCVEC_N_FILTERS];   /* "PLCVEC_FAMILY", ... */

/* The names of each filter, from options or variables (a variable's copy is split in place). */
typedef struct plcvec_filters {
    const char **lists[PLCVEC_N_FILTERS];
    size_t counts[PLCVEC_N_FILTERS], caps[PLCVEC_N_FILTERS];
    char *copies[PLCVEC_N_FILTERS];
} plcvec_filters;

int plcvec_filters_push(plcvec_filters *f, int filter, const char *name);
/* The comma-separated names of the filter's variable, when set; -1 and err on an empty name. */
int plcvec_filters_from_environment(plcvec_filters *f, int filter, char *err, size_t errlen);
/* The lists into a selection (which then points into f). */
void plcvec_filters_select(const plcvec_filters *f, plcvec_selection *sel);
void plcvec_filters_free(plcvec_filters *f);
/* K/N into sel's shard; -1 and err naming `what` (the option or the variable) otherwise. */
int plcvec_parse_shard(const char *what, const char *text, plcvec_selection *sel, char *err, size_t errlen);

#endif
