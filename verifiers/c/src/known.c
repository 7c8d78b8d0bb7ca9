/* Known failures (CONTRACT.md, "The expectations file"): a listed vector that fails or errors is
 * XFAIL and does not fail the run; one that passes is STALE, and so is a listed id the suite does
 * not have, so that the list can only shrink. The messages are TEXT.md's, naming the entry as
 * FILE:LINE and, for an id the suite merged into another vector, the vector it became. */
#include <stdio.h>
#include <string.h>

#include "known.h"

/* FILE:LINE of an entry; "in code" for one of a list given in code without a file. */
static void where(const plcvec_known_failure *k, char *buf, size_t size)
{
    if (!k->file)
        snprintf(buf, size, "in code");
    else if (k->line > 0)
        snprintf(buf, size, "%s:%d", k->file, k->line);
    else
        snprintf(buf, size, "%s", k->file);
}

void plcvec_known_apply(plcvec_verdict *vd, const plcvec_known_failure *known, size_t n_known)
{
    for (size_t i = 0; i < n_known; i++) {
        const plcvec_known_failure *k = &known[i];
        if (!k->id || !vd->vector || strcmp(k->id, vd->vector->id) != 0)
            continue;
        char at[300];
        where(k, at, sizeof at);
        const char *reason = k->reason ? k->reason : "";
        if (vd->status == PLCVEC_FAIL || vd->status == PLCVEC_ERROR) {
            /* The differing fields stay: --verbose shows them, and the roll-up judges the known
             * failure under the other readings. */
            char was[sizeof vd->message];
            snprintf(was, sizeof was, "%s", vd->message);
            vd->status = PLCVEC_XFAIL;
            snprintf(vd->message, sizeof vd->message, "known failure (%.200s): %.150s%s%.150s", at, reason,
                     was[0] ? "; " : "", was);
        } else if (vd->status == PLCVEC_PASS) {
            vd->status = PLCVEC_STALE;
            snprintf(vd->message, sizeof vd->message,
                     "listed as a known failure (%.200s: %.200s) but it passes; remove it from the expectations file", at,
                     reason);
        }
        return;
    }
}

/* The name before 0.3.0, kept for programs built against it (the shared library exports it too). */
void plcvec_apply_known(plcvec_verdict *vd, const plcvec_known_failure *known, size_t n_known)
{
    plcvec_known_apply(vd, known, n_known);
}

void plcvec_known_unknown_message(const plcvec_known_failure *k, char *buf, size_t size)
{
    char at[300];
    where(k, at, sizeof at);
    const char *into = k->id ? plcvec_merged_into(k->id) : NULL;
    if (into)
        snprintf(buf, size, "listed as a known failure (%s) but the suite has no such vector: it was merged into %s; "
                            "list that id instead", at, into);
    else
        snprintf(buf, size, "listed as a known failure (%s) but the suite has no such vector; remove it from the "
                            "expectations file", at);
}
