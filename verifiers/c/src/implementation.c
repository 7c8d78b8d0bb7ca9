/* Where an implementation reports what it did with one vector (CONTRACT.md, "Comparing"): after
 * each step the contact result and the devices, or instead of steps a skip or an error. The
 * runner owns it; the judge reads it back (compare.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "implementation.h"

const char plcvec_out_overflow_message[] =
    "a device reported before plcvec_out_step(), an unknown device id, or out of memory";

int plcvec_grow_to(void **p, size_t *cap, size_t need, size_t size)
{
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
    if (!plcvec_grow((void **)&out->results, &cap, out->n_steps + 1, sizeof *out->results) ||
        !plcvec_grow((void **)&out->first, &out->cap_steps, out->n_steps + 1, sizeof *out->first)) {
        out->overflow = 1;
        return;
    }
    out->results[out->n_steps] = result == 0 || result == 1 ? result : PLCVEC_NONE;
    out->first[out->n_steps++] = out->n_cells;
}

static plcvec_reported *add_cell(plcvec_out *out, plcvec_type type, unsigned value)
{
    if (out->n_steps == 0 || !plcvec_grow((void **)&out->cells, &out->cap_cells, out->n_cells + 1, sizeof *out->cells)) {
        out->overflow = 1;      /* a device before any plcvec_out_step(), or out of memory */
        return NULL;
    }
    plcvec_reported *c = &out->cells[out->n_cells++];
    c->type = (uint8_t)type;
    c->value = value;
    c->name[0] = '\0';
    return c;
}

/* Every case plcvec_out_device() does not settle in place: an interned or unknown id, a device
 * before any step, a full array. */
PLCVEC_OUT_OF_LINE static void out_device_checked(plcvec_out *out, int device, plcvec_type type, unsigned value)
{
    if (!plcvec_device(device)) {
        out->overflow = 1;
        return;
    }
    plcvec_reported *c = add_cell(out, type, value);
    if (c)
        c->device = device;
}

void plcvec_out_device(plcvec_out *out, int device, plcvec_type type, unsigned value)
{
    /* Every device of every step reported comes here: a device of the generated table after a
     * step, with room for it, is recorded without a call (and so without saving registers). */
    if ((unsigned)device < PLCVEC_DEVICE_COUNT && out->n_steps && out->n_cells < out->cap_cells) {
        plcvec_reported *c = &out->cells[out->n_cells++];
        c->device = device;
        c->type = (uint8_t)type;
        c->value = value;
        c->name[0] = '\0';
        return;
    }
    out_device_checked(out, device, type, value);
}

void plcvec_out_named(plcvec_out *out, const char *device, plcvec_type type, unsigned value)
{
    int id = plcvec_device_named(device);
    if (id >= 0) {
        plcvec_out_device(out, id, type, value);
        return;
    }
    plcvec_reported *c = add_cell(out, type, value);
    if (c) {
        c->device = -1;
        snprintf(c->name, sizeof c->name, "%s", device);
    }
}

int plcvec_out_skip(plcvec_out *out, const char *reason)
{
    out->status = PLCVEC_SKIPPED;
    snprintf(out->message, sizeof out->message, "%s", reason ? reason : "skipped");
    return PLCVEC_SKIPPED;
}

int plcvec_out_error(plcvec_out *out, const char *message)
{
    out->status = PLCVEC_FAILED;
    snprintf(out->message, sizeof out->message, "%s", message ? message : "error");
    return PLCVEC_FAILED;
}

plcvec_out *plcvec_out_new(void)
{
    return calloc(1, sizeof(plcvec_out));
}

void plcvec_out_release(plcvec_out *out)
{
    free(out->results);
    free(out->first);
    free(out->cells);
    memset(out, 0, sizeof *out);
}

void plcvec_out_free(plcvec_out *out)
{
    if (!out)
        return;
    plcvec_out_release(out);
    free(out);
}

void plcvec_out_reset(plcvec_out *out)
{
    out->n_steps = out->n_cells = 0;
    out->status = PLCVEC_RAN;
    out->overflow = 0;
    out->message[0] = '\0';
}

int plcvec_out_status(const plcvec_out *out, const char **message)
{
    if (message)
        *message = out->message[0] ? out->message : out->overflow ? plcvec_out_overflow_message : "";
    return out->overflow && out->status == PLCVEC_RAN ? PLCVEC_FAILED : out->status;
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
    size_t lo, hi;
    plcvec_out_span(out, step, &lo, &hi);
    *n = hi - lo;
    return out->cells + lo;
}
