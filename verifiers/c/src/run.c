/* Running a selection of vectors and reporting it: the C counterpart of `plcvec verify`. */
#include <stdlib.h>
#include <string.h>

#include "table.h"

static void header(FILE *log, const plcvec_impl *impl, plcvec_judge *j, const plcvec_vector **list, size_t selected)
{
    uint32_t families = 0;
    for (size_t i = 0; i < selected; i++)
        families |= 1u << list[i]->family;
    fprintf(log, "plcvec %s (schema %s, spec %.12s): %zu of %zu vectors selected for %s\n", PLCVEC_SUITE_VERSION,
            PLCVEC_SCHEMA_VERSION, PLCVEC_SPEC_SHA256, selected, plcvec_count(), impl->name ? impl->name : "(unnamed)");
    fprintf(log, "alternatives followed:");
    for (int i = 0, first = 1; i < PLCVEC_INTERPRETATION_COUNT; i++) {
        if (!(plcvec_interpretations[i].families & families))
            continue;
        int declared = 0;
        for (size_t c = 0; c < impl->n_choices; c++)
            declared |= impl->choices[c].interpretation == i;
        fprintf(log, "%s %s=%s%s", first ? "" : ",", plcvec_interpretations[i].id,
                plcvec_interpretations[i].alternatives[plcvec_judge_alternative(j, i)], declared ? "" : " (default)");
        first = 0;
    }
    fprintf(log, "\n");
}

int plcvec_run(const plcvec_impl *impl, const plcvec_options *opt, plcvec_summary *summary)
{
    static const plcvec_options none;
    if (!opt)
        opt = &none;
    FILE *log = opt->log ? opt->log : stdout;
    plcvec_summary sum = {0};
    char err[256];
    const plcvec_vector **list = NULL;
    long n = plcvec_select(&opt->selection, &list, err, sizeof err);
    if (n < 0) {
        fprintf(log, "plcvec: %s\n", err);
        return 2;
    }
    if (n == 0) {
        fprintf(log, "plcvec: the selection holds no vector (an empty selection never passes)\n");
        free(list);
        return 2;
    }
    plcvec_judge *j = plcvec_judge_new(impl, err, sizeof err);
    if (!j) {
        fprintf(log, "plcvec: %s\n", err);
        free(list);
        return 2;
    }
    header(log, impl, j, list, (size_t)n);
    sum.selected = (size_t)n;
    for (long i = 0; i < n; i++) {
        plcvec_verdict vd = *plcvec_judge_vector(j, list[i]);
        plcvec_apply_known(&vd, opt->known, opt->n_known);
        switch (vd.status) {
        case PLCVEC_PASS: sum.passed++; break;
        case PLCVEC_FAIL: sum.failed++; break;
        case PLCVEC_ERROR: sum.errors++; break;
        case PLCVEC_SKIP: sum.skipped++; break;
        case PLCVEC_XFAIL: sum.xfail++; break;
        case PLCVEC_STALE: sum.stale++; break;
        }
        if (vd.status == PLCVEC_FAIL || vd.status == PLCVEC_ERROR || vd.status == PLCVEC_STALE ||
            (opt->verbose && (vd.status == PLCVEC_SKIP || vd.status == PLCVEC_XFAIL)))
            plcvec_print_verdict(log, &vd);
    }
    for (size_t k = 0; k < opt->n_known; k++)
        if (!opt->known[k].id || !plcvec_find(opt->known[k].id)) {
            fprintf(log, "STALE %s\n    listed as a known failure (%s) but the suite has no such vector; remove it\n",
                    opt->known[k].id ? opt->known[k].id : "(null)", opt->known[k].reason ? opt->known[k].reason : "");
            sum.stale++;
        }
    plcvec_judge_free(j);
    free(list);
    size_t bad = sum.failed + sum.errors + sum.stale;
    int all_skipped = sum.skipped == sum.selected;
    if (all_skipped)
        fprintf(log, "plcvec: every selected vector was skipped: nothing was verified\n");
    fprintf(log, "(%zu failed, %zu errors, %zu stale, %zu known failures)\n", sum.failed, sum.errors, sum.stale, sum.xfail);
    fprintf(log, "plcvec: %zu passed, %zu failed, %zu skipped\n", sum.passed, bad, sum.skipped);
    fflush(log);
    if (summary)
        *summary = sum;
    return bad || all_skipped ? 1 : 0;
}

static void usage(FILE *f, const char *prog)
{
    fprintf(f,
            "usage: %s [--family F] [--instruction I] [--tag T] [--id GLOB] [--interpretation ID]\n"
            "          [--shard K/N] [--list] [--verbose]\n"
            "Judge the compiled-in plcvec vectors (filters repeat: OR within one, AND between them).\n"
            "Exit 0 passed, 1 failures, 2 usage error.\n",
            prog);
}

int plcvec_main(const plcvec_impl *impl, const plcvec_known_failure *known, size_t n_known, int argc, char **argv)
{
    const char *prog = argc > 0 ? argv[0] : "plcvec";
    /* Each filter list holds at most argc names: one array sliced five ways. */
    const char **names = calloc((size_t)(argc > 0 ? argc : 1) * 5, sizeof *names);
    if (!names)
        return 2;
    const char **lists[5];
    size_t counts[5] = {0};
    for (int l = 0; l < 5; l++)
        lists[l] = names + (size_t)l * (size_t)(argc > 0 ? argc : 1);
    static const char *const flags[5] = {"--family", "--instruction", "--tag", "--id", "--interpretation"};
    plcvec_options opt = {0};
    opt.known = known;
    opt.n_known = n_known;
    int list_only = 0, rc = 0;
    for (int i = 1; i < argc; i++) {
        int matched = 0;
        for (int l = 0; l < 5 && !matched; l++)
            if (strcmp(argv[i], flags[l]) == 0) {
                matched = 1;
                if (i + 1 >= argc) {
                    fprintf(stderr, "%s: %s needs a value\n", prog, argv[i]);
                    rc = 2;
                } else
                    lists[l][counts[l]++] = argv[++i];
            }
        if (matched)
            continue;
        if (strcmp(argv[i], "--shard") == 0 && i + 1 >= argc) {
            fprintf(stderr, "%s: --shard needs a value (K/N)\n", prog);
            rc = 2;
        } else if (strcmp(argv[i], "--shard") == 0) {
            char tail;
            if (sscanf(argv[++i], "%u/%u%c", &opt.selection.shard_k, &opt.selection.shard_n, &tail) != 2) {
                fprintf(stderr, "%s: --shard takes K/N (e.g. 2/4), got '%s'\n", prog, argv[i]);
                rc = 2;
            }
        } else if (strcmp(argv[i], "--list") == 0)
            list_only = 1;
        else if (strcmp(argv[i], "--verbose") == 0 || strcmp(argv[i], "-v") == 0)
            opt.verbose = 1;
        else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout, prog);
            free(names);
            return 0;
        } else {
            fprintf(stderr, "%s: unknown argument '%s'\n", prog, argv[i]);
            usage(stderr, prog);
            rc = 2;
        }
    }
    /* PLCVEC_SHARD=K/N splits a CI matrix without changing the test's command line. */
    const char *env = getenv("PLCVEC_SHARD");
    if (!rc && !opt.selection.shard_n && env && *env) {
        char tail;
        if (sscanf(env, "%u/%u%c", &opt.selection.shard_k, &opt.selection.shard_n, &tail) != 2) {
            fprintf(stderr, "%s: PLCVEC_SHARD takes K/N (e.g. 2/4), got '%s'\n", prog, env);
            rc = 2;
        }
    }
    if (rc) {
        free(names);
        return rc;
    }
    opt.selection.families = lists[0], opt.selection.n_families = counts[0];
    opt.selection.instructions = lists[1], opt.selection.n_instructions = counts[1];
    opt.selection.tags = lists[2], opt.selection.n_tags = counts[2];
    opt.selection.ids = lists[3], opt.selection.n_ids = counts[3];
    opt.selection.interpretations = lists[4], opt.selection.n_interpretations = counts[4];
    if (list_only) {
        const plcvec_vector **sel = NULL;
        char err[256];
        long n = plcvec_select(&opt.selection, &sel, err, sizeof err);
        if (n < 0) {
            fprintf(stderr, "%s: %s\n", prog, err);
            rc = 2;
        }
        for (long i = 0; i < n; i++)
            printf("%s\n", sel[i]->id);
        free(sel);
    } else
        rc = plcvec_run(impl, &opt, NULL);
    free(names);
    return rc;
}
