/* The closing lines of a run's text, as verifiers/parity/TEXT.md states them for every runner: the
 * skips by reason, why a run without failures did not pass, then an empty line and the summary
 * lines (what the run was made against, every alternative followed, the declared CPU writes, the
 * totals). */
#include <stdlib.h>
#include <string.h>

#include "judge.h"
#include "reports.h"

#define SHOW_REASONS 12

typedef struct reason_count {
    const char *reason;
    size_t n;
} reason_count;

/* TEXT.md's order of a counted list: the largest count first, then the text in byte order. */
static int by_count_then_reason(const void *a, const void *b)
{
    const reason_count *x = a, *y = b;
    if (x->n != y->n)
        return x->n > y->n ? -1 : 1;
    return strcmp(x->reason, y->reason);
}

void plcvec_skipped_lines(FILE *log, const char *const *reasons, size_t n_skipped, size_t selected)
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

void plcvec_not_passed_line(FILE *log, const plcvec_summary *sum)
{
    if (!sum->selected) {
        fprintf(log, "NOT PASSED (exit 5): no vector selected: the selection matches nothing (an empty selection "
                     "never passes)\n");
        return;
    }
    fprintf(log, "NOT PASSED (exit 5): nothing passed (");
    if (sum->skipped)
        fprintf(log, "%zu skipped%s", sum->skipped, sum->xfail ? ", " : "");
    if (sum->xfail)
        fprintf(log, "%zu known failures", sum->xfail);
    fprintf(log, "): the run proves nothing\n");
}

static int by_interpretation_id(const void *a, const void *b)
{
    return strcmp(plcvec_interpretations[*(const int *)a].id, plcvec_interpretations[*(const int *)b].id);
}

static int by_string(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* `interpretations: ID=alt (declared|default), ...` of the families run. */
static void interpretations_line(FILE *log, const plcvec_judge *j, uint32_t families)
{
    const plcvec_impl *impl = plcvec_judge_impl(j);
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
}

static void cpu_writes_line(FILE *log, const char *const *cpu_writes)
{
    size_t n = 0;
    while (cpu_writes && cpu_writes[n])
        n++;
    const char **sorted = n ? malloc(n * sizeof *sorted) : NULL;
    if (!sorted)
        return;
    memcpy(sorted, cpu_writes, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, by_string);
    fprintf(log, "cpu_writes:");
    for (size_t k = 0; k < n; k++)
        fprintf(log, "%s %s", k ? "," : "", sorted[k]);
    fprintf(log, "\n");
    free(sorted);
}

void plcvec_summary_lines(FILE *log, const plcvec_judge *j, uint32_t families, const plcvec_summary *sum,
                          double seconds)
{
    const plcvec_impl *impl = plcvec_judge_impl(j);
    fprintf(log, "\nplcvec: %s against the compiled-in vectors (suite %s, schema %s, spec sha256 %.12s)\n",
            impl->name ? impl->name : "(unnamed)", PLCVEC_SUITE_VERSION, PLCVEC_SCHEMA_VERSION, PLCVEC_SPEC_SHA256);
    interpretations_line(log, j, families);
    cpu_writes_line(log, impl->cpu_writes);
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
