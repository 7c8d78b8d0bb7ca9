/* Running a selection of vectors and reporting it: the C counterpart of `plcvec verify`, with its
 * options, its environment variables, its exit statuses and its words. */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "guard.h"
#include "table.h"

/* The run's closing text, as verifiers/parity/TEXT.md states it for every runner: the skips by
 * reason, why a run without failures did not pass, then an empty line and the summary lines. */

typedef struct reason_count {
    const char *reason;
    size_t n;
} reason_count;

/* TEXT.md's order of every counted list (skip reasons, roll-up groups): the largest count first,
 * then the text in byte order. */
static int count_then_text(size_t n1, const char *s1, size_t n2, const char *s2)
{
    if (n1 != n2)
        return n1 > n2 ? -1 : 1;
    return strcmp(s1, s2);
}

static int by_count_then_reason(const void *a, const void *b)
{
    const reason_count *x = a, *y = b;
    return count_then_text(x->n, x->reason, y->n, y->reason);
}

#define SHOW_REASONS 12

static void skipped_lines(FILE *log, const char **reasons, size_t n_skipped, size_t selected)
{
    if (!n_skipped)
        return;
    reason_count *counts = malloc(n_skipped * sizeof *counts);
    if (!counts)
        return;
    size_t n = 0;
    for (size_t i = 0; i < n_skipped; i++) {
        size_t k = 0;
        while (k < n && strcmp(counts[k].reason, reasons[i]) != 0)
            k++;
        if (k == n)
            counts[n++] = (reason_count){reasons[i], 0};
        counts[k].n++;
    }
    qsort(counts, n, sizeof *counts, by_count_then_reason);
    /* s/n as a percentage to one decimal, rounded half up, in integers (the same in every language). */
    size_t t = (2000 * n_skipped + selected) / (2 * selected);
    fprintf(log, "SKIPPED %zu of %zu vectors (%zu.%zu%%):\n", n_skipped, selected, t / 10, t % 10);
    for (size_t k = 0; k < n && k < SHOW_REASONS; k++)
        fprintf(log, "    %6zu  %s\n", counts[k].n, counts[k].reason[0] ? counts[k].reason : "(no reason given)");
    if (n > SHOW_REASONS)
        fprintf(log, "    ... and %zu more reasons (--jsonl lists each vector)\n", n - SHOW_REASONS);
    free(counts);
}

static int by_interpretation_id(const void *a, const void *b)
{
    return strcmp(plcvec_interpretations[*(const int *)a].id, plcvec_interpretations[*(const int *)b].id);
}

static int by_string(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static void summary_lines(FILE *log, const plcvec_impl *impl, plcvec_judge *j, uint32_t families,
                          const plcvec_summary *sum, double seconds)
{
    fprintf(log, "\nplcvec: %s against the compiled-in vectors (suite %s, schema %s, spec sha256 %.12s)\n",
            impl->name ? impl->name : "(unnamed)", PLCVEC_SUITE_VERSION, PLCVEC_SCHEMA_VERSION, PLCVEC_SPEC_SHA256);
    int order[PLCVEC_INTERPRETATION_COUNT], n = 0;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (plcvec_interpretations[i].families & families)
            order[n++] = i;
    qsort(order, (size_t)n, sizeof *order, by_interpretation_id);
    fprintf(log, "interpretations:");
    for (int k = 0; k < n; k++) {
        int i = order[k], declared = 0;
        for (size_t c = 0; c < impl->n_choices; c++)
            declared |= impl->choices[c].interpretation == i;
        fprintf(log, "%s %s=%s (%s)", k ? "," : "", plcvec_interpretations[i].id,
                plcvec_interpretations[i].alternatives[plcvec_judge_alternative(j, i)], declared ? "declared" : "default");
    }
    fprintf(log, "%s\n", n ? "" : " (none)");
    size_t n_cpu = 0;
    while (impl->cpu_writes && impl->cpu_writes[n_cpu])
        n_cpu++;
    const char **cpu = n_cpu ? malloc(n_cpu * sizeof *cpu) : NULL;
    if (cpu) {
        memcpy(cpu, impl->cpu_writes, n_cpu * sizeof *cpu);
        qsort(cpu, n_cpu, sizeof *cpu, by_string);
        fprintf(log, "cpu_writes:");
        for (size_t k = 0; k < n_cpu; k++)
            fprintf(log, "%s %s", k ? "," : "", cpu[k]);
        fprintf(log, "\n");
        free(cpu);
    }
    /* The totals: pass, fail and skip always, the others when not 0, in the order of the statuses. */
    fprintf(log, "%zu vectors: %zu pass, %zu fail", sum->selected + sum->stale_unknown, sum->passed, sum->failed);
    if (sum->errors)
        fprintf(log, ", %zu error", sum->errors);
    fprintf(log, ", %zu skip", sum->skipped);
    if (sum->xfail)
        fprintf(log, ", %zu xfail", sum->xfail);
    if (sum->stale)
        fprintf(log, ", %zu stale", sum->stale);
    fprintf(log, " in %.2f s\n", seconds);
}

/* ---- the roll-up by reading (TEXT.md "The roll-up by reading", "The inference") ------------- */

typedef struct record {
    const plcvec_vector *v;
    uint8_t status;             /* the verdict's, known failures applied */
    uint8_t judged;             /* 1 pass, 2 fail (an xfail that failed counts as fail), 0 not judged */
    uint64_t passes;            /* a failing answer: the offered expectations it passes under */
} record;

/* The alternative offered expectation o gives interpretation i (-1: none). */
static int offered(const plcvec_vector *v, size_t o, int i)
{
    if (o == 0)
        return plcvec_interpretations[i].default_alternative;
    const plcvec_alternative *a = &v->alternatives[o - 1];
    for (size_t c = 0; c < a->n_choices; c++)
        if (a->choices[c].interpretation == i)
            return a->choices[c].alternative;
    return -1;
}

/* The offered expectation whose alternatives for the vector's interpretations are `choice`'s; -1 if none. */
static long offered_for(const plcvec_vector *v, const uint8_t *choice)
{
    for (size_t o = 0; o <= v->n_alternatives; o++) {
        if (o && v->alternatives[o - 1].n_expect != v->n_steps)
            continue;
        size_t i = 0;
        while (i < v->n_interpretations && offered(v, o, v->interpretations[i]) == choice[v->interpretations[i]])
            i++;
        if (i == v->n_interpretations)
            return (long)o;
    }
    return -1;
}

static const plcvec_expect *expect_of(const plcvec_vector *v, size_t o, size_t s)
{
    return o == 0 ? &v->steps[s].expect : &v->alternatives[o - 1].expect[s];
}

static void put_cell(plcvec_cell *state, size_t *n, const plcvec_cell *c)
{
    for (size_t i = 0; i < *n; i++)
        if (state[i].device == c->device) {
            state[i] = *c;
            return;
        }
    state[(*n)++] = *c;
}

/* Whether two offered expectations expect the same: every step's result and full state. */
static int same_expectation(const plcvec_vector *v, size_t a, size_t b)
{
    if (a == b)
        return 1;
    size_t cap = (size_t)v->n_devices + 1;
    for (size_t s = 0; s < v->n_steps; s++)
        cap += v->steps[s].n_set + expect_of(v, a, s)->n_devices + expect_of(v, b, s)->n_devices;
    plcvec_cell *x = malloc(2 * cap * sizeof *x), *y = x ? x + cap : NULL;
    if (!x)
        return 0;
    size_t nx = 0, ny = 0;
    int same = 1;
    for (size_t i = 0; i < v->n_devices; i++)
        x[nx++] = y[ny++] = v->devices[i];
    for (size_t s = 0; s < v->n_steps && same; s++) {
        const plcvec_expect *ea = expect_of(v, a, s), *eb = expect_of(v, b, s);
        for (size_t i = 0; i < v->steps[s].n_set; i++)
            put_cell(x, &nx, &v->steps[s].set[i]), put_cell(y, &ny, &v->steps[s].set[i]);
        for (size_t i = 0; i < ea->n_devices; i++)
            put_cell(x, &nx, &ea->devices[i]);
        for (size_t i = 0; i < eb->n_devices; i++)
            put_cell(y, &ny, &eb->devices[i]);
        same = ea->result == eb->result && nx == ny;
        for (size_t i = 0; i < nx && same; i++) {
            size_t k = 0;
            while (k < ny && y[k].device != x[i].device)
                k++;
            same = k < ny && y[k].type == x[i].type && y[k].value == x[i].value;
        }
    }
    free(x);
    return same;
}

/* Whether a judged vector passes under `choice` (its interpretations read from it). */
static int passes_under(const record *r, const uint8_t *choice, const uint8_t *followed)
{
    long o = offered_for(r->v, choice);
    if (o < 0)
        return 0;
    if (r->judged == 2)
        return o < 64 && (r->passes >> o & 1);
    long f = offered_for(r->v, followed);
    return f >= 0 && same_expectation(r->v, (size_t)o, (size_t)f);
}

/* A failure no offered reading explains: an error, or a failure that does not pass under the
 * inferred choice. Both passes over the records below ask the same question. */
static int unexplained(const record *rec, const uint8_t *choice, const uint8_t *followed)
{
    if (rec->status != PLCVEC_FAIL && rec->status != PLCVEC_ERROR)
        return 0;
    return !(rec->status == PLCVEC_FAIL && rec->judged == 2 && passes_under(rec, choice, followed));
}

/* The group key of an unexplained failure: the clauses it cites, ", "-joined (cut at `size`). */
static void clause_key(const record *rec, char *key, size_t size)
{
    size_t len = 0;
    key[0] = '\0';
    for (size_t c = 0; c < rec->v->n_clauses && len < size; c++)
        len += (size_t)snprintf(key + len, size - len, "%s%s", c ? ", " : "", plcvec_clause(rec->v, c));
    if (!rec->v->n_clauses)
        snprintf(key, size, "(no clauses)");
}


static size_t score(const record *recs, size_t n, const uint8_t *choice, const uint8_t *followed)
{
    size_t total = 0;
    for (size_t i = 0; i < n; i++)
        total += recs[i].judged && passes_under(&recs[i], choice, followed);
    return total;
}

typedef struct group {
    char key[1024];
    size_t n;
    const char **ids;
} group;

static int group_order(const void *a, const void *b)
{
    const group *x = a, *y = b;
    return count_then_text(x->n, x->key, y->n, y->key);
}

static int id_order(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static void rollup_lines(FILE *log, const record *recs, size_t n, const plcvec_judge *j)
{
    size_t failing = 0;
    for (size_t i = 0; i < n; i++)
        failing += recs[i].status == PLCVEC_FAIL || recs[i].status == PLCVEC_ERROR;
    if (!failing)
        return;
    uint8_t followed[PLCVEC_INTERPRETATION_COUNT], choice[PLCVEC_INTERPRETATION_COUNT];
    int touched[PLCVEC_INTERPRETATION_COUNT] = {0}, order[PLCVEC_INTERPRETATION_COUNT], n_order = 0;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        followed[i] = choice[i] = (uint8_t)plcvec_judge_alternative(j, i);
    for (size_t r = 0; r < n; r++)
        for (size_t k = 0; recs[r].judged && k < recs[r].v->n_interpretations; k++)
            touched[recs[r].v->interpretations[k]] = 1;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (touched[i])
            order[n_order++] = i;
    qsort(order, (size_t)n_order, sizeof *order, by_interpretation_id);
    /* The choice: one interpretation at a time, in id order, to the first best alternative when it
     * is strictly better, until a round changes nothing. */
    size_t current = score(recs, n, choice, followed);
    for (int changed = 1; changed;) {
        changed = 0;
        for (int k = 0; k < n_order; k++) {
            int i = order[k], keep = choice[i], best_alt = -1;
            size_t best = 0;
            for (int a = 0; a < plcvec_interpretations[i].n_alternatives; a++) {
                if (a == keep)
                    continue;
                choice[i] = (uint8_t)a;
                size_t sc = score(recs, n, choice, followed);
                if (best_alt < 0 || sc > best)
                    best = sc, best_alt = a;
            }
            choice[i] = (uint8_t)keep;
            if (best_alt >= 0 && best > current) {
                choice[i] = (uint8_t)best_alt;
                current = best;
                changed = 1;
            }
        }
    }
    group *groups = calloc(n + 1, sizeof *groups);
    const char **ids = malloc((n + 1) * sizeof *ids);
    if (!groups || !ids) {
        free(groups);
        free(ids);
        return;
    }
    size_t explained = 0, broken = 0, n_groups = 0, used = 0;
    /* Explained: the failing vectors that pass under the choice, each in the group of its smallest change. */
    for (size_t r = 0; r < n; r++) {
        const record *rec = &recs[r];
        if (rec->judged == 1 && !passes_under(rec, choice, followed))
            broken++;
        if (rec->status != PLCVEC_FAIL || rec->judged != 2 || !passes_under(rec, choice, followed))
            continue;
        int differ[64], nd = 0;
        for (size_t k = 0; k < rec->v->n_interpretations; k++) {
            int i = rec->v->interpretations[k];
            if (choice[i] != followed[i] && nd < 64)
                differ[nd++] = i;
        }
        qsort(differ, (size_t)nd, sizeof *differ, by_interpretation_id);
        /* Subsets by size, each size in lexicographic order of positions (itertools.combinations). */
        unsigned long best = 0;
        int found = 0;
        for (int size = 1; size <= nd && !found && nd < 20; size++) {
            int pick[20];
            for (int q = 0; q < size; q++)
                pick[q] = q;
            for (;;) {
                uint8_t trial[PLCVEC_INTERPRETATION_COUNT];
                memcpy(trial, followed, sizeof trial);
                unsigned long mask = 0;
                for (int q = 0; q < size; q++)
                    trial[differ[pick[q]]] = choice[differ[pick[q]]], mask |= 1ul << pick[q];
                if (passes_under(rec, trial, followed)) {
                    best = mask, found = 1;
                    break;
                }
                int q = size - 1;
                while (q >= 0 && pick[q] == nd - size + q)
                    q--;
                if (q < 0)
                    break;
                pick[q]++;
                for (int w = q + 1; w < size; w++)
                    pick[w] = pick[w - 1] + 1;
            }
        }
        char key[1024] = "";
        size_t len = 0;
        for (int q = 0; q < nd; q++)
            if (best >> q & 1)
                len += (size_t)snprintf(key + len, len < sizeof key ? sizeof key - len : 0, "%s%s=%s", len ? ", " : "",
                                        plcvec_interpretations[differ[q]].id,
                                        plcvec_interpretations[differ[q]].alternatives[choice[differ[q]]]);
        size_t g = 0;
        while (g < n_groups && strcmp(groups[g].key, key) != 0)
            g++;
        if (g == n_groups) {
            snprintf(groups[g].key, sizeof groups[g].key, "%s", key);
            n_groups++;
        }
        groups[g].n++;
        explained++;
    }
    if (explained) {
        qsort(groups, n_groups, sizeof *groups, group_order);
        fprintf(log, "READINGS: %zu of %zu failing vectors pass under other alternatives:\n", explained, failing);
        for (size_t g = 0; g < n_groups; g++)
            fprintf(log, "    %6zu  %s\n", groups[g].n, groups[g].key);
        fprintf(log, "    declare:");
        for (int k = 0; k < n_order; k++)
            if (choice[order[k]] != followed[order[k]])
                fprintf(log, " --choose %s=%s", plcvec_interpretations[order[k]].id,
                        plcvec_interpretations[order[k]].alternatives[choice[order[k]]]);
        fprintf(log, "\n");
        if (broken)
            fprintf(log, "    (so declared, %zu vectors that pass now would fail)\n", broken);
    }
    /* The rest, grouped by the clauses they cite. */
    if (explained < failing) {
        memset(groups, 0, (n + 1) * sizeof *groups);
        n_groups = 0;
        for (size_t r = 0; r < n; r++) {
            const record *rec = &recs[r];
            if (!unexplained(rec, choice, followed))
                continue;
            char key[1024];
            clause_key(rec, key, sizeof key);
            size_t g = 0;
            while (g < n_groups && strcmp(groups[g].key, key) != 0)
                g++;
            if (g == n_groups) {
                snprintf(groups[g].key, sizeof groups[g].key, "%s", key);
                n_groups++;
            }
            groups[g].n++;      /* counted first; the ids go in each group's own slice below */
        }
        /* Second pass: fill the ids, each group in its own slice. */
        used = 0;
        for (size_t g = 0; g < n_groups; g++) {
            groups[g].ids = ids + used;
            used += groups[g].n;
            groups[g].n = 0;
        }
        for (size_t r = 0; r < n; r++) {
            const record *rec = &recs[r];
            if (!unexplained(rec, choice, followed))
                continue;
            char key[1024];
            clause_key(rec, key, sizeof key);
            size_t g = 0;
            while (strcmp(groups[g].key, key) != 0)
                g++;
            groups[g].ids[groups[g].n++] = rec->v->id;
        }
        qsort(groups, n_groups, sizeof *groups, group_order);
        fprintf(log, "NOT EXPLAINED by any reading: %zu failing vectors, by the clauses they cite:\n", failing - explained);
        for (size_t g = 0; g < n_groups; g++) {
            fprintf(log, "    %6zu  %s\n", groups[g].n, groups[g].key);
            qsort(groups[g].ids, groups[g].n, sizeof *groups[g].ids, id_order);
            for (size_t k = 0; k < groups[g].n && k < 5; k++)
                fprintf(log, "            %s\n", groups[g].ids[k]);
            if (groups[g].n > 5)
                fprintf(log, "            ... and %zu more\n", groups[g].n - 5);
        }
    }
    free(groups);
    free(ids);
}

static double now_s(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

int plcvec_run(const plcvec_impl *impl, const plcvec_options *opt, plcvec_summary *summary)
{
    static const plcvec_options none;
    if (!opt)
        opt = &none;
    FILE *log = opt->log ? opt->log : stdout;
    plcvec_summary sum = {0};
    char err[1024];
    const plcvec_vector **list = NULL;
    long n = plcvec_select(&opt->selection, &list, err, sizeof err);
    if (n < 0) {
        fprintf(log, "plcvec: %s\n", err);
        return PLCVEC_EXIT_USAGE;
    }
    if (n == 0) {
        fprintf(log, "NOT PASSED (exit 5): no vector selected: the selection matches nothing (an empty selection never "
                     "passes)\n");
        free(list);
        return PLCVEC_EXIT_NOTHING_TESTED;
    }
    plcvec_judge *j = plcvec_judge_new(impl, err, sizeof err);
    if (!j) {
        fprintf(log, "plcvec: %s\n", err);
        free(list);
        return PLCVEC_EXIT_USAGE;
    }
    double started = now_s();
    uint32_t families = 0;
    for (long i = 0; i < n; i++)
        families |= 1u << list[i]->family;
    /* Nothing of the run is left in a buffer while an implementation runs: a crash, an exit() or
     * the watchdog inside it ends the process without flushing stdio. */
    fflush(log);
    record *recs = calloc((size_t)n, sizeof *recs);
    const char **skip_reasons = malloc((size_t)n * sizeof *skip_reasons);
    char *reason_text = malloc((size_t)n * sizeof ((plcvec_verdict *)0)->message);
    if (!skip_reasons || !reason_text || !recs) {
        free(recs);
        free(skip_reasons);
        free(reason_text);
        plcvec_judge_free(j);
        free(list);
        fprintf(log, "plcvec: out of memory\n");
        return PLCVEC_EXIT_USAGE;
    }
    sum.selected = (size_t)n;
    const char **failing = opt->write_expectations ? malloc((size_t)n * sizeof *failing) : NULL;
    size_t n_failing = 0;
    if (opt->write_expectations && !failing) {
        fprintf(log, "plcvec: %s: out of memory\n", opt->write_expectations);
        plcvec_judge_free(j);
        free(list);
        return PLCVEC_EXIT_USAGE;
    }
    for (long i = 0; i < n; i++) {
        plcvec_verdict vd = *plcvec_judge_vector(j, list[i]);
        recs[i].v = list[i];
        recs[i].judged = vd.status == PLCVEC_PASS ? 1 : vd.status == PLCVEC_FAIL ? 2 : 0;
        recs[i].passes = vd.offered_passes;
        plcvec_apply_known(&vd, opt->known, opt->n_known);
        recs[i].status = (uint8_t)vd.status;
        switch (vd.status) {
        case PLCVEC_PASS: sum.passed++; break;
        case PLCVEC_FAIL: sum.failed++; break;
        case PLCVEC_ERROR: sum.errors++; break;
        case PLCVEC_SKIP:
            /* The reason, kept for the skips by reason (the verdict's text is reused next vector). */
            skip_reasons[sum.skipped] = memcpy(reason_text + sum.skipped * sizeof vd.message, vd.message, sizeof vd.message);
            sum.skipped++;
            break;
        case PLCVEC_XFAIL: sum.xfail++; break;
        case PLCVEC_STALE: sum.stale++; break;
        }
        if (failing && (vd.status == PLCVEC_FAIL || vd.status == PLCVEC_ERROR || vd.status == PLCVEC_XFAIL))
            failing[n_failing++] = list[i]->id;
        if (vd.status == PLCVEC_FAIL || vd.status == PLCVEC_ERROR || vd.status == PLCVEC_STALE ||
            (opt->verbose && (vd.status == PLCVEC_SKIP || vd.status == PLCVEC_XFAIL))) {
            plcvec_print_verdict(log, &vd);
            fflush(log);
        }
    }
    for (size_t k = 0; k < opt->n_known; k++)
        if (!opt->known[k].id || !plcvec_find(opt->known[k].id)) {
            fprintf(log, "STALE %s\n    listed as a known failure (%s) but the suite has no such vector; remove it\n",
                    opt->known[k].id ? opt->known[k].id : "(null)", opt->known[k].reason ? opt->known[k].reason : "");
            sum.stale++;
            sum.stale_unknown++;
        }
    size_t bad = sum.failed + sum.errors + sum.stale;
    int rc = bad ? PLCVEC_EXIT_FAILED : sum.passed == 0 ? PLCVEC_EXIT_NOTHING_TESTED : PLCVEC_EXIT_PASSED;
    rollup_lines(log, recs, (size_t)n, j);
    skipped_lines(log, skip_reasons, sum.skipped, sum.selected);
    if (rc == PLCVEC_EXIT_NOTHING_TESTED) {
        fprintf(log, "NOT PASSED (exit 5): nothing passed (");
        if (sum.skipped)
            fprintf(log, "%zu skipped%s", sum.skipped, sum.xfail ? ", " : "");
        if (sum.xfail)
            fprintf(log, "%zu known failures", sum.xfail);
        fprintf(log, "): the run proves nothing\n");
    }
    summary_lines(log, impl, j, families, &sum, now_s() - started);
    free(recs);
    free(skip_reasons);
    free(reason_text);
    plcvec_judge_free(j);
    free(list);
    if (opt->write_expectations) {
        if (plcvec_known_write(opt->write_expectations, failing, n_failing, "not yet triaged", err, sizeof err)) {
            fprintf(log, "plcvec: %s\n", err);
            rc = PLCVEC_EXIT_USAGE;
        } else
            fprintf(log, "plcvec: %zu known failures written to %s\n", n_failing, opt->write_expectations);
    }
    free(failing);
    fflush(log);
    if (summary)
        *summary = sum;
    return rc;
}

/* ---- plcvec_main: the options and variables of `plcvec verify` ------------------------------ */

static void usage(FILE *f, const char *prog)
{
    fprintf(f,
            "usage: %s [--family F] [--instruction I] [--tag T] [--id GLOB] [--interpretation ID]\n"
            "          [--shard K/N] [--choose ID=ALT] [--expectations FILE] [--write-expectations FILE]\n"
            "          [--list] [--verbose]\n"
            "Judge the compiled-in plcvec vectors (filters repeat: OR within one, AND between them).\n"
            "Each option defaults to its variable: PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG, PLCVEC_ID,\n"
            "PLCVEC_INTERPRETATION (comma-separated), PLCVEC_SHARD, PLCVEC_KNOWN_FAILURES,\n"
            "PLCVEC_WRITE_EXPECTATIONS; PLCVEC_TIMEOUT bounds each vector (seconds, default 10).\n"
            "Exit 0 passed, 1 failures, 2 usage error, 5 nothing tested.\n",
            prog);
}

enum { F_FAMILY, F_INSTRUCTION, F_TAG, F_ID, F_INTERPRETATION, N_FILTERS };
static const char *const filter_flags[N_FILTERS] = {"--family", "--instruction", "--tag", "--id", "--interpretation"};
static const char *const filter_vars[N_FILTERS] = {"PLCVEC_FAMILY", "PLCVEC_INSTRUCTION", "PLCVEC_TAG", "PLCVEC_ID",
                                                  "PLCVEC_INTERPRETATION"};

typedef struct cli {
    const char *prog;
    const char **lists[N_FILTERS];
    size_t counts[N_FILTERS], caps[N_FILTERS];
    char *env_copy[N_FILTERS];
    plcvec_choice *choices;
    size_t n_choices;
} cli;

static int push(cli *c, int l, const char *name)
{
    if (c->counts[l] == c->caps[l]) {
        size_t cap = c->caps[l] ? c->caps[l] * 2 : 8;
        const char **grown = realloc(c->lists[l], cap * sizeof *grown);
        if (!grown)
            return -1;
        c->lists[l] = grown, c->caps[l] = cap;
    }
    c->lists[l][c->counts[l]++] = name;
    return 0;
}

/* PLCVEC_FAMILY=a,b: the names, split in place of a copy. An empty item is a mistake, not "no
 * filter": `PLCVEC_FAMILY=,` must not run everything. */
static int from_environment(cli *c, int l, char *err, size_t errlen)
{
    const char *text = getenv(filter_vars[l]);
    if (!text)
        return 0;
    size_t len = strlen(text);
    char *copy = c->env_copy[l] = malloc(len + 1);
    if (!copy) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(copy, text, len + 1);
    for (char *item = copy;;) {
        char *comma = strchr(item, ',');
        if (comma)
            *comma = '\0';
        char *end = item + strlen(item);
        while (*item == ' ')
            item++;
        while (end > item && end[-1] == ' ')
            *--end = '\0';
        if (!*item) {
            snprintf(err, errlen, "%s=%s: an empty name (the variable takes comma-separated names; unset it to select "
                                  "everything)", filter_vars[l], text);
            return -1;
        }
        if (push(c, l, item)) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        if (!comma)
            break;
        item = comma + 1;
    }
    return 0;
}

static int parse_shard(const char *what, const char *text, plcvec_selection *sel, char *err, size_t errlen)
{
    unsigned k, n;
    char tail;
    if (sscanf(text, "%u/%u%c", &k, &n, &tail) != 2 || strchr(text, '-') || strchr(text, ' ')) {
        snprintf(err, errlen, "%s takes K/N (e.g. 2/4), got '%s'", what, text);
        return -1;
    }
    if (k < 1 || k > n) {
        snprintf(err, errlen, "%s %s: K must be between 1 and N", what, text);
        return -1;
    }
    sel->shard_k = k, sel->shard_n = n;
    return 0;
}

/* What the variables every plcvec runner reads say, for a runner of its own (GoogleTest). */
static int environment_checks(char *err, size_t errlen)
{
    if (getenv("PLCVEC_VECTORS")) {
        snprintf(err, errlen, "PLCVEC_VECTORS=%s: the C library's vectors are compiled in; export that folder into a "
                              "copy of the library (plcvec export --lang c --vectors DIR --root COPY) and build the copy "
                              "(README.md, \"The vectors in the library\")", getenv("PLCVEC_VECTORS"));
        return -1;
    }
    return plcvec_timeout_ms(err, errlen) < 0 ? -1 : 0;
}

static void selection_of(const cli *c, plcvec_selection *sel)
{
    sel->families = c->lists[F_FAMILY], sel->n_families = c->counts[F_FAMILY];
    sel->instructions = c->lists[F_INSTRUCTION], sel->n_instructions = c->counts[F_INSTRUCTION];
    sel->tags = c->lists[F_TAG], sel->n_tags = c->counts[F_TAG];
    sel->ids = c->lists[F_ID], sel->n_ids = c->counts[F_ID];
    sel->interpretations = c->lists[F_INTERPRETATION], sel->n_interpretations = c->counts[F_INTERPRETATION];
}

static void cli_free(cli *c)
{
    for (int l = 0; l < N_FILTERS; l++) {
        free(c->lists[l]);
        free(c->env_copy[l]);
    }
    free(c->choices);
}

long plcvec_select_from_environment(const char *family, const plcvec_vector ***out, char *err, size_t errlen)
{
    cli c = {0};
    plcvec_selection sel = {0};
    *out = NULL;
    long n = -1;
    int l = 0;
    while (l < N_FILTERS && from_environment(&c, l, err, errlen) == 0)
        l++;
    const char *shard = getenv("PLCVEC_SHARD");
    if (l == N_FILTERS && (!shard || parse_shard("PLCVEC_SHARD", shard, &sel, err, errlen) == 0) &&
        environment_checks(err, errlen) == 0) {
        selection_of(&c, &sel);
        n = plcvec_select(&sel, out, err, errlen);
    }
    if (n >= 0 && family) {
        int f = 0;
        while (f < PLCVEC_FAMILY_COUNT && strcmp(plcvec_family_names[f], family) != 0)
            f++;
        if (f == PLCVEC_FAMILY_COUNT) {
            snprintf(err, errlen, "unknown family '%s': the suite has no such family", family);
            free(*out);
            *out = NULL;
            n = -1;
        } else {
            long k = 0;
            for (long i = 0; i < n; i++)
                if ((int)(*out)[i]->family == f)
                    (*out)[k++] = (*out)[i];
            n = k;
        }
    }
    cli_free(&c);
    return n;
}

static int parse_choice(cli *c, const char *text)
{
    const char *eq = strchr(text, '=');
    char id[96];
    snprintf(id, sizeof id, "%.*s", eq ? (int)(eq - text < 90 ? eq - text : 90) : 90, text);
    int interp = eq ? plcvec_interpretation_named(id) : -1;
    if (interp < 0) {
        fprintf(stderr, "%s: --choose %s: %s; known:", c->prog, text,
                eq ? "no such interpretation" : "takes INTERPRETATION=ALTERNATIVE");
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            fprintf(stderr, "%s %s", i ? "," : "", plcvec_interpretations[i].id);
        fprintf(stderr, "\n");
        return -1;
    }
    int alt = plcvec_alternative_named(interp, eq + 1);
    if (alt < 0) {
        const plcvec_interpretation_info *info = &plcvec_interpretations[interp];
        fprintf(stderr, "%s: --choose %s: %s has no alternative '%s'; known:", c->prog, text, info->id, eq + 1);
        for (int a = 0; a < info->n_alternatives; a++)
            fprintf(stderr, "%s %s", a ? "," : "", info->alternatives[a]);
        fprintf(stderr, "\n");
        return -1;
    }
    plcvec_choice *grown = realloc(c->choices, (c->n_choices + 1) * sizeof *grown);
    if (!grown)
        return -1;
    c->choices = grown;
    c->choices[c->n_choices].interpretation = (uint8_t)interp;
    c->choices[c->n_choices++].alternative = (uint8_t)alt;
    return 0;
}

int plcvec_main(const plcvec_impl *impl, const plcvec_known_failure *known, size_t n_known, int argc, char **argv)
{
    cli c = {0};
    c.prog = argc > 0 ? argv[0] : "plcvec";
    plcvec_options opt = {0};
    int list_only = 0, rc = 0, given[N_FILTERS] = {0}, shard_flag = 0;
    const char *expectations = NULL, *shard = NULL;
    plcvec_known_failure *file_known = NULL, *all_known = NULL;
    size_t n_file_known = 0;
    char err[1024] = "";
    for (int i = 1; i < argc && !rc; i++) {
        const char *a = argv[i];
        int l = 0;
        while (l < N_FILTERS && strcmp(a, filter_flags[l]) != 0)
            l++;
        int takes_value = l < N_FILTERS || !strcmp(a, "--shard") || !strcmp(a, "--choose") ||
                          !strcmp(a, "--expectations") || !strcmp(a, "--write-expectations");
        if (takes_value && i + 1 >= argc) {
            fprintf(stderr, "%s: %s needs a value\n", c.prog, a);
            rc = 2;
        } else if (l < N_FILTERS) {
            given[l] = 1;
            rc = push(&c, l, argv[++i]) ? 2 : 0;
        } else if (!strcmp(a, "--shard"))
            shard = argv[++i];
        else if (!strcmp(a, "--choose"))
            rc = parse_choice(&c, argv[++i]) ? 2 : 0;
        else if (!strcmp(a, "--expectations"))
            expectations = argv[++i];
        else if (!strcmp(a, "--write-expectations"))
            opt.write_expectations = argv[++i];
        else if (!strcmp(a, "--list"))
            list_only = 1;
        else if (!strcmp(a, "--verbose") || !strcmp(a, "-v"))
            opt.verbose = 1;
        else if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout, c.prog);
            goto done;
        } else {
            fprintf(stderr, "%s: unknown argument '%s'\n", c.prog, a);
            usage(stderr, c.prog);
            rc = 2;
        }
    }
    /* The variables are the options' defaults: a CI matrix or a shared job sets them once for
     * every runner of every language. */
    for (int l = 0; l < N_FILTERS && !rc; l++)
        if (!given[l] && from_environment(&c, l, err, sizeof err))
            rc = 2;
    if (!rc && environment_checks(err, sizeof err))
        rc = 2;
    if (!rc && (shard || (shard = getenv("PLCVEC_SHARD")) != NULL))
        rc = parse_shard(shard_flag ? "--shard" : "PLCVEC_SHARD", shard, &opt.selection, err, sizeof err) ? 2 : 0;
    if (!rc && !opt.write_expectations)
        opt.write_expectations = getenv("PLCVEC_WRITE_EXPECTATIONS");
    if (!rc && !expectations)
        expectations = getenv("PLCVEC_KNOWN_FAILURES");
    if (!rc && expectations && plcvec_known_load(expectations, &file_known, &n_file_known, err, sizeof err))
        rc = 2;
    if (rc) {
        if (err[0])
            fprintf(stderr, "%s: %s\n", c.prog, err);
        goto done;
    }
    /* The list in code and the file's entries together. */
    all_known = malloc((n_known + n_file_known + 1) * sizeof *all_known);
    if (!all_known) {
        rc = 2;
        goto done;
    }
    if (n_known)
        memcpy(all_known, known, n_known * sizeof *known);
    if (n_file_known)
        memcpy(all_known + n_known, file_known, n_file_known * sizeof *file_known);
    opt.known = all_known;
    opt.n_known = n_known + n_file_known;
    selection_of(&c, &opt.selection);
    if (list_only) {
        const plcvec_vector **sel = NULL;
        long n = plcvec_select(&opt.selection, &sel, err, sizeof err);
        if (n < 0) {
            fprintf(stderr, "%s: %s\n", c.prog, err);
            rc = 2;
        }
        for (long i = 0; i < n; i++)
            printf("%s\n", sel[i]->id);
        free(sel);
    } else {
        /* --choose on the command line declares on top of what the implementation declares. */
        plcvec_impl run_impl = *impl;
        plcvec_choice *merged = NULL;
        if (c.n_choices) {
            merged = malloc((impl->n_choices + c.n_choices) * sizeof *merged);
            if (!merged) {
                rc = 2;
                goto done;
            }
            if (impl->n_choices)
                memcpy(merged, impl->choices, impl->n_choices * sizeof *merged);
            memcpy(merged + impl->n_choices, c.choices, c.n_choices * sizeof *merged);
            run_impl.choices = merged;
            run_impl.n_choices = impl->n_choices + c.n_choices;
        }
        rc = plcvec_run(&run_impl, &opt, NULL);
        free(merged);
    }
done:
    cli_free(&c);
    free(all_known);
    plcvec_known_free(file_known, n_file_known);
    return rc;
}
