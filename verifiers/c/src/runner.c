/* Running a selection and keeping its record: the C counterpart of `plcvec verify`'s run, with its
 * exit statuses and its words (the failure blocks as each vector is judged, then the end of the
 * run). plcvec_report is the record any runner keeps, plcvec_run's and the GoogleTest pattern's. */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "files.h"
#include "infer.h"
#include "judge.h"
#include "known.h"
#include "reports.h"
#include "rollup.h"
#include "settings.h"

struct plcvec_report {
    const plcvec_judge *judge;
    plcvec_judged *judged;
    size_t n, cap;
    char **skip_reasons;        /* one per skipped vector, kept for the skips by reason */
    plcvec_summary sum;
    uint32_t families;          /* of the vectors run (bit f): their interpretations are listed */
};

plcvec_report *plcvec_report_new(const plcvec_judge *j)
{
    plcvec_report *r = calloc(1, sizeof *r);
    if (r)
        r->judge = j;
    return r;
}

void plcvec_report_free(plcvec_report *r)
{
    if (!r)
        return;
    for (size_t i = 0; i < r->sum.skipped; i++)
        free(r->skip_reasons[i]);
    free(r->skip_reasons);
    free(r->judged);
    free(r);
}

/* What the inference judges of a verdict (TEXT.md, "The inference", step 2): a pass, a fail (a
 * known failure with differing fields failed), or nothing (an error, a skip, a stale entry). */
static uint8_t answer_of(const plcvec_verdict *vd)
{
    switch (vd->status) {
    case PLCVEC_PASS: return PLCVEC_ANSWER_PASSED;
    case PLCVEC_FAIL: return PLCVEC_ANSWER_FAILED;
    case PLCVEC_XFAIL: return vd->n_problems ? PLCVEC_ANSWER_FAILED : PLCVEC_ANSWER_NONE;
    default: return PLCVEC_ANSWER_NONE;
    }
}

static int count(plcvec_summary *sum, const plcvec_verdict *vd, char **skip_reasons)
{
    switch (vd->status) {
    case PLCVEC_PASS: sum->passed++; break;
    case PLCVEC_FAIL: sum->failed++; break;
    case PLCVEC_ERROR: sum->errors++; break;
    case PLCVEC_XFAIL: sum->xfail++; break;
    case PLCVEC_STALE: sum->stale++; break;
    case PLCVEC_SKIP: {
        size_t len = strlen(vd->message);
        char *reason = malloc(len + 1);
        if (!reason)
            return -1;
        skip_reasons[sum->skipped++] = memcpy(reason, vd->message, len + 1);
        break;
    }
    }
    sum->selected++;
    return 0;
}

int plcvec_report_add(plcvec_report *r, const plcvec_verdict *vd)
{
    if (!vd->vector)
        return 0;
    if (r->n == r->cap) {
        size_t cap = r->cap ? r->cap * 2 : 256;
        plcvec_judged *judged = realloc(r->judged, cap * sizeof *judged);
        char **reasons = judged ? realloc(r->skip_reasons, cap * sizeof *reasons) : NULL;
        if (judged)
            r->judged = judged;
        if (!reasons)
            return -1;
        r->skip_reasons = reasons;
        r->cap = cap;
    }
    r->judged[r->n++] = (plcvec_judged){vd->vector, (uint8_t)vd->status, answer_of(vd), vd->offered_passes};
    r->families |= UINT32_C(1) << vd->vector->family;
    return count(&r->sum, vd, r->skip_reasons);
}

/* A STALE block for each known failure that names no vector of the suite, in the list's order. */
static void unknown_ids(FILE *log, plcvec_summary *sum, const plcvec_known_failure *known, size_t n_known)
{
    for (size_t k = 0; k < n_known; k++) {
        if (known[k].id && plcvec_find(known[k].id))
            continue;
        char message[1024];
        plcvec_known_unknown_message(&known[k], message, sizeof message);
        fprintf(log, "STALE %s\n    %s\n", known[k].id ? known[k].id : "(no id)", message);
        sum->stale++;
        sum->stale_unknown++;
    }
}

int plcvec_report_end(plcvec_report *r, FILE *log, const plcvec_known_failure *known, size_t n_known, double seconds)
{
    unknown_ids(log, &r->sum, known, n_known);
    const plcvec_summary *sum = &r->sum;
    int rc = sum->failed + sum->errors + sum->stale ? PLCVEC_EXIT_FAILED
             : sum->passed == 0                     ? PLCVEC_EXIT_NOTHING_TESTED
                                                    : PLCVEC_EXIT_PASSED;
    uint8_t followed[PLCVEC_INTERPRETATION_COUNT];
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        followed[i] = (uint8_t)plcvec_judge_alternative(r->judge, i);
    if (plcvec_rollup_lines(log, r->judged, r->n, followed, known, n_known) != 0)
        fprintf(log, "plcvec: out of memory: the roll-up by reading is left out\n");
    plcvec_skipped_lines(log, (const char *const *)r->skip_reasons, sum->skipped, sum->selected);
    if (rc == PLCVEC_EXIT_NOTHING_TESTED)
        plcvec_not_passed_line(log, sum);
    plcvec_summary_lines(log, r->judge, r->families, sum, seconds);
    fflush(log);
    return rc;
}

static double now_s(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

/* Judge each vector of `list` into the report, printing each failure's block as it is judged. */
static int judge_all(plcvec_judge *j, plcvec_report *report, const plcvec_vector **list, long n,
                     const plcvec_options *opt, FILE *log, const char **failing, size_t *n_failing)
{
    for (long i = 0; i < n; i++) {
        plcvec_verdict vd = *plcvec_judge_vector(j, list[i]);
        plcvec_known_apply(&vd, opt->known, opt->n_known);
        if (plcvec_report_add(report, &vd) != 0)
            return -1;
        if (failing && (vd.status == PLCVEC_FAIL || vd.status == PLCVEC_ERROR || vd.status == PLCVEC_XFAIL))
            failing[(*n_failing)++] = list[i]->id;
        if (vd.status == PLCVEC_FAIL || vd.status == PLCVEC_ERROR || vd.status == PLCVEC_STALE ||
            (opt->verbose && (vd.status == PLCVEC_SKIP || vd.status == PLCVEC_XFAIL))) {
            plcvec_print_verdict(log, &vd);
            fflush(log);    /* nothing left in a buffer while an implementation runs: it may end the process */
        }
    }
    return 0;
}

static int write_expectations(FILE *log, const char *path, const char **failing, size_t n_failing)
{
    char err[1024];
    if (plcvec_known_write(path, failing, n_failing, "not yet triaged", err, sizeof err)) {
        fprintf(log, "plcvec: %s\n", err);
        return PLCVEC_EXIT_USAGE;
    }
    fprintf(log, "plcvec: %zu known failures written to %s\n", n_failing, path);
    return 0;
}

/* The run of a selection that holds vectors, by a judge made for it. */
static int run_selected(plcvec_judge *j, const plcvec_vector **list, long n, const plcvec_options *opt, FILE *log,
                        plcvec_summary *summary)
{
    plcvec_report *report = plcvec_report_new(j);
    const char **failing = opt->write_expectations ? malloc((size_t)n * sizeof *failing) : NULL;
    size_t n_failing = 0;
    double started = now_s();
    fflush(log);
    int rc;
    if (!report || (opt->write_expectations && !failing) ||
        judge_all(j, report, list, n, opt, log, failing, &n_failing) != 0) {
        fprintf(log, "plcvec: out of memory\n");
        rc = PLCVEC_EXIT_USAGE;
    } else {
        rc = plcvec_report_end(report, log, opt->known, opt->n_known, now_s() - started);
        if (opt->write_expectations && write_expectations(log, opt->write_expectations, failing, n_failing))
            rc = PLCVEC_EXIT_USAGE;
        if (summary)
            *summary = report->sum;
    }
    fflush(log);
    free(failing);
    plcvec_report_free(report);
    return rc;
}

int plcvec_run(const plcvec_impl *impl, const plcvec_options *opt, plcvec_summary *summary)
{
    static const plcvec_options none;
    opt = opt ? opt : &none;
    FILE *log = opt->log ? opt->log : stdout;
    char err[1024];
    const plcvec_vector **list = NULL;
    plcvec_settings_warn();
    long n = plcvec_select(&opt->selection, &list, err, sizeof err);
    plcvec_judge *j = n > 0 ? plcvec_judge_new(impl, err, sizeof err) : NULL;
    int rc;
    if (n < 0 || (n > 0 && !j) ||
        (opt->write_expectations && plcvec_file_check(opt->write_expectations, err, sizeof err) != 0)) {
        fprintf(log, "plcvec: %s\n", err);
        rc = PLCVEC_EXIT_USAGE;
    } else if (n == 0) {
        plcvec_summary empty = {0};
        plcvec_not_passed_line(log, &empty);
        rc = PLCVEC_EXIT_NOTHING_TESTED;
    } else
        rc = run_selected(j, list, n, opt, log, summary);
    plcvec_judge_free(j);
    free(list);
    return rc;
}
