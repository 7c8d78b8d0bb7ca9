/* The "execute this instruction on my memory" helper (plcvec_machine, VOCABULARY.md's Emulator): an
 * emulator that only executes instructions on its own memory. The runner writes each vector's
 * devices into that memory, executes each step, and reads them back. */
#include <string.h>

#include "plcvec/plcvec.h"

static int machine_supports(void *ctx, plcvec_instruction instruction)
{
    const plcvec_machine *m = ctx;
    return m->supports ? m->supports(m->ctx, instruction) : 1;
}

typedef struct seen_arg {
    const plcvec_vector *v;
    plcvec_out *out;
} seen_arg;

static void seen(void *arg, const char *device, plcvec_type type, unsigned value)
{
    seen_arg *a = arg;
    for (size_t i = 0; i < a->v->n_devices; i++)
        if (strcmp(plcvec_device(a->v->devices[i].device)->name, device) == 0)
            return;     /* already read back */
    plcvec_out_named(a->out, device, type, value);
}

static int machine_run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    const plcvec_machine *m = ctx;
    if (m->reset && m->reset(m->ctx, v) != 0)
        return plcvec_out_skip(out, "the machine's reset() refused the vector");
    for (size_t i = 0; i < v->n_devices; i++)
        m->write(m->ctx, plcvec_device(v->devices[i].device)->name, (plcvec_type)v->devices[i].type, v->devices[i].value);
    for (size_t s = 0; s < v->n_steps; s++) {
        const plcvec_step *st = &v->steps[s];
        for (size_t i = 0; i < st->n_set; i++)
            m->write(m->ctx, plcvec_device(st->set[i].device)->name, (plcvec_type)st->set[i].type, st->set[i].value);
        int result = m->execute(m->ctx, v, st);
        if (result == -2)
            return plcvec_out_error(out, "execute() reported an error");
        plcvec_out_step(out, result);
        for (size_t i = 0; i < v->n_devices; i++) {
            const plcvec_cell *c = &v->devices[i];
            plcvec_out_device(out, c->device, (plcvec_type)c->type, m->read(m->ctx, plcvec_device(c->device)->name));
        }
        if (m->written) {
            seen_arg a = {v, out};
            m->written(m->ctx, seen, &a);
        }
    }
    return 0;
}

plcvec_impl plcvec_machine_impl(const plcvec_machine *m)
{
    plcvec_impl impl = {0};
    impl.name = m->name;
    impl.ctx = (void *)m;
    impl.choices = m->choices;
    impl.n_choices = m->n_choices;
    impl.supports = machine_supports;
    impl.run = machine_run;
    impl.cpu_writes = m->cpu_writes;
    return impl;
}
