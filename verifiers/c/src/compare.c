/* Comparing what an implementation reported with what a vector expects (CONTRACT.md, "Comparing"):
 * the contact result and every judged device after every step, with its type; listed devices a
 * step must leave alone; no write outside the vector. */
#include <string.h>

#include "compare.h"
#include "expect.h"
#include "implementation.h"

static plcvec_problem *problem(plcvec_problems *list, int step, int device)
{
    if (!plcvec_grow((void **)&list->items, &list->cap, list->n + 1, sizeof *list->items))
        return NULL;
    plcvec_problem *p = &list->items[list->n++];
    memset(p, 0, sizeof *p);
    p->step = step;
    p->device = device;
    return p;
}

static int declared_cpu_write(const char *const *cpu_writes, const char *name)
{
    for (const char *const *d = cpu_writes; d && *d; d++)
        if (strcmp(*d, name) == 0)
            return 1;
    return 0;
}

/* What the implementation held of p's device before step s: the vector's value for step 0; after,
 * its own report of step s-1 with step s's `set` written over it. */
static void held_before(const plcvec_vector *v, const plcvec_out *out, int s, const plcvec_cell *vector_before,
                        plcvec_problem *p)
{
    if (s == 0) {
        if (vector_before)
            p->has_held = 1, p->held_type = vector_before->type, p->held = vector_before->value;
        return;
    }
    const plcvec_step *st = &v->steps[s];
    for (size_t i = 0; i < st->n_set; i++)
        if (st->set[i].device == p->device) {
            p->has_held = 1, p->held_type = st->set[i].type, p->held = st->set[i].value;
            return;
        }
    size_t lo, hi;
    plcvec_out_span(out, (size_t)s - 1, &lo, &hi);
    for (size_t k = lo; k < hi; k++)
        if (out->cells[k].device == p->device) {
            p->has_held = 1, p->held_type = out->cells[k].type, p->held = out->cells[k].value;
            return;
        }
}

/* The fast path of a step that passes: the same devices in the same order with the same values
 * and types (what an implementation reporting its image in the vector's order gives). */
static int same_cells(const plcvec_vector *v, const plcvec_out *out, size_t lo, size_t hi, const plcvec_cell *state,
                      size_t n_state)
{
    size_t i = 0;
    int scratch = v->n_scratch != 0;   /* most vectors have none: no search per cell */
    for (size_t k = lo; k < hi; k++) {
        const plcvec_reported *r = &out->cells[k];
        if (scratch && r->device >= 0 && plcvec_expect_scratch(v, r->device))
            continue;
        if (i >= n_state || r->device != state[i].device || r->type != state[i].type || r->value != state[i].value)
            return 0;
        i++;
    }
    return i == n_state;
}

/* A listed device (state[i]) against what was reported for it in [lo, hi); 0, or -1 out of memory. */
static int compare_listed(const plcvec_vector *v, const plcvec_out *out, int s, size_t lo, size_t hi,
                          const plcvec_cell *want, const plcvec_cell *before, size_t n_before, plcvec_problems *problems)
{
    const plcvec_reported *got = NULL, *again = NULL;
    for (size_t k = lo; k < hi && !again; k++)
        if (out->cells[k].device == want->device) {
            if (!got)
                got = &out->cells[k];
            else if (out->cells[k].type != got->type || out->cells[k].value != got->value)
                again = &out->cells[k];     /* one device, two values: neither can be believed */
        }
    if (!again && got && got->type == want->type && got->value == want->value)
        return 0;
    plcvec_problem *p = problem(problems, s, want->device);
    if (!p)
        return -1;
    p->has_expected = 1, p->expected_type = want->type, p->expected = want->value;
    if (got)
        p->has_actual = 1, p->actual_type = got->type, p->actual = got->value;
    if (again) {
        p->twice = 1, p->second_type = again->type, p->second = again->value;
        return 0;
    }
    const plcvec_cell *b = plcvec_state_cell(before, n_before, want->device);
    if (b) {
        p->has_before = 1, p->before_type = b->type, p->before = b->value;
        p->keep = b->type == want->type && b->value == want->value;
    }
    held_before(v, out, s, b, p);
    return 0;
}

/* Step s: what was reported with the expected state after it (devices `entry` leaves unjudged are
 * not compared, and being in the vector, writing them is no stray write). */
static int compare_step(const plcvec_vector *v, const plcvec_alternative *entry, const plcvec_out *out, int s,
                        const plcvec_states *st, size_t n_state, const char *const *cpu_writes,
                        plcvec_problems *problems)
{
    size_t lo, hi;
    plcvec_out_span(out, (size_t)s, &lo, &hi);
    if (same_cells(v, out, lo, hi, st->state, n_state))
        return 0;
    /* The state before the step, which only a differing field names: worked out here rather than
     * copied at every step of every vector. */
    size_t n_before = plcvec_expect_before(v, entry, (size_t)s, st->before);
    for (size_t i = 0; i < n_state; i++)
        if (!plcvec_expect_unjudged(entry, st->state[i].device) &&
            compare_listed(v, out, s, lo, hi, &st->state[i], st->before, n_before, problems) != 0)
            return -1;
    for (size_t k = lo; k < hi; k++) {     /* a write outside the vector */
        const plcvec_reported *r = &out->cells[k];
        if (r->device >= 0 && (plcvec_expect_scratch(v, r->device) || plcvec_state_cell(st->state, n_state, r->device)))
            continue;
        const char *name = r->device >= 0 ? plcvec_device(r->device)->name : r->name;
        if (declared_cpu_write(cpu_writes, name))
            continue;   /* a device the CPU writes on its own account, declared, and not in the vector */
        plcvec_problem *p = problem(problems, s, r->device);
        if (!p)
            return -1;
        snprintf(p->name, sizeof p->name, "%s", name);
        p->has_actual = 1, p->actual_type = r->type, p->actual = r->value;
    }
    return 0;
}

static int compare_result(const plcvec_expect *x, const plcvec_out *out, int s, plcvec_problems *problems)
{
    if (x->result == PLCVEC_NONE || out->results[s] == x->result)
        return 0;
    plcvec_problem *p = problem(problems, s, -1);
    if (!p)
        return -1;
    p->has_expected = 1, p->expected_type = PLCVEC_BIT, p->expected = (uint32_t)x->result;
    p->has_actual = out->results[s] != PLCVEC_NONE;
    p->actual_type = PLCVEC_BIT, p->actual = (uint32_t)(out->results[s] == 1);
    return 0;
}

int plcvec_compare(const plcvec_vector *v, const plcvec_alternative *entry, const plcvec_out *out,
                   const char *const *cpu_writes, plcvec_states *st, plcvec_problems *problems)
{
    if (out->n_steps != v->n_steps) {
        plcvec_problem *p = problem(problems, -1, -2);
        if (!p)
            return -1;
        p->has_expected = p->has_actual = 1;
        p->expected = v->n_steps;
        p->actual = (uint32_t)out->n_steps;
        return 0;
    }
    size_t need = plcvec_expect_capacity(v, entry), cap = st->cap;
    if (!plcvec_grow((void **)&st->state, &cap, need, sizeof *st->state) ||
        !plcvec_grow((void **)&st->before, &st->cap, need, sizeof *st->before))
        return -1;
    /* The expected state, step by step: before step s (its `set` written over the state after
     * step s-1), then after it. */
    size_t n = plcvec_expect_before(v, entry, 0, st->state);
    for (size_t s = 0; s < v->n_steps; s++) {
        const plcvec_step *step = &v->steps[s];
        for (size_t i = 0; s > 0 && i < step->n_set; i++)
            if (!plcvec_expect_scratch(v, step->set[i].device))
                plcvec_state_put(st->state, &n, &step->set[i]);
        const plcvec_expect *x = plcvec_expect_step(v, entry, s);
        for (size_t i = 0; i < x->n_devices; i++)
            if (!plcvec_expect_scratch(v, x->devices[i].device))
                plcvec_state_put(st->state, &n, &x->devices[i]);
        if (compare_result(x, out, (int)s, problems) != 0 ||
            compare_step(v, entry, out, (int)s, st, n, cpu_writes, problems) != 0)
            return -1;
    }
    return 0;
}

static const char *problem_name(const plcvec_problem *p)
{
    return p->name[0] ? p->name : p->device >= 0 ? plcvec_device(p->device)->name : "";
}

int plcvec_problem_order(const void *a, const void *b)
{
    const plcvec_problem *x = a, *y = b;
    if (x->step != y->step)
        return x->step < y->step ? -1 : 1;
    int x_result = x->device == -1 && !x->name[0], y_result = y->device == -1 && !y->name[0];
    if (x_result != y_result)
        return x_result ? -1 : 1;
    return strcmp(problem_name(x), problem_name(y));
}
