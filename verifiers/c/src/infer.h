/* The inference (TEXT.md, "The inference"): the alternatives a run's answers follow, found from the
 * vectors and the answers alone, as `plcvec verify --infer` finds them. */
#ifndef PLCVEC_INFER_H
#define PLCVEC_INFER_H

#include "plcvec/plcvec.h"

/* What the answer to a vector was, for the inference: none (an error, a skip), or judged. */
enum { PLCVEC_ANSWER_NONE, PLCVEC_ANSWER_PASSED, PLCVEC_ANSWER_FAILED };

/* One vector of a run. */
typedef struct plcvec_judged {
    const plcvec_vector *v;
    uint8_t status;             /* the verdict's, known failures applied */
    uint8_t answer;             /* PLCVEC_ANSWER_*: a pass, a fail; an xfail whose answer failed counts as failed */
    uint64_t passes;            /* the offered expectations (bit o: plcvec_verdict.offered_passes) it passes under */
} plcvec_judged;

typedef struct plcvec_inference {
    uint8_t followed[PLCVEC_INTERPRETATION_COUNT];  /* declared, else the default */
    uint8_t choice[PLCVEC_INTERPRETATION_COUNT];    /* what explains the most judged vectors */
    size_t broken;              /* vectors that pass now and would fail under the choice */
} plcvec_inference;

/* The choice over `judged` (whose `passes` of the vectors that passed it fills in). -1 when out of
 * memory. */
int plcvec_infer(plcvec_judged *judged, size_t n, const uint8_t *followed, plcvec_inference *inf);
/* Whether the choice explains a failing vector or a known failure: its answer failed and passes
 * under the choice (an error or a vector not run is never explained). */
int plcvec_explained(const plcvec_inference *inf, const plcvec_judged *r);
/* Whether r passes now and would fail under the choice (the inference's `broken`). */
int plcvec_broken(const plcvec_inference *inf, const plcvec_judged *r);
/* The smallest change that explains r (the interpretations, sorted by id, into `out`); its size. */
int plcvec_smallest_change(const plcvec_inference *inf, const plcvec_judged *r, int *out);

#endif
