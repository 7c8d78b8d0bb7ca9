/* plcvec_main: a test program's main() with the options and variables of `plcvec verify`, its exit
 * statuses and its words. Each option's default is its PLCVEC_* variable (settings.c), so that a CI
 * matrix or a shared job sets them once for every runner of every language. */
#include <stdlib.h>
#include <string.h>

#include "selection.h"
#include "settings.h"

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

/* The command line, read. */
typedef struct cli {
    const char *prog;
    plcvec_filters filters;
    int given[PLCVEC_N_FILTERS];
    plcvec_choice *choices;
    size_t n_choices;
    const char *shard, *expectations, *write_expectations;
    int list_only, verbose, help;
} cli;

static void print_known(const char *prog, const char *what, int interp)
{
    fprintf(stderr, "%s: %s; known:", prog, what);
    if (interp < 0)
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            fprintf(stderr, "%s %s", i ? "," : "", plcvec_interpretations[i].id);
    for (int a = 0; interp >= 0 && a < plcvec_interpretations[interp].n_alternatives; a++)
        fprintf(stderr, "%s %s", a ? "," : "", plcvec_interpretations[interp].alternatives[a]);
    fprintf(stderr, "\n");
}

/* --choose ID=ALT; -1 (with the known names on stderr) for a name the suite does not have. */
static int parse_choice(cli *c, const char *text)
{
    const char *eq = strchr(text, '=');
    char id[96], what[256];
    snprintf(id, sizeof id, "%.*s", eq ? (int)(eq - text < 90 ? eq - text : 90) : 90, text);
    int interp = eq ? plcvec_interpretation_named(id) : -1;
    if (interp < 0) {
        snprintf(what, sizeof what, "--choose %.150s: %s", text, eq ? "no such interpretation" : "takes INTERPRETATION=ALTERNATIVE");
        print_known(c->prog, what, -1);
        return -1;
    }
    int alt = plcvec_alternative_named(interp, eq + 1);
    if (alt < 0) {
        snprintf(what, sizeof what, "--choose %.100s: %s has no alternative '%.80s'", text, plcvec_interpretations[interp].id, eq + 1);
        print_known(c->prog, what, interp);
        return -1;
    }
    plcvec_choice *grown = realloc(c->choices, (c->n_choices + 1) * sizeof *grown);
    if (!grown)
        return -1;
    c->choices = grown;
    c->choices[c->n_choices++] = (plcvec_choice){(uint8_t)interp, (uint8_t)alt};
    return 0;
}

/* One option at argv[*i] (its value after it); 0, or 2 for a usage error. */
static int parse_option(cli *c, int argc, char **argv, int *i)
{
    const char *a = argv[*i];
    int l = 0;
    while (l < PLCVEC_N_FILTERS && strcmp(a, plcvec_filter_options[l]) != 0)
        l++;
    int takes_value = l < PLCVEC_N_FILTERS || !strcmp(a, "--shard") || !strcmp(a, "--choose") ||
                      !strcmp(a, "--expectations") || !strcmp(a, "--write-expectations");
    if (takes_value && *i + 1 >= argc) {
        fprintf(stderr, "%s: %s needs a value\n", c->prog, a);
        return 2;
    }
    const char *value = takes_value ? argv[++*i] : NULL;
    if (l < PLCVEC_N_FILTERS) {
        c->given[l] = 1;
        return plcvec_filters_push(&c->filters, l, value) ? 2 : 0;
    }
    if (!strcmp(a, "--choose"))
        return parse_choice(c, value) ? 2 : 0;
    if (!strcmp(a, "--shard"))
        c->shard = value;
    else if (!strcmp(a, "--expectations"))
        c->expectations = value;
    else if (!strcmp(a, "--write-expectations"))
        c->write_expectations = value;
    else if (!strcmp(a, "--list"))
        c->list_only = 1;
    else if (!strcmp(a, "--verbose") || !strcmp(a, "-v"))
        c->verbose = 1;
    else if (!strcmp(a, "--help") || !strcmp(a, "-h"))
        c->help = 1;
    else {
        fprintf(stderr, "%s: unknown argument '%s'\n", c->prog, a);
        usage(stderr, c->prog);
        return 2;
    }
    return 0;
}

/* The options not given, from their variables; the selection and the files. 0, or 2 with err. */
static int defaults_from_environment(cli *c, plcvec_options *opt, char *err, size_t errlen)
{
    for (int l = 0; l < PLCVEC_N_FILTERS; l++)
        if (!c->given[l] && plcvec_filters_from_environment(&c->filters, l, err, errlen))
            return 2;
    if (plcvec_settings_check(err, errlen))
        return 2;
    const char *shard = c->shard ? c->shard : plcvec_setting("PLCVEC_SHARD");
    if (shard && plcvec_parse_shard(c->shard ? "--shard" : "PLCVEC_SHARD", shard, &opt->selection, err, errlen))
        return 2;
    plcvec_filters_select(&c->filters, &opt->selection);
    opt->write_expectations = c->write_expectations ? c->write_expectations : plcvec_setting("PLCVEC_WRITE_EXPECTATIONS");
    opt->verbose = c->verbose;
    if (!c->expectations)
        c->expectations = plcvec_setting("PLCVEC_KNOWN_FAILURES");
    return 0;
}

/* The implementation's declarations with --choose's on top; a usage error when the two give one
 * interpretation two alternatives (CONTRACT.md, "Declarations"). NULL on a usage error. */
static plcvec_choice *declarations(const plcvec_impl *impl, const cli *c, const char **why)
{
    plcvec_choice *merged = malloc((impl->n_choices + c->n_choices + 1) * sizeof *merged);
    if (!merged) {
        *why = "out of memory";
        return NULL;
    }
    for (size_t k = 0; k < c->n_choices; k++)
        for (size_t d = 0; d < impl->n_choices; d++)
            if (impl->choices[d].interpretation == c->choices[k].interpretation &&
                impl->choices[d].alternative != c->choices[k].alternative) {
                const plcvec_interpretation_info *info = &plcvec_interpretations[c->choices[k].interpretation];
                fprintf(stderr, "%s: --choose %s=%s, but the implementation declares %s=%s\n", c->prog, info->id,
                        info->alternatives[c->choices[k].alternative], info->id,
                        info->alternatives[impl->choices[d].alternative]);
                free(merged);
                *why = "";
                return NULL;
            }
    if (impl->n_choices)
        memcpy(merged, impl->choices, impl->n_choices * sizeof *merged);
    if (c->n_choices)
        memcpy(merged + impl->n_choices, c->choices, c->n_choices * sizeof *merged);
    return merged;
}

/* --list: the ids selected, one a line. */
static int list_ids(const cli *c, const plcvec_options *opt)
{
    char err[1024];
    const plcvec_vector **sel = NULL;
    long n = plcvec_select(&opt->selection, &sel, err, sizeof err);
    if (n < 0)
        fprintf(stderr, "%s: %s\n", c->prog, err);
    for (long i = 0; i < n; i++)
        printf("%s\n", sel[i]->id);
    free(sel);
    return n < 0 ? 2 : 0;
}

/* The run with the known failures of the file and of the program's list together. */
static int run(const plcvec_impl *impl, const cli *c, plcvec_options *opt, const plcvec_known_failure *known,
               size_t n_known, const plcvec_known_failure *file_known, size_t n_file_known)
{
    plcvec_known_failure *all = malloc((n_known + n_file_known + 1) * sizeof *all);
    const char *why = NULL;
    plcvec_choice *merged = all ? declarations(impl, c, &why) : NULL;
    if (!merged) {
        if (why && why[0])
            fprintf(stderr, "%s: %s\n", c->prog, why);
        free(all);
        return 2;
    }
    if (n_known)
        memcpy(all, known, n_known * sizeof *known);
    if (n_file_known)
        memcpy(all + n_known, file_known, n_file_known * sizeof *file_known);
    opt->known = all, opt->n_known = n_known + n_file_known;
    plcvec_impl declared = *impl;
    declared.choices = merged, declared.n_choices = impl->n_choices + c->n_choices;
    int rc = plcvec_run(&declared, opt, NULL);
    free(merged);
    free(all);
    return rc;
}

int plcvec_main(const plcvec_impl *impl, const plcvec_known_failure *known, size_t n_known, int argc, char **argv)
{
    cli c = {0};
    c.prog = argc > 0 ? argv[0] : "plcvec";
    plcvec_options opt = {0};
    plcvec_known_failure *file_known = NULL;
    size_t n_file_known = 0;
    char err[1024] = "";
    int rc = 0;
    plcvec_settings_warn();
    for (int i = 1; i < argc && !rc && !c.help; i++)
        rc = parse_option(&c, argc, argv, &i);
    if (!rc && !c.help)
        rc = defaults_from_environment(&c, &opt, err, sizeof err);
    if (!rc && !c.help && c.expectations && plcvec_known_load(c.expectations, &file_known, &n_file_known, err, sizeof err))
        rc = 2;
    if (rc && err[0])
        fprintf(stderr, "%s: %s\n", c.prog, err);
    else if (c.help)
        usage(stdout, c.prog);
    else if (!rc)
        rc = c.list_only ? list_ids(&c, &opt) : run(impl, &c, &opt, known, n_known, file_known, n_file_known);
    plcvec_filters_free(&c.filters);
    free(c.choices);
    plcvec_known_free(file_known, n_file_known);
    return rc;
}
