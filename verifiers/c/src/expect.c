/* A vector's expectations under the alternatives followed: its own steps for the defaults, else the
 * entry of `alternatives` whose choices match (CONTRACT.md); the full state expected before and
 * after each step, worked out from the initial devices, each step's `set` and its changes, as the
 * Python runner does; and the devices an entry leaves unjudged (schema 1.1). */
#include <stdlib.h>
#include <string.h>

#include "expect.h"

const plcvec_alternative plcvec_expect_missing;

const plcvec_alternative *plcvec_expect_entry(const plcvec_vector *v, const uint8_t *alternative)
{
    int all_default = 1;
    for (size_t i = 0; i < v->n_interpretations; i++) {
        uint8_t interp = v->interpretations[i];
        if (alternative[interp] != plcvec_interpretations[interp].default_alternative)
            all_default = 0;
    }
    if (all_default)
        return NULL;
    for (size_t a = 0; a < v->n_alternatives; a++) {
        const plcvec_alternative *entry = &v->alternatives[a];
        size_t i = 0;
        while (i < v->n_interpretations && plcvec_expect_offered(entry, v->interpretations[i]) ==
                                               alternative[v->interpretations[i]])
            i++;
        if (i == v->n_interpretations)
            return entry;
    }
    return &plcvec_expect_missing;
}

int plcvec_expect_offered(const plcvec_alternative *entry, int interp)
{
    if (!entry)
        return plcvec_interpretations[interp].default_alternative;
    for (size_t c = 0; c < entry->n_choices; c++)
        if (entry->choices[c].interpretation == interp)
            return entry->choices[c].alternative;
    return -1;
}

int plcvec_expect_unjudged(const plcvec_alternative *entry, int device)
{
    for (size_t u = 0; entry && u < entry->n_unjudged; u++)
        for (size_t d = 0; d < entry->unjudged[u].n_devices; d++)
            if (entry->unjudged[u].devices[d] == device)
                return 1;
    return 0;
}

const plcvec_cell *plcvec_state_cell(const plcvec_cell *state, size_t n, int device)
{
    for (size_t i = 0; i < n; i++)
        if (state[i].device == device)
            return &state[i];
    return NULL;
}

size_t plcvec_expect_capacity(const plcvec_vector *v, const plcvec_alternative *entry)
{
    size_t need = (size_t)v->n_devices + 1;
    for (size_t s = 0; s < v->n_steps; s++)
        need += v->steps[s].n_set + plcvec_expect_step(v, entry, s)->n_devices;
    return need;
}

/* The cells of `list` into `state`, scratch left out. */
static void put_all(const plcvec_vector *v, plcvec_cell *state, size_t *n, const plcvec_cell *list, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (!plcvec_expect_scratch(v, list[i].device))
            plcvec_state_put(state, n, &list[i]);
}

/* The initial devices, scratch left out: each listed once, so appended without a search (and
 * copied whole when the vector has no scratch, as most have not). */
static size_t initial_state(const plcvec_vector *v, plcvec_cell *state)
{
    if (!v->n_scratch) {
        memcpy(state, v->devices, v->n_devices * sizeof *state);
        return v->n_devices;
    }
    size_t n = 0;
    for (size_t i = 0; i < v->n_devices; i++)
        if (!plcvec_expect_scratch(v, v->devices[i].device))
            state[n++] = v->devices[i];
    return n;
}

size_t plcvec_expect_before(const plcvec_vector *v, const plcvec_alternative *entry, size_t k, plcvec_cell *state)
{
    size_t n = initial_state(v, state);
    for (size_t s = 0; s <= k && s < v->n_steps; s++) {
        put_all(v, state, &n, v->steps[s].set, v->steps[s].n_set);
        if (s < k) {
            const plcvec_expect *x = plcvec_expect_step(v, entry, s);
            put_all(v, state, &n, x->devices, x->n_devices);
        }
    }
    return n;
}

int plcvec_expect_value(const plcvec_vector *v, const plcvec_alternative *entry, size_t k, int device, plcvec_cell *cell)
{
    const plcvec_expect *x = plcvec_expect_step(v, entry, k);
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
        const plcvec_expect *e = plcvec_expect_step(v, entry, s);
        for (size_t i = 0; i < v->steps[s].n_set; i++)
            if (v->steps[s].set[i].device == device)
                *cell = v->steps[s].set[i], found = 1;
        for (size_t i = 0; i < e->n_devices; i++)
            if (e->devices[i].device == device)
                *cell = e->devices[i], found = 1;
    }
    return found;
}

/* Every device of `x` that `entry` judges is judged by `followed` and holds the same in `y`. */
static int judged_alike(const plcvec_cell *x, size_t nx, const plcvec_alternative *entry, const plcvec_cell *y,
                        size_t ny, const plcvec_alternative *followed)
{
    for (size_t i = 0; i < nx; i++) {
        if (plcvec_expect_unjudged(entry, x[i].device))
            continue;
        const plcvec_cell *there = plcvec_state_cell(y, ny, x[i].device);
        if (!there || plcvec_expect_unjudged(followed, x[i].device) || there->type != x[i].type ||
            there->value != x[i].value)
            return 0;
    }
    return 1;
}

int plcvec_expect_same(const plcvec_vector *v, const plcvec_alternative *entry, const plcvec_alternative *followed)
{
    if (entry == followed)
        return 1;
    size_t cap = plcvec_expect_capacity(v, entry) + plcvec_expect_capacity(v, followed);
    plcvec_cell *x = malloc(2 * cap * sizeof *x), *y = x ? x + cap : NULL;
    if (!x)
        return -1;
    size_t nx = initial_state(v, x), ny = initial_state(v, y);
    int same = 1;
    for (size_t s = 0; s < v->n_steps && same; s++) {
        const plcvec_expect *ex = plcvec_expect_step(v, entry, s), *ey = plcvec_expect_step(v, followed, s);
        put_all(v, x, &nx, v->steps[s].set, v->steps[s].n_set);
        put_all(v, y, &ny, v->steps[s].set, v->steps[s].n_set);
        put_all(v, x, &nx, ex->devices, ex->n_devices);
        put_all(v, y, &ny, ey->devices, ey->n_devices);
        /* A device judged under `entry` but absent under `followed` differs too: look both ways. */
        same = ex->result == ey->result && judged_alike(x, nx, entry, y, ny, followed) &&
               judged_alike(y, ny, entry, x, nx, followed);
    }
    free(x);
    return same;
}
