/* Running one vector through an implementation and judging what it reports (CONTRACT.md,
 * "Comparing"): the contact result and every listed device after every step, with its type;
 * listed devices a step must leave alone; no write outside the vector. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "guard.h"
#include "table.h"

const char *const plcvec_status_names[] = {"pass", "fail", "error", "skip", "xfail", "stale"};

enum { RAN = 0, SKIPPED = 1, FAILED = 2 };

typedef plcvec_reported reported;

struct plcvec_out {
    int *results;               /* per reported step */
    size_t *first;              /* per reported step: index of its first cell */
    size_t n_steps, cap_steps;
    reported *cells;
    size_t n_cells, cap_cells;
    int status;
    int overflow;               /* out of memory while recording: reported as an error */
    char message[256];
};

struct plcvec_judge {
    plcvec_impl impl;
    uint8_t alternative[PLCVEC_INTERPRETATION_COUNT];
    plcvec_out out;
    plcvec_problem *problems;
    size_t n_problems, cap_problems;
    plcvec_cell *state, *before;
    size_t cap_state;
    plcvec_verdict verdict;
};

/* ---- what the implementation reports ------------------------------------------------------ */

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 1;
    size_t n = *cap ? *cap * 2 : 64;
    while (n < need)
        n *= 2;
    void *q = realloc(*p, n * size);
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

void plcvec_out_step(plcvec_out *out, int result)
{
    size_t cap = out->cap_steps;
    if (!grow((void **)&out->results, &cap, out->n_steps + 1, sizeof *out->results) ||
        !grow((void **)&out->first, &out->cap_steps, out->n_steps + 1, sizeof *out->first)) {
        out->overflow = 1;
        return;
    }
    out->results[out->n_steps] = result == 0 || result == 1 ? result : PLCVEC_NONE;
    out->first[out->n_steps++] = out->n_cells;
}

static reported *add_cell(plcvec_out *out, plcvec_type type, unsigned value)
{
    if (out->n_steps == 0 || !grow((void **)&out->cells, &out->cap_cells, out->n_cells + 1, sizeof *out->cells)) {
        out->overflow = 1;      /* a device before any plcvec_out_step(), or out of memory */
        return NULL;
    }
    reported *c = &out->cells[out->n_cells++];
    c->type = (uint8_t)type;
    c->value = value;
    c->name[0] = '\0';
    return c;
}

void plcvec_out_device(plcvec_out *out, int device, plcvec_type type, unsigned value)
{
    if (!plcvec_device(device)) {
        out->overflow = 1;
        return;
    }
    reported *c = add_cell(out, type, value);
    if (c)
        c->device = device;
}

void plcvec_out_named(plcvec_out *out, const char *device, plcvec_type type, unsigned value)
{
    int id = plcvec_device_named(device);
    if (id >= 0) {
        plcvec_out_device(out, id, type, value);
        return;
    }
    reported *c = add_cell(out, type, value);
    if (c) {
        c->device = -1;
        snprintf(c->name, sizeof c->name, "%s", device);
    }
}

int plcvec_out_skip(plcvec_out *out, const char *reason)
{
    out->status = SKIPPED;
    snprintf(out->message, sizeof out->message, "%s", reason ? reason : "skipped");
    return SKIPPED;
}

int plcvec_out_error(plcvec_out *out, const char *message)
{
    out->status = FAILED;
    snprintf(out->message, sizeof out->message, "%s", message ? message : "error");
    return FAILED;
}

plcvec_out *plcvec_out_new(void)
{
    return calloc(1, sizeof(plcvec_out));
}

void plcvec_out_free(plcvec_out *out)
{
    if (!out)
        return;
    free(out->results);
    free(out->first);
    free(out->cells);
    free(out);
}

void plcvec_out_reset(plcvec_out *out)
{
    out->n_steps = out->n_cells = 0;
    out->status = RAN;
    out->overflow = 0;
    out->message[0] = '\0';
}

int plcvec_out_status(const plcvec_out *out, const char **message)
{
    if (message)
        *message = out->message[0] ? out->message
                   : out->overflow ? "a device reported before plcvec_out_step(), an unknown device id, or out of memory"
                                   : "";
    return out->overflow && out->status == RAN ? FAILED : out->status;
}

size_t plcvec_out_step_count(const plcvec_out *out)
{
    return out->n_steps;
}

int plcvec_out_result(const plcvec_out *out, size_t step)
{
    return step < out->n_steps ? out->results[step] : PLCVEC_NONE;
}

const plcvec_reported *plcvec_out_cells(const plcvec_out *out, size_t step, size_t *n)
{
    if (step >= out->n_steps) {
        *n = 0;
        return NULL;
    }
    size_t hi = step + 1 < out->n_steps ? out->first[step + 1] : out->n_cells;
    *n = hi - out->first[step];
    return out->cells + out->first[step];
}

/* ---- the judge ---------------------------------------------------------------------------- */

plcvec_judge *plcvec_judge_new(const plcvec_impl *impl, char *err, size_t errlen)
{
    if (!impl || !impl->run) {
        snprintf(err, errlen, "the implementation has no run function");
        return NULL;
    }
    plcvec_judge *j = calloc(1, sizeof *j);
    if (!j) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    long bound = plcvec_timeout_ms(err, errlen);
    if (bound < 0) {
        free(j);
        return NULL;
    }
    /* The watchdog, the crash handlers and the exit guard: once per process. */
    plcvec_guard_install(bound);
    j->impl = *impl;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        j->alternative[i] = plcvec_interpretations[i].default_alternative;
    for (size_t c = 0; c < impl->n_choices; c++) {
        const plcvec_choice *ch = &impl->choices[c];
        if (ch->interpretation >= PLCVEC_INTERPRETATION_COUNT ||
            ch->alternative >= plcvec_interpretations[ch->interpretation].n_alternatives) {
            snprintf(err, errlen, "%s declares interpretation %u alternative %u, which the suite does not have",
                     impl->name ? impl->name : "the implementation", ch->interpretation, ch->alternative);
            free(j);
            return NULL;
        }
        j->alternative[ch->interpretation] = ch->alternative;
    }
    return j;
}

void plcvec_judge_free(plcvec_judge *j)
{
    if (!j)
        return;
    free(j->out.results);
    free(j->out.first);
    free(j->out.cells);
    free(j->problems);
    free(j->state);
    free(j->before);
    free(j);
}

int plcvec_judge_alternative(const plcvec_judge *j, int interpretation)
{
    return interpretation >= 0 && interpretation < PLCVEC_INTERPRETATION_COUNT ? j->alternative[interpretation] : -1;
}

/* The alternatives entry that applies, NULL for the vector's own expectations, or `missing`. */
static const plcvec_alternative missing;

static const plcvec_alternative *applicable(const plcvec_judge *j, const plcvec_vector *v)
{
    int all_default = 1;
    for (size_t i = 0; i < v->n_interpretations; i++) {
        uint8_t interp = v->interpretations[i];
        if (j->alternative[interp] != plcvec_interpretations[interp].default_alternative)
            all_default = 0;
    }
    if (all_default)
        return NULL;
    for (size_t a = 0; a < v->n_alternatives; a++) {
        const plcvec_alternative *alt = &v->alternatives[a];
        int match = 1;
        for (size_t i = 0; i < v->n_interpretations && match; i++) {
            uint8_t interp = v->interpretations[i];
            int found = 0;
            for (size_t c = 0; c < alt->n_choices; c++)
                if (alt->choices[c].interpretation == interp)
                    found = alt->choices[c].alternative == j->alternative[interp];
            match = found;
        }
        if (match)
            return alt;
    }
    return &missing;
}

const plcvec_expect *plcvec_expected(const plcvec_judge *j, const plcvec_vector *v, size_t step)
{
    if (step >= v->n_steps)
        return NULL;
    const plcvec_alternative *alt = applicable(j, v);
    if (alt == &missing || (alt && step >= alt->n_expect))
        return NULL;
    return alt ? &alt->expect[step] : &v->steps[step].expect;
}

static int is_scratch(const plcvec_vector *v, int device)
{
    for (size_t i = 0; i < v->n_scratch; i++)
        if (v->scratch[i] == device)
            return 1;
    return 0;
}

static plcvec_problem *problem(plcvec_judge *j, int step, int device)
{
    if (!grow((void **)&j->problems, &j->cap_problems, j->n_problems + 1, sizeof *j->problems))
        return NULL;
    plcvec_problem *p = &j->problems[j->n_problems++];
    memset(p, 0, sizeof *p);
    p->step = step;
    p->device = device;
    return p;
}

static void put(plcvec_cell *state, size_t *n, const plcvec_cell *c)
{
    for (size_t i = 0; i < *n; i++)
        if (state[i].device == c->device) {
            state[i] = *c;
            return;
        }
    state[(*n)++] = *c;
}

static const plcvec_cell *cell_of(const plcvec_cell *state, size_t n, int device)
{
    for (size_t i = 0; i < n; i++)
        if (state[i].device == device)
            return &state[i];
    return NULL;
}

static int cpu_writes(const plcvec_judge *j, const char *name)
{
    for (const char *const *d = j->impl.cpu_writes; d && *d; d++)
        if (strcmp(*d, name) == 0)
            return 1;
    return 0;
}

/* What the implementation held of p's device before step s: the vector's value for step 0; after,
 * its own report of step s-1 with step s's `set` written over it. */
static void held_before(const plcvec_judge *j, const plcvec_vector *v, int s, const plcvec_cell *vector_before,
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
    const reported *r = j->out.cells;
    for (size_t k = j->out.first[s - 1]; k < j->out.first[s]; k++)
        if (r[k].device == p->device) {
            p->has_held = 1, p->held_type = r[k].type, p->held = r[k].value;
            return;
        }
}

/* Compare step `s`: what was reported (cells [lo, hi)) with the expected state. */
static void compare_step(plcvec_judge *j, const plcvec_vector *v, int s, const plcvec_cell *state, size_t n_state,
                         const plcvec_cell *before, size_t n_before)
{
    const reported *r = j->out.cells;
    size_t lo = j->out.first[s], hi = s + 1 < (int)j->out.n_steps ? j->out.first[s + 1] : j->out.n_cells;
    /* Fast path: the same devices in the same order with the same values and types. */
    size_t k = lo, i = 0;
    for (; k < hi; k++) {
        if (r[k].device >= 0 && is_scratch(v, r[k].device))
            continue;
        if (i >= n_state || r[k].device != state[i].device || r[k].type != state[i].type || r[k].value != state[i].value)
            break;
        i++;
    }
    if (k == hi && i == n_state)
        return;
    for (i = 0; i < n_state; i++) {
        const reported *got = NULL, *again = NULL;
        for (k = lo; k < hi && !again; k++)
            if (r[k].device == state[i].device) {
                if (!got)
                    got = &r[k];
                else if (r[k].type != got->type || r[k].value != got->value)
                    again = &r[k];      /* one device, two values: neither can be believed */
            }
        if (!again && got && got->type == state[i].type && got->value == state[i].value)
            continue;
        plcvec_problem *p = problem(j, s, state[i].device);
        if (!p)
            return;
        p->has_expected = 1;
        p->expected_type = state[i].type;
        p->expected = state[i].value;
        if (got) {
            p->has_actual = 1;
            p->actual_type = got->type;
            p->actual = got->value;
        }
        if (again) {
            p->twice = 1;
            p->second_type = again->type;
            p->second = again->value;
            continue;
        }
        const plcvec_cell *b = cell_of(before, n_before, state[i].device);
        if (b) {
            p->has_before = 1;
            p->before_type = b->type;
            p->before = b->value;
            p->keep = b->type == state[i].type && b->value == state[i].value;
        }
        held_before(j, v, s, b, p);
    }
    for (k = lo; k < hi; k++) {     /* a write outside the vector */
        if (r[k].device >= 0 && (is_scratch(v, r[k].device) || cell_of(state, n_state, r[k].device)))
            continue;
        if (cpu_writes(j, r[k].device >= 0 ? plcvec_device(r[k].device)->name : r[k].name))
            continue;   /* a device the CPU writes on its own account, declared, and not in the vector */
        plcvec_problem *p = problem(j, s, r[k].device);
        if (!p)
            return;
        snprintf(p->name, sizeof p->name, "%s", r[k].device >= 0 ? plcvec_device(r[k].device)->name : r[k].name);
        p->has_actual = 1;
        p->actual_type = r[k].type;
        p->actual = r[k].value;
    }
}

/* ---- judged by: the interpretations that decide a differing field (TEXT.md) ----------------- */

/* The expected value of `device` (or the result, device -1) after step k under one offered
 * expectation (NULL: the vector's own): 1 and the cell when listed. */
static int expected_at(const plcvec_vector *v, const plcvec_alternative *alt, size_t k, int device, plcvec_cell *cell)
{
    const plcvec_expect *x = alt ? &alt->expect[k] : &v->steps[k].expect;
    if (device == -1) {
        cell->type = PLCVEC_BIT;
        cell->value = (uint16_t)(x->result == 1);
        return x->result != PLCVEC_NONE;
    }
    int found = 0;
    for (size_t i = 0; i < v->n_devices; i++)
        if (v->devices[i].device == device)
            *cell = v->devices[i], found = 1;
    for (size_t s = 0; s <= k; s++) {
        const plcvec_expect *e = alt ? &alt->expect[s] : &v->steps[s].expect;
        for (size_t i = 0; i < v->steps[s].n_set; i++)
            if (v->steps[s].set[i].device == device)
                *cell = v->steps[s].set[i], found = 1;
        for (size_t i = 0; i < e->n_devices; i++)
            if (e->devices[i].device == device)
                *cell = e->devices[i], found = 1;
    }
    return found;
}

/* The alternative an offered expectation gives interpretation `interp`; -1 when it gives none. */
static int offered_alternative(const plcvec_alternative *alt, int interp)
{
    if (!alt)
        return plcvec_interpretations[interp].default_alternative;
    for (size_t c = 0; c < alt->n_choices; c++)
        if (alt->choices[c].interpretation == interp)
            return alt->choices[c].alternative;
    return -1;
}

/* The interpretations I for which the vector offers an expectation that differs from the followed
 * combination in I alone and differs from the followed expectation at (step, device). */
static uint64_t deciders(const plcvec_judge *j, const plcvec_vector *v, const plcvec_alternative *followed, int step,
                         int device)
{
    if (step < 0 || !v->n_interpretations)
        return 0;
    plcvec_cell here = {0, 0, 0};
    int listed = expected_at(v, followed, (size_t)step, device, &here);
    uint64_t found = 0;
    for (size_t o = 0; o <= v->n_alternatives; o++) {
        const plcvec_alternative *alt = o == 0 ? NULL : &v->alternatives[o - 1];
        if (alt == followed || (alt && alt->n_expect != v->n_steps))
            continue;
        int differing = -1, count = 0, complete = 1;
        for (size_t i = 0; i < v->n_interpretations; i++) {
            int interp = v->interpretations[i], a = offered_alternative(alt, interp);
            if (a < 0)
                complete = 0;
            else if (a != j->alternative[interp])
                differing = interp, count++;
        }
        if (!complete || count != 1 || (found >> differing & 1))
            continue;
        plcvec_cell there = {0, 0, 0};
        int listed_there = expected_at(v, alt, (size_t)step, device, &there);
        if (listed != listed_there || (listed && (here.type != there.type || here.value != there.value)))
            found |= UINT64_C(1) << differing;
    }
    return found;
}

static void judged_by(plcvec_judge *j, uint64_t which)
{
    plcvec_verdict *vd = &j->verdict;
    vd->n_choices = 0;
    /* Sorted by id. */
    for (;;) {
        int next = -1;
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT && i < 64; i++)
            if ((which >> i & 1) && (next < 0 || strcmp(plcvec_interpretations[i].id, plcvec_interpretations[next].id) < 0))
                next = i;
        if (next < 0)
            break;
        which &= ~(UINT64_C(1) << next);
        vd->choices[vd->n_choices].interpretation = (uint8_t)next;
        vd->choices[vd->n_choices++].alternative = j->alternative[next];
    }
}

static const char *problem_name(const plcvec_problem *p)
{
    return p->name[0] ? p->name : p->device >= 0 ? plcvec_device(p->device)->name : "";
}

/* Within a step, the result first, then the devices by name. */
static int problem_order(const void *a, const void *b)
{
    const plcvec_problem *x = a, *y = b;
    if (x->step != y->step)
        return x->step < y->step ? -1 : 1;
    int x_result = x->device == -1 && !x->name[0], y_result = y->device == -1 && !y->name[0];
    if (x_result != y_result)
        return x_result ? -1 : 1;
    return strcmp(problem_name(x), problem_name(y));
}

/* Compare the answer in j->out with the expectations `alt` (NULL: the vector's own), adding the
 * differences to j->problems. -1 when out of memory. */
static int compare_answer(plcvec_judge *j, const plcvec_vector *v, const plcvec_alternative *alt)
{
    plcvec_out *out = &j->out;
    if (out->n_steps != v->n_steps) {
        plcvec_problem *p = problem(j, -1, -2);
        if (p) {
            p->has_expected = p->has_actual = 1;
            p->expected = v->n_steps;
            p->actual = (uint32_t)out->n_steps;
        }
    } else {
        size_t need = (size_t)v->n_devices + 1;
        for (size_t s = 0; s < v->n_steps; s++)
            need += v->steps[s].n_set + (alt ? alt->expect[s].n_devices : v->steps[s].expect.n_devices);
        size_t cap = j->cap_state;
        if (!grow((void **)&j->state, &cap, need, sizeof *j->state) ||
            !grow((void **)&j->before, &j->cap_state, need, sizeof *j->before)) {
            return -1;
        }
        size_t n = 0;
        for (size_t i = 0; i < v->n_devices; i++)
            if (!is_scratch(v, v->devices[i].device))
                j->state[n++] = v->devices[i];
        for (size_t s = 0; s < v->n_steps; s++) {
            const plcvec_step *st = &v->steps[s];
            const plcvec_expect *x = alt ? &alt->expect[s] : &st->expect;
            for (size_t i = 0; i < st->n_set; i++)
                if (!is_scratch(v, st->set[i].device))
                    put(j->state, &n, &st->set[i]);
            memcpy(j->before, j->state, n * sizeof *j->state);
            size_t n_before = n;
            for (size_t i = 0; i < x->n_devices; i++)
                if (!is_scratch(v, x->devices[i].device))
                    put(j->state, &n, &x->devices[i]);
            if (x->result != PLCVEC_NONE && out->results[s] != x->result) {
                plcvec_problem *p = problem(j, (int)s, -1);
                if (p) {
                    p->has_expected = 1;
                    p->expected_type = PLCVEC_BIT;
                    p->expected = (uint32_t)x->result;
                    p->has_actual = out->results[s] != PLCVEC_NONE;
                    p->actual_type = PLCVEC_BIT;
                    p->actual = (uint32_t)(out->results[s] == 1);
                }
            }
            compare_step(j, v, (int)s, j->state, n, j->before, n_before);
        }
    }
    return 0;
}

const plcvec_verdict *plcvec_judge_vector(plcvec_judge *j, const plcvec_vector *v)
{
    plcvec_verdict *vd = &j->verdict;
    plcvec_out *out = &j->out;
    vd->vector = v;
    vd->message[0] = '\0';
    vd->problems = NULL;
    vd->n_problems = 0;
    j->n_problems = 0;
    vd->n_choices = 0;
    vd->applied = NULL;
    vd->offered_passes = 0;
    plcvec_guard_enter(v->id);      /* supports() is the implementation's code too */
    int supported = !j->impl.supports || j->impl.supports(j->impl.ctx, v->instruction);
    plcvec_guard_leave();
    if (!supported) {
        vd->status = PLCVEC_SKIP;
        snprintf(vd->message, sizeof vd->message, "the implementation does not support %s",
                 plcvec_instruction_names[v->instruction]);
        return vd;
    }
    const plcvec_alternative *alt = applicable(j, v);
    if (alt == &missing || (alt && alt->n_expect != v->n_steps)) {
        vd->status = PLCVEC_ERROR;
        snprintf(vd->message, sizeof vd->message,
                 "the vector lists no expectation for the alternatives it was judged by (is the suite damaged?)");
        return vd;
    }
    plcvec_out_reset(out);
    plcvec_guard_enter(v->id);
    int rc = j->impl.run(j->impl.ctx, v, out);
    plcvec_guard_leave();
    if (out->status == SKIPPED || rc == SKIPPED) {
        vd->status = PLCVEC_SKIP;
        snprintf(vd->message, sizeof vd->message, "%.300s", out->message[0] ? out->message : "skipped");
        return vd;
    }
    if (out->status == FAILED || rc != RAN || out->overflow) {
        vd->status = PLCVEC_ERROR;
        snprintf(vd->message, sizeof vd->message, "the implementation reported an error: %.300s",
                 out->message[0] ? out->message
                 : out->overflow ? "a device reported before plcvec_out_step(), an unknown device id, or out of memory"
                                 : "run() returned nonzero");
        return vd;
    }
    if (compare_answer(j, v, alt) != 0) {
        vd->status = PLCVEC_ERROR;
        snprintf(vd->message, sizeof vd->message, "out of memory");
        return vd;
    }
    /* For the roll-up by reading: under which offered expectations the same answer passes. */
    vd->offered_passes = 0;
    size_t kept = j->n_problems;
    for (size_t o = 0; o <= v->n_alternatives && o < 64 && kept; o++) {
        const plcvec_alternative *other = o == 0 ? NULL : &v->alternatives[o - 1];
        if (other && other->n_expect != v->n_steps)
            continue;
        if (compare_answer(j, v, other) == 0 && j->n_problems == kept)
            vd->offered_passes |= UINT64_C(1) << o;
        j->n_problems = kept;
    }
    if (j->n_problems > 1)
        qsort(j->problems, j->n_problems, sizeof *j->problems, problem_order);
    uint64_t which = 0;
    for (size_t i = 0; i < j->n_problems; i++) {
        plcvec_problem *p = &j->problems[i];
        if (p->device != -2 && !(p->device == -1 && p->name[0]))
            p->deciders = deciders(j, v, alt, p->step, p->device);
        which |= p->deciders;
    }
    judged_by(j, which);
    vd->applied = alt;
    vd->problems = j->problems;
    vd->n_problems = j->n_problems;
    vd->status = j->n_problems ? PLCVEC_FAIL : PLCVEC_PASS;
    return vd;
}

void plcvec_apply_known(plcvec_verdict *vd, const plcvec_known_failure *known, size_t n_known)
{
    for (size_t i = 0; i < n_known; i++) {
        if (!known[i].id || !vd->vector || strcmp(known[i].id, vd->vector->id) != 0)
            continue;
        if (vd->status == PLCVEC_FAIL || vd->status == PLCVEC_ERROR) {
            char was[sizeof vd->message];
            snprintf(was, sizeof was, "%s", vd->message);
            vd->status = PLCVEC_XFAIL;
            snprintf(vd->message, sizeof vd->message, "known failure: %.200s%s%.280s", known[i].reason ? known[i].reason : "",
                     was[0] ? "; " : "", was);
        } else if (vd->status == PLCVEC_PASS) {
            vd->status = PLCVEC_STALE;
            snprintf(vd->message, sizeof vd->message,
                     "listed as a known failure (%.300s) but it passes; remove it from the list",
                     known[i].reason ? known[i].reason : "");
        }
        return;
    }
}

/* ---- the verdict as text ------------------------------------------------------------------ */

typedef struct text {
    char *buf;
    size_t size, len;
} text;

static void add(text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    size_t room = t->len < t->size ? t->size - t->len : 0;
    int n = vsnprintf(room ? t->buf + t->len : NULL, room, fmt, ap);
    va_end(ap);
    if (n > 0)
        t->len += (size_t)n;
}

static void value(text *t, int has, uint8_t type, uint32_t v, const char *absent)
{
    if (!has)
        add(t, "%s", absent);
    else if (type == PLCVEC_BIT)
        add(t, "%s", v ? "true" : "false");
    else
        add(t, "%u", (unsigned)v);
}

#define SHOW_PROBLEMS 12    /* field lines shown per failing vector, as the Python runner */

/* The vector's state before step k under the expectations judged against (scratch left out): the
 * initial devices, each earlier step's `set` and changes, then step k's `set`. */
static size_t state_before(const plcvec_vector *v, const plcvec_alternative *alt, size_t k, plcvec_cell *state)
{
    size_t n = 0;
    for (size_t i = 0; i < v->n_devices; i++)
        if (!is_scratch(v, v->devices[i].device))
            state[n++] = v->devices[i];
    for (size_t s = 0; s <= k && s < v->n_steps; s++) {
        for (size_t i = 0; i < v->steps[s].n_set; i++)
            if (!is_scratch(v, v->steps[s].set[i].device))
                put(state, &n, &v->steps[s].set[i]);
        if (s == k)
            break;
        const plcvec_expect *x = alt ? &alt->expect[s] : &v->steps[s].expect;
        for (size_t i = 0; i < x->n_devices; i++)
            if (!is_scratch(v, x->devices[i].device))
                put(state, &n, &x->devices[i]);
    }
    return n;
}

static size_t state_capacity(const plcvec_vector *v, const plcvec_alternative *alt)
{
    size_t need = (size_t)v->n_devices + 1;
    for (size_t s = 0; s < v->n_steps; s++)
        need += v->steps[s].n_set + (alt ? alt->expect[s].n_devices : v->steps[s].expect.n_devices);
    return need;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(plcvec_device(((const plcvec_cell *)a)->device)->name, plcvec_device(((const plcvec_cell *)b)->device)->name);
}

/* `step k inputs: clock=..., rlo_in=..., en=..., input=..., elapsed_ms=..., set DEV=value ...` */
static void inputs_line(text *t, const plcvec_step *st, int k)
{
    add(t, "    step %d inputs:", k);
    const char *sep = " ";
    const plcvec_clock *c = st->clock;
    if (c) {
        add(t, "%sclock=", sep);
        const int date[3] = {c->year, c->month, c->day}, time[3] = {c->hour, c->minute, c->second};
        const unsigned date_bits[3] = {PLCVEC_CLOCK_YEAR, PLCVEC_CLOCK_MONTH, PLCVEC_CLOCK_DAY};
        const unsigned time_bits[3] = {PLCVEC_CLOCK_HOUR, PLCVEC_CLOCK_MINUTE, PLCVEC_CLOCK_SECOND};
        int any_date = 0, any_time = 0;
        for (int i = 0; i < 3; i++)
            if (c->fields & date_bits[i])
                add(t, any_date++ ? "/%d" : "%d", date[i]);
        for (int i = 0; i < 3; i++)
            if (c->fields & time_bits[i]) {
                if (!any_time && any_date)
                    add(t, " ");
                add(t, any_time++ ? ":%02d" : "%d", time[i]);
            }
        sep = ", ";
    }
    static const char *const names[3] = {"rlo_in", "en", "input"};
    const int8_t values[3] = {st->rlo_in, st->en, st->input};
    for (int i = 0; i < 3; i++)
        if (values[i] != PLCVEC_NONE) {
            add(t, "%s%s=%s", sep, names[i], values[i] ? "true" : "false");
            sep = ", ";
        }
    if (st->elapsed_ms != PLCVEC_NONE) {
        add(t, "%selapsed_ms=%lld", sep, (long long)st->elapsed_ms);
        sep = ", ";
    }
    if (st->n_set) {
        plcvec_cell sorted[64];
        size_t n = st->n_set < 64 ? st->n_set : 64;
        memcpy(sorted, st->set, n * sizeof *sorted);
        qsort(sorted, n, sizeof *sorted, by_name);
        add(t, "%sset", sep);
        for (size_t i = 0; i < n; i++) {
            add(t, " %s=", plcvec_device(sorted[i].device)->name);
            value(t, 1, sorted[i].type, sorted[i].value, "");
        }
        sep = ", ";
    }
    add(t, "%s\n", sep[0] == ' ' ? " (none)" : "");
}

static int by_operand_name(const void *a, const void *b)
{
    return strcmp((*(const plcvec_operand *const *)a)->name, (*(const plcvec_operand *const *)b)->name);
}

/* `step k operands: name DEV=words, name constant K, name DEV (scratch), ...`, sorted by name. */
static void operands_line(text *t, const plcvec_vector *v, const plcvec_cell *state, size_t n_state, int k)
{
    const plcvec_operand *ops[16];
    size_t n = v->n_operands < 16 ? v->n_operands : 16;
    for (size_t i = 0; i < n; i++)
        ops[i] = &v->operands[i];
    qsort(ops, n, sizeof *ops, by_operand_name);
    add(t, "    step %d operands:", k);
    for (size_t i = 0; i < n; i++) {
        const plcvec_operand *op = ops[i];
        add(t, "%s %s ", i ? "," : "", op->name);
        if (op->is_constant) {
            add(t, "constant %ld", (long)op->constant);
            continue;
        }
        const char *dev = plcvec_device(op->device)->name;
        if (is_scratch(v, op->device)) {
            add(t, "%s (scratch)", dev);
            continue;
        }
        const plcvec_cell *c = cell_of(state, n_state, op->device);
        if (!c) {
            add(t, "%s (not in the vector)", dev);
            continue;
        }
        add(t, "%s=", dev);
        value(t, 1, c->type, c->value, "");
        /* The words that follow, while each next address is a listed word of no other operand. */
        for (int id = op->device; c->type == PLCVEC_WORD;) {
            const plcvec_device_info *d = plcvec_device(id);
            if (d->number < 0)
                break;
            char next[32];
            snprintf(next, sizeof next, "%s%ld", d->kind, (long)d->number + 1);
            id = plcvec_device_named(next);
            c = id >= 0 && !is_scratch(v, id) ? cell_of(state, n_state, id) : NULL;
            for (size_t o = 0; c && o < v->n_operands; o++)
                if (!v->operands[o].is_constant && v->operands[o].device == id)
                    c = NULL;
            if (!c || c->type != PLCVEC_WORD)
                break;
            add(t, " %u", (unsigned)c->value);
        }
    }
    add(t, "\n");
}

size_t plcvec_format_verdict(char *buf, size_t size, const plcvec_verdict *vd)
{
    text t = {buf, size, 0};
    if (size)
        buf[0] = '\0';
    const plcvec_vector *v = vd->vector;
    static const char *const upper[] = {"PASS", "FAIL", "ERROR", "SKIP", "XFAIL", "STALE"};
    add(&t, "%s %s\n", vd->status <= PLCVEC_STALE ? upper[vd->status] : "?", v ? v->id : "?");
    if (v && v->description[0])
        add(&t, "    %s: %s\n", plcvec_instruction_names[v->instruction], v->description);
    if (vd->n_choices) {
        add(&t, "    judged by:");
        for (size_t i = 0; i < vd->n_choices; i++) {
            const plcvec_interpretation_info *info = &plcvec_interpretations[vd->choices[i].interpretation];
            add(&t, "%s %s=%s", i ? "," : "", info->id, info->alternatives[vd->choices[i].alternative]);
        }
        add(&t, "\n");
    }
    plcvec_cell *state = v && vd->n_problems ? malloc(state_capacity(v, vd->applied) * sizeof *state) : NULL;
    int shown_step = -1;
    for (size_t i = 0; i < vd->n_problems && i < SHOW_PROBLEMS; i++) {
        const plcvec_problem *p = &vd->problems[i];
        if (p->device == -2) {
            add(&t, "    steps: expected %u steps, got %u steps\n", (unsigned)p->expected, (unsigned)p->actual);
            continue;
        }
        if (p->step != shown_step && state && p->step >= 0 && (size_t)p->step < v->n_steps) {
            shown_step = p->step;
            inputs_line(&t, &v->steps[p->step], p->step);
            operands_line(&t, v, state, state_before(v, vd->applied, (size_t)p->step, state), p->step);
        }
        add(&t, "    step %d %s: expected ", p->step, p->name[0] ? p->name : p->device == -1 ? "result" : plcvec_device(p->device)->name);
        value(&t, p->has_expected, p->expected_type, p->expected, "<not in the vector>");
        if (p->twice) {
            add(&t, ", got two values: ");
            value(&t, 1, p->actual_type, p->actual, "");
            add(&t, " and ");
            value(&t, 1, p->second_type, p->second, "");
            add(&t, " (the device was reported twice)\n");
            continue;
        }
        add(&t, ", got ");
        value(&t, p->has_actual, p->actual_type, p->actual, "<not reported>");
        int is_device = p->device >= 0 || p->name[0];
        if (is_device && p->has_expected) {
            /* "must leave it unchanged" only where the implementation wrote the device in this step. */
            int wrote = p->has_actual && (!p->has_held || p->held_type != p->actual_type || p->held != p->actual);
            int held_expected = p->has_held && p->held_type == p->expected_type && p->held == p->expected;
            if (p->keep && wrote && held_expected)
                add(&t, " (the step must leave it unchanged)");
            else {
                add(&t, " (before the step: ");
                value(&t, p->has_held, p->held_type, p->held, "<not reported>");
                add(&t, p->keep && wrote ? "; the step must leave it unchanged)" : ")");
            }
        }
        add(&t, "\n");
    }
    free(state);
    if (vd->n_problems > SHOW_PROBLEMS)
        add(&t, "    ... and %zu more differences\n", vd->n_problems - SHOW_PROBLEMS);
    if (vd->message[0])
        add(&t, "    %s\n", vd->message);
    if (v && v->n_clauses) {
        add(&t, "    spec clauses:");
        for (size_t i = 0; i < v->n_clauses; i++)
            add(&t, "%s %s", i ? "," : "", plcvec_clause(v, i));
        add(&t, "\n");
    }
    return t.len;
}

void plcvec_print_verdict(FILE *f, const plcvec_verdict *vd)
{
    char small[4096];
    size_t n = plcvec_format_verdict(small, sizeof small, vd);
    if (n < sizeof small) {
        fputs(small, f);
        return;
    }
    char *big = malloc(n + 1);
    if (!big) {
        fputs(small, f);
        return;
    }
    plcvec_format_verdict(big, n + 1, vd);
    fputs(big, f);
    free(big);
}
