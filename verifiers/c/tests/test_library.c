/* The library's own behaviour: names, selection and shards, the comparison (types, unchanged
 * devices, writes outside the vector, steps), known failures, and the failure text. Faults are
 * planted by wrapping the reference and tampering with what it reports. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reference.h"

/* ---- a reference whose reports are tampered with ---------------------------------------- */

enum tamper { NOTHING, BIT_AS_WORD, WRITE_OUTSIDE, CHANGE_LISTED, DROP_STEP, FLIP_RESULT, SKIP_ALL };

typedef struct tampered {
    plcvec_reference ref;
    plcvec_impl inner;
    plcvec_out *scratch;
    enum tamper how;
} tampered;

static int tampered_run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    tampered *t = ctx;
    if (t->how == SKIP_ALL)
        return plcvec_out_skip(out, "planted: skips everything");
    plcvec_out_reset(t->scratch);
    t->inner.run(t->inner.ctx, v, t->scratch);
    size_t steps = plcvec_out_step_count(t->scratch);
    for (size_t s = 0; s < steps; s++) {
        if (t->how == DROP_STEP && s + 1 == steps)
            break;
        int result = plcvec_out_result(t->scratch, s);
        if (t->how == FLIP_RESULT && result != PLCVEC_NONE)
            result = !result;
        plcvec_out_step(out, result);
        size_t n;
        const plcvec_reported *cells = plcvec_out_cells(t->scratch, s, &n);
        for (size_t i = 0; i < n; i++) {
            plcvec_type type = (plcvec_type)cells[i].type;
            unsigned value = cells[i].value;
            if (t->how == BIT_AS_WORD && cells[i].device == PLCVEC_DEV_SM709)
                type = PLCVEC_WORD;
            if (t->how == CHANGE_LISTED && cells[i].device == PLCVEC_DEV_D100)
                value ^= 1;
            plcvec_out_device(out, cells[i].device, type, value);
        }
        if (t->how == WRITE_OUTSIDE)
            plcvec_out_named(out, "D9999", PLCVEC_WORD, 7);
    }
    return 0;
}

static plcvec_impl tampered_impl(tampered *t, enum tamper how)
{
    plcvec_reference_init(&t->ref);
    t->inner = plcvec_reference_impl(&t->ref);
    t->scratch = plcvec_out_new();
    t->how = how;
    plcvec_impl impl = t->inner;
    impl.ctx = t;
    impl.run = tampered_run;
    return impl;
}

/* A one-step LD vector of the FX5 time comparison that lists SM709 and D100 and changes neither. */
static const plcvec_vector *plain_ld_vector(void)
{
    for (size_t i = 0; i < plcvec_count(); i++) {
        const plcvec_vector *v = plcvec_at(i);
        if (v->family != PLCVEC_FAMILY_FX5_TIME_COMPARE || v->n_steps != 1 || v->n_interpretations ||
            v->steps[0].expect.n_devices || strncmp(plcvec_instruction_names[v->instruction], "LD", 2) != 0)
            continue;
        int sm709 = 0, d100 = 0;
        for (size_t k = 0; k < v->n_devices; k++) {
            sm709 |= v->devices[k].device == PLCVEC_DEV_SM709;
            d100 |= v->devices[k].device == PLCVEC_DEV_D100;
        }
        if (sm709 && d100)
            return v;
    }
    return NULL;
}

static const char *verdict_text(plcvec_judge *j, const plcvec_vector *v, plcvec_status *status)
{
    static char text[8192];
    const plcvec_verdict *vd = plcvec_judge_vector(j, v);
    *status = vd->status;
    plcvec_format_verdict(text, sizeof text, vd);
    return text;
}

static void test_comparison(void)
{
    const plcvec_vector *v = plain_ld_vector();
    CHECK(v != NULL);
    if (!v)
        return;
    struct {
        enum tamper how;
        plcvec_status status;
        const char *line;
    } cases[] = {
        {NOTHING, PLCVEC_PASS, NULL},
        {BIT_AS_WORD, PLCVEC_FAIL, "step 0 SM709: expected false, got 0 (the step must leave it unchanged)"},
        {WRITE_OUTSIDE, PLCVEC_FAIL, "step 0 D9999: expected <not in the vector>, got 7\n"},  /* no suffix: not listed */
        {CHANGE_LISTED, PLCVEC_FAIL, "(the step must leave it unchanged)"},
        {DROP_STEP, PLCVEC_FAIL, "steps: expected 1 steps, got 0 steps"},
        {FLIP_RESULT, PLCVEC_FAIL, "step 0 result: expected "},
        {SKIP_ALL, PLCVEC_SKIP, "planted: skips everything"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tampered t;
        plcvec_impl impl = tampered_impl(&t, cases[c].how);
        char err[256];
        plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
        plcvec_status status;
        const char *text = verdict_text(j, v, &status);
        CHECK(status == cases[c].status);
        if (cases[c].line && !strstr(text, cases[c].line)) {
            fprintf(stderr, "case %zu: no '%s' in:\n%s", c, cases[c].line, text);
            failures++;
        }
        if (status == PLCVEC_FAIL && cases[c].how != DROP_STEP) {
            /* TEXT.md: the step's inputs and operands (sorted by name, each device with its words)
             * before the step's first field line. */
            CHECK(strstr(text, "\n    step 0 inputs: ") != NULL);
            CHECK(strstr(text, "\n    step 0 operands: s1 D100=") != NULL && strstr(text, ", s2 D") != NULL);
            CHECK(strstr(text, "step 0 inputs: ") < strstr(text, "step 0 operands: ") &&
                  strstr(text, "step 0 operands: ") < strstr(text, cases[c].line));
        }
        if (status == PLCVEC_FAIL) {
            CHECK(strstr(text, v->id) != NULL);
            CHECK(strstr(text, "spec clauses: fx5-time-compare#") != NULL);
        }
        plcvec_judge_free(j);
        plcvec_out_free(t.scratch);
    }
}

/* The expectation that applies follows the declared alternative. */
static void test_alternatives(void)
{
    const plcvec_vector *v = NULL;
    for (size_t i = 0; i < plcvec_count() && !v; i++)
        if (plcvec_at(i)->n_alternatives && plcvec_at(i)->alternatives[0].n_choices == 1)
            v = plcvec_at(i);
    CHECK(v != NULL);
    if (!v)
        return;
    const plcvec_choice choice = v->alternatives[0].choices[0];
    plcvec_reference ref;
    plcvec_reference_init(&ref);
    plcvec_impl impl = plcvec_reference_impl(&ref);
    char err[256];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    CHECK(plcvec_expected(j, v, 0) == &v->steps[0].expect);
    plcvec_judge_free(j);
    impl.choices = &choice;
    impl.n_choices = 1;
    j = plcvec_judge_new(&impl, err, sizeof err);
    CHECK(plcvec_expected(j, v, 0) == &v->alternatives[0].expect[0]);
    /* The reference still follows the default: judged by the declared alternative, it fails
     * wherever the two readings differ (every vector that lists alternatives differs somewhere). */
    plcvec_judge_free(j);
    plcvec_choice bad = {choice.interpretation, 200};
    impl.choices = &bad;
    CHECK(plcvec_judge_new(&impl, err, sizeof err) == NULL);
    CHECK(strstr(err, "does not have") != NULL);
}

static void test_names_and_selection(void)
{
    /* zlib.crc32 of these strings (and the CRC-32 check value of "123456789"). */
    CHECK(plcvec_crc32("123456789") == 0xCBF43926u);
    CHECK(plcvec_crc32("fx5-time-add/TADD/manual-example/program") == 0x57D9B78Eu);
    CHECK(plcvec_crc32("cp1e-time-compare/AND <=DT/logic/rlo-off/eq") == 0xAEA0FB74u);
    CHECK(plcvec_crc32("") == 0);

    CHECK(plcvec_glob("fx5-*/TADD[P]/*", "fx5-time-add/TADDP/pulse/x"));
    CHECK(!plcvec_glob("fx5-*/TADD[P]/*", "fx5-time-add/TADD/pulse/x"));
    CHECK(plcvec_glob("*<=DT*", "cp1e-time-compare/AND <=DT/logic"));
    CHECK(plcvec_glob("a?c", "abc") && !plcvec_glob("a?c", "ac"));
    CHECK(plcvec_glob("[!x]*", "abc") && !plcvec_glob("[!a]*", "abc"));
    CHECK(plcvec_glob("[a-c]", "b") && !plcvec_glob("[a-c]", "d"));
    CHECK(plcvec_glob("a[b", "a[b"));       /* an unclosed [ is a character */
    CHECK(!plcvec_glob("abc", "abcd") && plcvec_glob("*", "") && plcvec_glob("**a", "ba"));

    CHECK(plcvec_count() == PLCVEC_TOTAL_VECTORS);
    for (size_t i = 0; i < plcvec_count(); i += 97)
        CHECK(plcvec_find(plcvec_at(i)->id) == plcvec_at(i));
    CHECK(plcvec_find("fx5-time-add/no/such/vector") == NULL);
    CHECK(plcvec_device_named("SM709") == PLCVEC_DEV_SM709 && plcvec_device_named("Q999") == -1);
    CHECK(strcmp(plcvec_devices[PLCVEC_DEV_D100].kind, "D") == 0 && plcvec_devices[PLCVEC_DEV_D100].number == 100);
    CHECK(plcvec_devices[PLCVEC_DEV_P_EQ].number == -1);
    int scope = plcvec_interpretation_named("FX5-SM709-SCOPE");
    CHECK(scope == PLCVEC_INTERP_FX5_SM709_SCOPE);
    CHECK(plcvec_alternative_named(scope, "all-words") == PLCVEC_FX5_SM709_SCOPE_ALL_WORDS);
    CHECK(plcvec_alternative_named(scope, "no-such") == -1);

    /* Shards: disjoint, and together every vector. */
    size_t total = 0;
    char err[256];
    for (unsigned k = 1; k <= 4; k++) {
        plcvec_selection sel = {0};
        sel.shard_k = k, sel.shard_n = 4;
        const plcvec_vector **list;
        long n = plcvec_select(&sel, &list, err, sizeof err);
        CHECK(n > 0);
        for (long i = 0; i < n; i++)
            CHECK(plcvec_crc32(list[i]->id) % 4 + 1 == k);
        total += (size_t)n;
        free(list);
    }
    CHECK(total == plcvec_count());

    const char *fam[] = {"fx5-time-add"}, *tags[] = {"pulse", "wrap"}, *bad[] = {"no-such-family"};
    plcvec_selection sel = {0};
    sel.families = fam, sel.n_families = 1, sel.tags = tags, sel.n_tags = 2;
    const plcvec_vector **list;
    long n = plcvec_select(&sel, &list, err, sizeof err);
    CHECK(n > 0);
    for (long i = 0; i < n; i++)
        CHECK(list[i]->family == PLCVEC_FAMILY_FX5_TIME_ADD &&
              (list[i]->tags & ((UINT64_C(1) << PLCVEC_TAG_PULSE) | (UINT64_C(1) << PLCVEC_TAG_WRAP))));
    free(list);
    sel.families = bad;
    CHECK(plcvec_select(&sel, &list, err, sizeof err) == -1 && strstr(err, "no-such-family"));
    plcvec_selection shard = {0};
    shard.shard_k = 5, shard.shard_n = 4;
    CHECK(plcvec_select(&shard, &list, err, sizeof err) == -1);
}

static void test_run_and_known_failures(void)
{
    const plcvec_vector *v = plain_ld_vector();
    FILE *log = tmpfile();
    tampered t;
    plcvec_impl impl = tampered_impl(&t, CHANGE_LISTED);
    const char *ids[] = {v->id};
    plcvec_options opt = {0};
    opt.selection.ids = ids, opt.selection.n_ids = 1;
    opt.log = log;
    plcvec_summary sum;
    CHECK(plcvec_run(&impl, &opt, &sum) == 1 && sum.failed == 1);
    plcvec_known_failure known[] = {{v->id, "planted", "known.toml", 3}};
    opt.known = known, opt.n_known = 1;
    /* A known failure does not fail the run; but a run in which nothing passed proves nothing. */
    CHECK(plcvec_run(&impl, &opt, &sum) == PLCVEC_EXIT_NOTHING_TESTED && sum.xfail == 1);
    t.how = NOTHING;                            /* fixed: the entry is stale */
    CHECK(plcvec_run(&impl, &opt, &sum) == 1 && sum.stale == 1);
    plcvec_known_failure unknown[] = {{"fx5-time-add/no/such/vector", "gone", NULL, 0}};
    opt.known = unknown;
    CHECK(plcvec_run(&impl, &opt, &sum) == 1 && sum.stale == 1 && sum.passed == 1);
    opt.known = NULL, opt.n_known = 0;
    t.how = SKIP_ALL;                           /* skipping everything never passes */
    CHECK(plcvec_run(&impl, &opt, &sum) == PLCVEC_EXIT_NOTHING_TESTED && sum.skipped == 1);
    const char *family[] = {"fx5-time-add"};
    opt.selection.families = family, opt.selection.n_families = 1;
    CHECK(plcvec_run(&impl, &opt, &sum) == PLCVEC_EXIT_NOTHING_TESTED);    /* nor does an empty selection */
    opt.selection.families = NULL, opt.selection.n_families = 0;
    const char *none[] = {"no/such/*"};
    opt.selection.ids = none;                   /* an id glob that matches no id is a mistake */
    CHECK(plcvec_run(&impl, &opt, &sum) == PLCVEC_EXIT_USAGE);
    rewind(log);
    char text[65536];
    size_t len = fread(text, 1, sizeof text - 1, log);
    text[len] = '\0';
    CHECK(strstr(text, "\n1 vectors: 0 pass, 1 fail, 0 skip in ") != NULL);     /* TEXT.md's totals */
    CHECK(strstr(text, "known failure: planted") == NULL);      /* xfail is printed only with verbose */
    CHECK(strstr(text, "but it passes; remove it") != NULL);
    CHECK(strstr(text, "the suite has no such vector") != NULL);
    CHECK(strstr(text, "SKIPPED 1 of 1 vectors (100.0%):\n         1  ") != NULL);
    CHECK(strstr(text, "NOT PASSED (exit 5): nothing passed (1 skipped): the run proves nothing") != NULL);
    CHECK(strstr(text, "no vector selected") != NULL);
    CHECK(strstr(text, "id no/such/*: matches no vector id") != NULL);
    CHECK(strstr(text, "FX5-SM709-SCOPE=selected-fields (declared)") != NULL);    /* every alternative followed */
    fclose(log);
    plcvec_out_free(t.scratch);
}

/* Write `text` to a temporary file; its name into path. */
static void temp_file(const char *text, char *path, size_t size)
{
    static int n;
    snprintf(path, size, "%s/plcvec-known-%d-%d.toml", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", (int)(size_t)&n % 9973, n++);
    FILE *f = fopen(path, "wb");
    fputs(text, f);
    fclose(f);
}

/* Load `text` as a known-failures file: 0 and the entries, or -1 with the error (path replaced by FILE). */
static int load_known(const char *text, plcvec_known_failure **list, size_t *n, char *err, size_t errlen)
{
    char path[256], raw[1024];
    temp_file(text, path, sizeof path);
    int rc = plcvec_known_load(path, list, n, raw, sizeof raw);
    remove(path);
    if (rc && strncmp(raw, path, strlen(path)) == 0)
        snprintf(err, errlen, "FILE%s", raw + strlen(path));
    else
        snprintf(err, errlen, "%s", raw);
    return rc;
}

/* The instructions as values, against the manual's spellings (the pages' own names). */
static void test_instruction_metadata(void)
{
    const plcvec_instruction_info *i = &plcvec_instructions[PLCVEC_INSTR_LDTM_LE];
    CHECK(strcmp(i->name, "LDTM<=") == 0 && i->family == PLCVEC_FAMILY_FX5_TIME_COMPARE && i->form == PLCVEC_FORM_LD &&
          i->condition == PLCVEC_CONDITION_LE && i->execution == PLCVEC_EXECUTION_EVERY_SCAN);
    i = &plcvec_instructions[PLCVEC_INSTR_AND_NE_DT];       /* "AND <>DT": CP1E, the AND form of <> */
    CHECK(i->family == PLCVEC_FAMILY_CP1E_TIME_COMPARE && i->form == PLCVEC_FORM_AND && i->condition == PLCVEC_CONDITION_NE);
    i = &plcvec_instructions[PLCVEC_INSTR_ORDT_GT];
    CHECK(i->form == PLCVEC_FORM_OR && i->condition == PLCVEC_CONDITION_GT && i->family == PLCVEC_FAMILY_FX5_DATE_COMPARE);
    i = &plcvec_instructions[PLCVEC_INSTR_TADDP];           /* the P suffix: executed on the rising edge */
    CHECK(i->form == PLCVEC_FORM_NONE && i->condition == PLCVEC_CONDITION_NONE &&
          i->execution == PLCVEC_EXECUTION_RISING_EDGE);
    CHECK(plcvec_instructions[PLCVEC_INSTR_TADD].execution == PLCVEC_EXECUTION_EVERY_SCAN);
    CHECK(plcvec_instructions[PLCVEC_INSTR_HOUR].form == PLCVEC_FORM_NONE);
    CHECK(strcmp(plcvec_condition_names[PLCVEC_CONDITION_GE], ">=") == 0 && strcmp(plcvec_form_names[PLCVEC_FORM_OR], "OR") == 0);
    for (int k = 0; k < PLCVEC_INSTRUCTION_COUNT; k++)
        CHECK(strcmp(plcvec_instructions[k].name, plcvec_instruction_names[k]) == 0 &&
              plcvec_instructions[k].family == plcvec_instruction_family[k]);
}

static void test_known_failures_file(void)
{
    plcvec_known_failure *list;
    size_t n;
    char err[1024];
    /* The format of CONTRACT.md, with comments, blank lines, both string kinds and escapes. */
    CHECK(load_known("# ours\n\n[[known-failure]]\nid = \"a/b<c\"  # trailing comment\nreason = 'no \\escape'\n"
                     "[[known-failure]]\r\nid = \"x\\u00e9\\\"y\"\r\nreason = \"tab\\there\"\r\n",
                     &list, &n, err, sizeof err) == 0);
    CHECK(n == 2 && strcmp(list[0].id, "a/b<c") == 0 && strcmp(list[0].reason, "no \\escape") == 0);
    CHECK(n == 2 && strcmp(list[1].id, "x\xc3\xa9\"y") == 0 && strcmp(list[1].reason, "tab\there") == 0);
    plcvec_known_free(list, n);
    CHECK(load_known("", &list, &n, err, sizeof err) == 0 && n == 0);
    /* Each refusal names the file and the line, as every plcvec runner does. */
    static const struct { const char *text, *says; } bad[] = {
        {"[[known-failure]]\nid = \"a\nreason = \"r\"\n", "FILE:2: not valid TOML: the string is not closed on its line"},
        {"[[known-failure]]\nid = \"a\"\nreason = \"r\"\ncolour = \"red\"\n", "FILE:4: unknown key 'colour' (an entry has `id` and `reason`)"},
        {"id = \"a\"\n", "FILE:1: unknown key 'id'; an expectations file holds only [[known-failure]] entries"},
        {"[known-failure]\nid = \"a\"\n", "FILE:1: unknown table [known-failure]"},
        {"[[known-failure]]\n\n\nreason = \"r\"\n", "FILE:1: entry without an `id`"},
        {"[[known-failure]]\nid = \"a\"\nreason = \"  \"\n", "FILE:1: a: every known failure needs a `reason`"},
        {"[[known-failure]]\nid = \"a\"\nreason = \"r\"\n[[known-failure]]\nid = \"a\"\nreason = \"s\"\n",
         "FILE:4: a is listed twice (first at line 1)"},
        {"[[known-failure]]\nid = 3\n", "FILE:2: not valid TOML here: `id` and `reason` are strings"},
        {"[[known-failure]]\nid = \"a\" b\n", "FILE:2: not valid TOML: unexpected text after the value"},
        {"[[known-failure]]\nid = \"a\"\nid = \"b\"\n", "FILE:3: not valid TOML: `id` is given twice in one entry"},
        {"[[known-failure]]\nid = \"\"\"a\"\"\"\n", "FILE:2: multi-line strings are not used"},
        {"[[known-failure]]\nid = \"a\\q\"\n", "FILE:2: not valid TOML: an unknown escape"},
        {"[[known-failure]]\nid = \"\xff\"\n", "FILE:2: not UTF-8 text"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc = load_known(bad[i].text, &list, &n, err, sizeof err);
        CHECK(rc == -1 && strncmp(err, bad[i].says, strlen(bad[i].says)) == 0);
        if (rc != -1 || strncmp(err, bad[i].says, strlen(bad[i].says)) != 0)
            fprintf(stderr, "    case %zu: %s\n", i, err);
    }
    CHECK(plcvec_known_load("/no/such/dir/known.toml", &list, &n, err, sizeof err) == -1 &&
          strstr(err, "/no/such/dir/known.toml: cannot read the expectations file") != NULL);

    /* Writing: what `plcvec verify --write-expectations` writes, byte for byte, and it reads back. */
    char path[256];
    temp_file("", path, sizeof path);
    const char *ids[] = {"b/2", "a/\"1\""};
    CHECK(plcvec_known_write(path, ids, 2, "not yet triaged", err, sizeof err) == 0);
    FILE *f = fopen(path, "rb");
    char text[1024] = "";
    size_t len = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[len] = '\0';
    if (f)
        fclose(f);
    CHECK(strcmp(text, "# Known failures: each passing entry fails the run as stale, so fix and delete.\n\n"
                       "[[known-failure]]\nid = \"a/\\\"1\\\"\"\nreason = \"not yet triaged\"\n\n"
                       "[[known-failure]]\nid = \"b/2\"\nreason = \"not yet triaged\"\n") == 0);
    CHECK(plcvec_known_load(path, &list, &n, err, sizeof err) == 0 && n == 2 && strcmp(list[0].id, "a/\"1\"") == 0);
    plcvec_known_free(list, n);
    remove(path);
}

int main(void)
{
    test_instruction_metadata();
    test_known_failures_file();
    test_names_and_selection();
    test_comparison();
    test_alternatives();
    test_run_and_known_failures();
    printf("test_library: %d failures\n", failures);
    return failures ? 1 : 0;
}
