/* What the rest of the library reads of a judge (plcvec_judge, judge.c). */
#ifndef PLCVEC_JUDGE_H
#define PLCVEC_JUDGE_H

#include "plcvec/plcvec.h"

/* The implementation the judge runs, with its declarations and its CPU writes. */
const plcvec_impl *plcvec_judge_impl(const plcvec_judge *j);

#endif
