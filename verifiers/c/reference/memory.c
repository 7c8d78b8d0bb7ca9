#include "memory.h"

#include <stdio.h>
#include <string.h>

static const mem_cell *find(const memory *m, address a)
{
    for (size_t i = 0; i < m->n; i++) {
        const mem_cell *c = &m->cells[i];
        if (a.device >= 0 ? c->device == a.device : (c->number == a.number && strcmp(c->kind, a.kind) == 0))
            return c;
    }
    return NULL;
}

address memory_device(int device)
{
    const plcvec_device_info *d = plcvec_device(device);
    address a = {d->kind, d->number, device};
    return a;
}

address memory_offset(address base, int offset)
{
    address a = {base.kind, base.number + offset, offset == 0 ? base.device : -1};
    if (a.device >= 0)
        return a;
    /* The table of names is sorted, so D101 usually sits right after D100: start there, wrap
     * around. A device the table does not have keeps -1 and is found by type and number. */
    int d = base.device >= 0 && base.device < PLCVEC_DEVICE_COUNT ? base.device : 0;
    for (int k = 0; k < PLCVEC_DEVICE_COUNT; k++, d = d + 1 < PLCVEC_DEVICE_COUNT ? d + 1 : 0) {
        const plcvec_device_info *t = &plcvec_devices[d];
        /* The table's kinds are one string per kind, so the same pointer usually says it. */
        if (t->number == a.number && (t->kind == a.kind || strcmp(t->kind, a.kind) == 0)) {
            a.device = d;
            break;
        }
    }
    return a;
}

int memory_in_range(const memory *m, address base, int words)
{
    long size = plcvec_size_of(m->vector, base.kind);
    if (size < 0)
        return 1;
    return base.number >= 0 && (long)base.number + words <= size;
}

uint16_t memory_read(const memory *m, address a)
{
    const mem_cell *c = find(m, a);
    return c ? c->value : 0;
}

void memory_write(memory *m, address a, plcvec_type type, uint16_t value)
{
    mem_cell *c = (mem_cell *)find(m, a);
    if (!c) {
        if (m->n == MEMORY_CELLS) {
            m->overflow = 1;
            return;
        }
        c = &m->cells[m->n++];
        c->device = a.device;
        c->kind = a.kind;
        c->number = a.number;
    }
    c->type = (uint8_t)type;
    c->value = value;
}

void memory_write_named(memory *m, int device, plcvec_type type, uint16_t value)
{
    memory_write(m, memory_device(device), type, value);
}

void memory_load(memory *m, const plcvec_vector *v)
{
    m->vector = v;
    m->n = 0;
    m->overflow = v->n_devices > MEMORY_CELLS;
    for (size_t i = 0; i < v->n_devices && i < MEMORY_CELLS; i++) {
        const plcvec_cell *src = &v->devices[i];
        const plcvec_device_info *d = plcvec_device(src->device);
        mem_cell *c = &m->cells[m->n++];
        c->device = src->device;
        c->kind = d->kind;
        c->number = d->number;
        c->type = src->type;
        c->value = src->value;
    }
}

int16_t to_signed16(uint16_t word)
{
    return (int16_t)(word >= 0x8000 ? (int)word - 0x10000 : (int)word);
}

void memory_report(const memory *m, plcvec_out *out, int result)
{
    plcvec_out_step(out, result);
    for (size_t i = 0; i < m->n; i++) {
        const mem_cell *c = &m->cells[i];
        if (c->device >= 0)
            plcvec_out_device(out, c->device, (plcvec_type)c->type, c->value);
        else {
            char name[24];
            if (c->number >= 0)
                snprintf(name, sizeof name, "%s%ld", c->kind, (long)c->number);
            else
                snprintf(name, sizeof name, "%s", c->kind);
            plcvec_out_named(out, name, (plcvec_type)c->type, c->value);
        }
    }
}
