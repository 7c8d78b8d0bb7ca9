/* Judging one vector: the implementation runs it inside the guards (guard.c), its answer is
 * compared with the expectation of the alternatives followed (compare.c), and the verdict says
 * which interpretations decide a differing field and under which offered expectations the same
 * answer would pass (what the roll-up by reading is built on). */
#include <stdlib.h>
#include <string.h>

#include "choices.h"
#include "compare.h"
#include "expect.h"
#include "guard.h"
#include "implementation.h"
#include "judge.h"
#include "settings.h"

struct plcvec_judge {
    plcvec_impl impl;
    uint8_t alternative[PLCVEC_INTERPRETATION_COUNT];
    plcvec_out out;
    plcvec_problems problems;
    plcvec_states states;
    plcvec_verdict verdict;
};

plcvec_judge *plcvec_judge_new(const plcvec_impl *impl, char *err, size_t errlen)
{
    if (!impl || !impl->run) {
        snprintf(err, errlen, "the implementation has no run function");
        return NULL;
    }
    long bound = plcvec_settings_timeout_ms(err, errlen);
    if (bound < 0)
        return NULL;
    plcvec_judge *j = calloc(1, sizeof *j);
    if (!j) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (plcvec_choices_resolve(impl, j->alternative, err, errlen) != 0) {
        free(j);
        return NULL;
    }
    /* The watchdog, the crash handlers and the exit guard: once per process. */
    plcvec_guard_install(bound);
    j->impl = *impl;
    return j;
}

void plcvec_judge_free(plcvec_judge *j)
{
    if (!j)
        return;
    plcvec_out_release(&j->out);
    free(j->problems.items);
    free(j->states.state);
    free(j->states.before);
    free(j);
}

int plcvec_judge_alternative(const plcvec_judge *j, int interpretation)
{
    return interpretation >= 0 && interpretation < PLCVEC_INTERPRETATION_COUNT ? j->alternative[interpretation] : -1;
}

const plcvec_impl *plcvec_judge_impl(const plcvec_judge *j)
{
    return &j->impl;
}

const plcvec_expect *plcvec_expected(const plcvec_judge *j, const plcvec_vector *v, size_t step)
{
    if (step >= v->n_steps)
        return NULL;
    const plcvec_alternative *entry = plcvec_expect_entry(v, j->alternative);
    if (entry == &plcvec_expect_missing || (entry && step >= entry->n_expect))
        return NULL;
    return plcvec_expect_step(v, entry, step);
}

/* The verdict without an answer to compare: a skip, or an error with its message. */
static const plcvec_verdict *verdict_of(plcvec_verdict *vd, plcvec_status status, const char *prefix,
                                        const char *message)
{
    vd->status = status;
    snprintf(vd->message, sizeof vd->message, "%s%.300s", prefix, message);
    return vd;
}

/* Under which offered expectations (bit o: 0 the vector's own, o the entry alternatives[o - 1])
 * the answer that failed would pass. */
static uint64_t offered_passes(plcvec_judge *j, const plcvec_vector *v)
{
    uint64_t passes = 0;
    size_t kept = j->problems.n;
    for (size_t o = 0; o <= v->n_alternatives && o < 64; o++) {
        const plcvec_alternative *entry = o == 0 ? NULL : &v->alternatives[o - 1];
        if (entry && entry->n_expect != v->n_steps)
            continue;
        if (plcvec_compare(v, entry, &j->out, j->impl.cpu_writes, &j->states, &j->problems) == 0 && j->problems.n == kept)
            passes |= UINT64_C(1) << o;
        j->problems.n = kept;
    }
    return passes;
}

/* The answer in j->out against the expectation followed: the problems in TEXT.md's order, each with
 * the interpretations that decide it, and the verdict's `judged by`. */
static const plcvec_verdict *judge_answer(plcvec_judge *j, const plcvec_vector *v, const plcvec_alternative *entry)
{
    plcvec_verdict *vd = &j->verdict;
    if (plcvec_compare(v, entry, &j->out, j->impl.cpu_writes, &j->states, &j->problems) != 0)
        return verdict_of(vd, PLCVEC_ERROR, "", "out of memory");
    if (!j->problems.n) {
        vd->status = PLCVEC_PASS;   /* the common case: nothing more to work out */
        return vd;
    }
    vd->offered_passes = offered_passes(j, v);
    if (j->problems.n > 1)
        qsort(j->problems.items, j->problems.n, sizeof *j->problems.items, plcvec_problem_order);
    uint64_t which = 0;
    for (size_t i = 0; i < j->problems.n; i++) {
        plcvec_problem *p = &j->problems.items[i];
        if (p->device != -2 && !(p->device == -1 && p->name[0]))
            p->deciders = plcvec_choices_deciders(v, j->alternative, entry, p->step, p->device);
        which |= p->deciders;
    }
    vd->n_choices = plcvec_choices_judged_by(which, j->alternative, vd->choices);
    vd->problems = j->problems.items;
    vd->n_problems = j->problems.n;
    vd->status = PLCVEC_FAIL;
    return vd;
}

const plcvec_verdict *plcvec_judge_vector(plcvec_judge *j, const plcvec_vector *v)
{
    plcvec_verdict *vd = &j->verdict;
    plcvec_out *out = &j->out;
    /* What the previous vector's verdict set (not the whole struct: this runs for every vector). */
    vd->vector = v;
    vd->message[0] = '\0';
    vd->problems = NULL;
    vd->n_problems = vd->n_choices = 0;
    vd->applied = NULL;
    vd->offered_passes = 0;
    j->problems.n = 0;
    const plcvec_alternative *entry = plcvec_expect_entry(v, j->alternative);
    if (entry == &plcvec_expect_missing || (entry && entry->n_expect != v->n_steps))
        return verdict_of(vd, PLCVEC_ERROR, "",
                          "the vector lists no expectation for the alternatives it was judged by (is the suite damaged?)");
    vd->applied = entry;        /* also for a skip or an error: the block names what it leaves unjudged */
    /* supports() is the implementation's code too: one guarded stretch for both calls. */
    plcvec_guard_enter(v->id);
    if (j->impl.supports && !j->impl.supports(j->impl.ctx, v->instruction)) {
        plcvec_guard_leave();
        return verdict_of(vd, PLCVEC_SKIP, "the implementation does not support ", plcvec_instruction_names[v->instruction]);
    }
    plcvec_out_reset(out);
    int rc = j->impl.run(j->impl.ctx, v, out);
    plcvec_guard_leave();
    if (out->status == PLCVEC_SKIPPED || rc == PLCVEC_SKIPPED)
        return verdict_of(vd, PLCVEC_SKIP, "", out->message[0] ? out->message : "skipped");
    if (out->status == PLCVEC_FAILED || rc != PLCVEC_RAN || out->overflow)
        return verdict_of(vd, PLCVEC_ERROR, "the implementation reported an error: ",
                          out->message[0] ? out->message : out->overflow ? plcvec_out_overflow_message
                                                                         : "run() returned nonzero");
    return judge_answer(j, v, entry);
}
