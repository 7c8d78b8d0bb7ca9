/* The paths taken at every device of every vector, each against an answer worked out another way:
 * what plcvec_out_device() records (in place for a device of the generated table, through the
 * checked path otherwise), operands and sizes by name (compared in place, so a prefix must not
 * match), and the reference's base + offset (by a walk of the device table from the base, wrapping
 * around) against the lookup of the device's name; and the state before a later step, which the
 * comparison works out only for a differing field. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reference.h"

/* Past the first array of cells (64), through growth, every cell recorded in order. */
#define MANY_CELLS 1000

static void test_reported_devices(void)
{
    plcvec_out *out = plcvec_out_new();
    const char *why;
    plcvec_out_step(out, 1);
    for (unsigned i = 0; i < MANY_CELLS; i++)
        plcvec_out_device(out, (int)(i % PLCVEC_DEVICE_COUNT), (plcvec_type)(i & 1), i * 7);
    int d5000 = plcvec_device_intern("D5000");    /* not in the generated table: an interned id */
    CHECK(d5000 >= PLCVEC_DEVICE_COUNT);
    plcvec_out_device(out, d5000, PLCVEC_WORD, 65535);
    CHECK(plcvec_out_status(out, &why) == 0 && why[0] == '\0');
    size_t n;
    const plcvec_reported *cells = plcvec_out_cells(out, 0, &n);
    CHECK(n == MANY_CELLS + 1);
    int in_order = n == MANY_CELLS + 1;
    for (unsigned i = 0; in_order && i < MANY_CELLS; i++)
        in_order = cells[i].device == (int)(i % PLCVEC_DEVICE_COUNT) && cells[i].type == (i & 1) &&
                   cells[i].value == i * 7 && cells[i].name[0] == '\0';
    CHECK(in_order);
    CHECK(n == MANY_CELLS + 1 && cells[MANY_CELLS].device == d5000 && cells[MANY_CELLS].value == 65535);

    /* A device before any step breaks the interface: the report is an error, nothing recorded;
     * also in a plcvec_out used before, which has room for cells (as the runner's is). */
    plcvec_out_reset(out);
    plcvec_out_device(out, PLCVEC_DEV_D100, PLCVEC_WORD, 1);
    CHECK(plcvec_out_status(out, &why) == 2 && strstr(why, "before plcvec_out_step()") != NULL);
    CHECK(plcvec_out_step_count(out) == 0);

    /* An id that is no device, below the table or past the interned ones: an error, not a cell. */
    int unknown[] = {-1, -2, d5000 + 1000};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; k++) {
        plcvec_out_reset(out);
        plcvec_out_step(out, 0);
        plcvec_out_device(out, unknown[k], PLCVEC_WORD, 3);
        CHECK(plcvec_out_status(out, &why) == 2 && strstr(why, "an unknown device id") != NULL);
        plcvec_out_cells(out, 0, &n);
        CHECK(n == 0);
    }
    plcvec_out_free(out);
}

/* A vector of `family` with an operand named `name` and a stated size of kind `kind`. */
static const plcvec_vector *vector_with(plcvec_family family, const char *name, const char *kind)
{
    for (size_t i = 0; i < plcvec_count(); i++) {
        const plcvec_vector *v = plcvec_at(i);
        int has_name = 0, has_kind = 0;
        for (size_t k = 0; k < v->n_operands; k++)
            has_name |= strcmp(v->operands[k].name, name) == 0;
        for (size_t k = 0; k < v->n_sizes; k++)
            has_kind |= strcmp(v->sizes[k].kind, kind) == 0;
        if (v->family == family && has_name && has_kind)
            return v;
    }
    return NULL;
}

static void test_names(void)
{
    const plcvec_vector *v = vector_with(PLCVEC_FAMILY_FX5_TIME_COMPARE, "s1", "D");
    CHECK(v != NULL);
    if (!v)
        return;
    const plcvec_operand *s1 = plcvec_operand_named(v, "s1");
    CHECK(s1 != NULL && strcmp(s1->name, "s1") == 0);
    /* A name that is a prefix of an operand's, or has one as its prefix, or differs in case. */
    const char *not_operands[] = {"s", "s10", "s1 ", "S1", "", "1"};
    for (size_t k = 0; k < sizeof not_operands / sizeof not_operands[0]; k++)
        CHECK(plcvec_operand_named(v, not_operands[k]) == NULL);
    long points = -1;
    for (size_t k = 0; k < v->n_sizes; k++)
        if (strcmp(v->sizes[k].kind, "D") == 0)
            points = (long)v->sizes[k].points;
    CHECK(points > 0 && plcvec_size_of(v, "D") == points);
    const char *not_kinds[] = {"", "DD", "d", "SD"};
    for (size_t k = 0; k < sizeof not_kinds / sizeof not_kinds[0]; k++) {
        int stated = 0;
        for (size_t i = 0; i < v->n_sizes; i++)
            stated |= strcmp(v->sizes[i].kind, not_kinds[k]) == 0;
        CHECK(stated || plcvec_size_of(v, not_kinds[k]) == -1);
    }
}

/* base + k for every device of the table with a number and k = 0..9: the device of that type and
 * number (found by its name), or none; its kind and number whatever the table holds. Where the
 * table's order by name puts base + k before base ("D99" + 1 is "D100"), the walk wraps around. */
static void test_offsets(void)
{
    size_t found = 0;
    for (int d = 0; d < PLCVEC_DEVICE_COUNT; d++) {
        const plcvec_device_info *base = &plcvec_devices[d];
        if (base->number < 0)
            continue;
        for (int k = 0; k < 10; k++) {
            char name[32];
            snprintf(name, sizeof name, "%s%ld", base->kind, (long)base->number + k);
            int want = plcvec_device_named(name);
            address a = memory_offset(memory_device(d), k);
            CHECK(a.device == want);
            CHECK(strcmp(a.kind, base->kind) == 0 && a.number == base->number + k);
            found += want >= 0;
        }
    }
    CHECK(found > (size_t)PLCVEC_DEVICE_COUNT / 2);  /* the table's multi-word operands were found */
}

/* ---- the state before a later step, named by a differing field --------------------------- */

/* The reference, but step `step`'s report of `device` has its lowest bit flipped. */
typedef struct flipping {
    plcvec_reference ref;
    plcvec_impl inner;
    plcvec_out *copy;
    size_t step;
    int device;
} flipping;

static int flipping_run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    flipping *f = ctx;
    plcvec_out_reset(f->copy);
    f->inner.run(f->inner.ctx, v, f->copy);
    for (size_t s = 0; s < plcvec_out_step_count(f->copy); s++) {
        plcvec_out_step(out, plcvec_out_result(f->copy, s));
        size_t n;
        const plcvec_reported *cells = plcvec_out_cells(f->copy, s, &n);
        for (size_t i = 0; i < n; i++)
            plcvec_out_device(out, cells[i].device, (plcvec_type)cells[i].type,
                              cells[i].value ^ (s == f->step && cells[i].device == f->device));
    }
    return 0;
}

static const plcvec_cell *cell_in(const plcvec_cell *cells, size_t n, int device)
{
    for (size_t i = 0; i < n; i++)
        if (cells[i].device == device)
            return &cells[i];
    return NULL;
}

/* A word of v that step 0 changes and step 1 neither sets nor changes (so step 1 must keep step 0's
 * value, not the initial one); NULL if none. */
static const plcvec_cell *changed_then_kept(const plcvec_vector *v)
{
    if (v->n_steps < 2 || v->n_interpretations || v->n_scratch)
        return NULL;
    const plcvec_expect *x = &v->steps[0].expect;
    for (size_t i = 0; i < x->n_devices; i++) {
        const plcvec_cell *c = &x->devices[i], *initial = cell_in(v->devices, v->n_devices, c->device);
        if (c->type == PLCVEC_WORD && initial && initial->value != c->value &&
            !cell_in(v->steps[1].set, v->steps[1].n_set, c->device) &&
            !cell_in(v->steps[1].expect.devices, v->steps[1].expect.n_devices, c->device) &&
            !cell_in(v->steps[0].set, v->steps[0].n_set, c->device))
            return c;
    }
    return NULL;
}

/* "before the step" of a field that differs at step 1 is the state after step 0, not the initial
 * one: the step must leave the word step 0 wrote unchanged. */
static void test_before_a_later_step(void)
{
    const plcvec_vector *v = NULL;
    const plcvec_cell *kept = NULL;
    for (size_t i = 0; i < plcvec_count() && !kept; i++)
        kept = changed_then_kept(v = plcvec_at(i));
    CHECK(kept != NULL);
    if (!kept)
        return;
    flipping f = {.step = 1, .device = kept->device};
    plcvec_reference_init(&f.ref);
    f.inner = plcvec_reference_impl(&f.ref);
    f.copy = plcvec_out_new();
    plcvec_impl impl = f.inner;
    impl.ctx = &f;
    impl.run = flipping_run;
    char err[256], text[8192], want[128];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    const plcvec_verdict *vd = plcvec_judge_vector(j, v);
    CHECK(vd->status == PLCVEC_FAIL);
    plcvec_format_verdict(text, sizeof text, vd);
    snprintf(want, sizeof want, "step 1 %s: expected %u, got %u (the step must leave it unchanged)\n",
             plcvec_devices[kept->device].name, (unsigned)kept->value, (unsigned)kept->value ^ 1u);
    CHECK_HAS(text, want);
    plcvec_judge_free(j);
    plcvec_out_free(f.copy);
}

int main(void)
{
    test_offsets();     /* first: the table alone, before test_reported_devices() interns D5000 */
    test_reported_devices();
    test_names();
    test_before_a_later_step();
    if (failures) {
        fprintf(stderr, "%d check(s) failed\n", failures);
        return 1;
    }
    printf("report and lookups: ok\n");
    return 0;
}
