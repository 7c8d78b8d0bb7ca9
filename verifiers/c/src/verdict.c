/* The verdict as people read it: the failure block of verifiers/parity/TEXT.md, byte for byte the
 * one every plcvec runner prints (status and id, the description, judged by, the devices left
 * unjudged, each step's inputs and operand words, one line per differing field, the message, the
 * spec clauses). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"

const char *const plcvec_status_names[] = {"pass", "fail", "error", "skip", "xfail", "stale"};

#define SHOW_PROBLEMS 12    /* field lines shown per failing vector (TEXT.md) */

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

static int by_name(const void *a, const void *b)
{
    return strcmp(plcvec_device(((const plcvec_cell *)a)->device)->name, plcvec_device(((const plcvec_cell *)b)->device)->name);
}

/* The clock as the date, the time or both: 2029/6/17 4:02:41. */
static void clock_text(text *t, const plcvec_clock *c)
{
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
}

/* `step k inputs: clock=..., rlo_in=..., en=..., input=..., elapsed_ms=..., set DEV=value ...` */
static void inputs_line(text *t, const plcvec_step *st, int k)
{
    add(t, "    step %d inputs:", k);
    const char *sep = " ";
    if (st->clock) {
        add(t, "%sclock=", sep);
        clock_text(t, st->clock);
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

/* The words after an operand's first: each next address while it is a listed word of no other
 * operand, not scratch. */
static void following_words(text *t, const plcvec_vector *v, int device, const plcvec_cell *state, size_t n_state)
{
    for (int id = device;;) {
        const plcvec_device_info *d = plcvec_device(id);
        if (d->number < 0)
            return;
        char next[32];
        snprintf(next, sizeof next, "%s%ld", d->kind, (long)d->number + 1);
        id = plcvec_device_named(next);
        const plcvec_cell *c = id >= 0 && !plcvec_expect_scratch(v, id) ? plcvec_state_cell(state, n_state, id) : NULL;
        for (size_t o = 0; c && o < v->n_operands; o++)
            if (!v->operands[o].is_constant && v->operands[o].device == id)
                c = NULL;
        if (!c || c->type != PLCVEC_WORD)
            return;
        add(t, " %u", (unsigned)c->value);
    }
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
        const char *dev = op->is_constant ? NULL : plcvec_device(op->device)->name;
        const plcvec_cell *c = dev ? plcvec_state_cell(state, n_state, op->device) : NULL;
        if (op->is_constant)
            add(t, "constant %ld", (long)op->constant);
        else if (plcvec_expect_scratch(v, op->device))
            add(t, "%s (scratch)", dev);
        else if (!c)
            add(t, "%s (not in the vector)", dev);
        else {
            add(t, "%s=", dev);
            value(t, 1, c->type, c->value, "");
            if (c->type == PLCVEC_WORD)
                following_words(t, v, op->device, state, n_state);
        }
    }
    add(t, "\n");
}

/* ` (before the step: X)`, or that the step must leave the device unchanged (TEXT.md, "A field
 * line"): "must leave it unchanged" only where the implementation wrote the device in the step. */
static void held_suffix(text *t, const plcvec_problem *p)
{
    int wrote = p->has_actual && (!p->has_held || p->held_type != p->actual_type || p->held != p->actual);
    int held_expected = p->has_held && p->held_type == p->expected_type && p->held == p->expected;
    if (p->keep && wrote && held_expected) {
        add(t, " (the step must leave it unchanged)");
        return;
    }
    add(t, " (before the step: ");
    value(t, p->has_held, p->held_type, p->held, "<not reported>");
    add(t, p->keep && wrote ? "; the step must leave it unchanged)" : ")");
}

/* `step k DEVICE: expected X, got Y (...)`, or the number of steps. */
static void field_line(text *t, const plcvec_problem *p)
{
    if (p->device == -2) {
        add(t, "    steps: expected %u steps, got %u steps\n", (unsigned)p->expected, (unsigned)p->actual);
        return;
    }
    add(t, "    step %d %s: expected ", p->step, p->name[0] ? p->name : p->device == -1 ? "result" : plcvec_device(p->device)->name);
    value(t, p->has_expected, p->expected_type, p->expected, "<not in the vector>");
    if (p->twice) {
        add(t, ", got two values: ");
        value(t, 1, p->actual_type, p->actual, "");
        add(t, " and ");
        value(t, 1, p->second_type, p->second, "");
        add(t, " (the device was reported twice)\n");
        return;
    }
    add(t, ", got ");
    value(t, p->has_actual, p->actual_type, p->actual, "<not reported>");
    if ((p->device >= 0 || p->name[0]) && p->has_expected)
        held_suffix(t, p);
    add(t, "\n");
}

/* The field lines, each step's first preceded by its inputs and operands (the state the vector
 * gives the step, under the expectation judged). */
static void field_lines(text *t, const plcvec_verdict *vd)
{
    const plcvec_vector *v = vd->vector;
    plcvec_cell *state = v && vd->n_problems ? malloc(plcvec_expect_capacity(v, vd->applied) * sizeof *state) : NULL;
    int shown_step = -1;
    for (size_t i = 0; i < vd->n_problems && i < SHOW_PROBLEMS; i++) {
        const plcvec_problem *p = &vd->problems[i];
        if (p->device != -2 && p->step != shown_step && state && p->step >= 0 && (size_t)p->step < v->n_steps) {
            shown_step = p->step;
            inputs_line(t, &v->steps[p->step], p->step);
            operands_line(t, v, state, plcvec_expect_before(v, vd->applied, (size_t)p->step, state), p->step);
        }
        field_line(t, p);
    }
    free(state);
    if (vd->n_problems > SHOW_PROBLEMS)
        add(t, "    ... and %zu more differences\n", vd->n_problems - SHOW_PROBLEMS);
}

/* `judged by: ID=alt, ...` and `not judged under ID=alt: DEV, DEV` (one line per interpretation of
 * the entry's unjudged map). */
static void judgement_lines(text *t, const plcvec_verdict *vd)
{
    if (vd->n_choices) {
        add(t, "    judged by:");
        for (size_t i = 0; i < vd->n_choices; i++) {
            const plcvec_interpretation_info *info = &plcvec_interpretations[vd->choices[i].interpretation];
            add(t, "%s %s=%s", i ? "," : "", info->id, info->alternatives[vd->choices[i].alternative]);
        }
        add(t, "\n");
    }
    const plcvec_alternative *entry = vd->applied;
    for (size_t u = 0; entry && u < entry->n_unjudged; u++) {
        const plcvec_unjudged *un = &entry->unjudged[u];
        const plcvec_interpretation_info *info = &plcvec_interpretations[un->interpretation];
        int alt = plcvec_expect_offered(entry, un->interpretation);
        add(t, "    not judged under %s=%s:", info->id, alt >= 0 ? info->alternatives[alt] : "?");
        for (size_t d = 0; d < un->n_devices; d++)
            add(t, "%s %s", d ? "," : "", plcvec_device(un->devices[d])->name);
        add(t, "\n");
    }
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
    judgement_lines(&t, vd);
    field_lines(&t, vd);
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
