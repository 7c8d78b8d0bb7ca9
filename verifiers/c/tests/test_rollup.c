/* The roll-up by reading (verifiers/parity/TEXT.md): the declaration in C's syntax is TEXT.md's
 * row for C, and no mutant of the reference ends with a reading proposed without the `partial`
 * mark (a mutant whose failures one reading explains would be a reading, not a bug).
 *
 *   test_rollup TEXT.md */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reference.h"
#include "rollup.h"

/* The C cell of TEXT.md's table "The declaration in each runner", without its backticks. */
static int c_declaration_in(const char *path, char *cell, size_t size)
{
    FILE *f = fopen(path, "rb");
    char line[1024];
    int found = 0;
    while (f && !found && fgets(line, sizeof line, f)) {
        const char *start = strncmp(line, "| C | `", 7) == 0 ? line + 7 : NULL;
        const char *end = start ? strstr(start, "` |") : NULL;
        if (end) {
            snprintf(cell, size, "%.*s", (int)(end - start), start);
            found = 1;
        }
    }
    if (f)
        fclose(f);
    return found;
}

static void test_declaration_is_texts(const char *text_md)
{
    char want[512] = "", got[512];
    CHECK(c_declaration_in(text_md, want, sizeof want));
    uint8_t choice[PLCVEC_INTERPRETATION_COUNT] = {0};
    choice[PLCVEC_INTERP_FX5_SM709_SCOPE] = PLCVEC_FX5_SM709_SCOPE_ALL_WORDS;
    choice[PLCVEC_INTERP_TADD_FLAGS_OFF] = PLCVEC_TADD_FLAGS_OFF_SET_ONLY;
    uint64_t which = UINT64_C(1) << PLCVEC_INTERP_FX5_SM709_SCOPE | UINT64_C(1) << PLCVEC_INTERP_TADD_FLAGS_OFF;
    plcvec_declaration_text(got, sizeof got, which, choice);
    if (strcmp(got, want) != 0) {
        fprintf(stderr, "the C declaration is\n  %s\nTEXT.md says\n  %s\n", got, want);
        failures++;
    }
    /* The same, as plcvec verify takes it (the shared cases' form). */
    plcvec_rollup_declaration_form(PLCVEC_DECLARE_CHOOSE);
    plcvec_declaration_text(got, sizeof got, which, choice);
    CHECK(strcmp(got, "--choose FX5-SM709-SCOPE=all-words --choose TADD-FLAGS-OFF=set-only") == 0);
    plcvec_rollup_declaration_form(PLCVEC_DECLARE_C);
}

/* The run's text of impl over `opt` (its log set here), malloc'd; its status must be `rc`. */
static char *run_text_of(const plcvec_impl *impl, plcvec_options *opt, int rc)
{
    FILE *log = tmpfile();
    opt->log = log;
    CHECK(plcvec_run(impl, opt, NULL) == rc);
    long size = ftell(log);
    char *text = malloc((size_t)size + 1);
    rewind(log);
    size_t got = text ? fread(text, 1, (size_t)size, log) : 0;
    if (text)
        text[got] = '\0';
    fclose(log);
    return text;
}

/* The run's text of one mutant, in C's own declaration syntax. */
static char *run_text(const plcvec_mutant *mutant)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    mutant->apply(&ref);
    plcvec_impl impl = plcvec_reference_impl(&ref);
    plcvec_options opt = {0};
    return run_text_of(&impl, &opt, PLCVEC_EXIT_FAILED);
}

/* Every proposal of the roll-up (a line under READINGS or KNOWN FAILURES) is marked partial. */
static void test_no_mutant_is_a_reading(void)
{
    for (size_t m = 0; m < plcvec_mutant_count; m++) {
        char *text = run_text(&plcvec_mutants[m]);
        CHECK(text != NULL);
        int in_readings = 0, proposals = 0;
        for (char *line = text ? strtok(text, "\n") : NULL; line; line = strtok(NULL, "\n")) {
            if (strncmp(line, "READINGS: ", 10) == 0 || strncmp(line, "KNOWN FAILURES: ", 16) == 0) {
                in_readings = 1;
                continue;
            }
            if (line[0] != ' ')
                in_readings = 0;
            /* A group line: six columns of count, two spaces, ID=alternative. */
            if (in_readings && strlen(line) > 12 && line[9] >= '0' && line[9] <= '9' && line[10] == ' ' && line[11] == ' ') {
                proposals++;
                if (!strstr(line, " (partial: ")) {
                    fprintf(stderr, "mutant %s: a reading proposed without the partial mark:\n%s\n",
                            plcvec_mutants[m].name, line);
                    failures++;
                }
            }
            if (in_readings && strncmp(line, "    declare: {PLCVEC_INTERP_", 28) != 0 && strncmp(line, "    declare:", 12) == 0) {
                fprintf(stderr, "mutant %s: the declaration is not in C's syntax: %s\n", plcvec_mutants[m].name, line);
                failures++;
            }
        }
        printf("mutant %s: %d readings proposed, each partial\n", plcvec_mutants[m].name, proposals);
        free(text);
    }
}

/* An implementation that follows HOUR-FIRST-SCAN=after-cpu-start undeclared: its failures pass under
 * that reading, and also under the readings that leave D1, D2 and M8004 unjudged (whose ids come
 * first). The search takes first the readings that judge every device, so after-cpu-start alone is
 * proposed, explaining everything (TEXT.md, "The inference", step 4). */
static void test_a_reading_that_judges_comes_first(void)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    CHECK(plcvec_reference_choose(&ref, "HOUR-FIRST-SCAN", "after-cpu-start") == 0);
    plcvec_impl impl = plcvec_reference_impl(&ref);
    impl.choices = NULL, impl.n_choices = 0;
    const char *family[] = {"fc6a-hour-meter"};
    plcvec_options opt = {0};
    opt.selection.families = family, opt.selection.n_families = 1;
    char *text = run_text_of(&impl, &opt, PLCVEC_EXIT_FAILED);
    const char *readings = text ? strstr(text, "READINGS: ") : NULL;
    CHECK(readings != NULL && !strstr(text, "NOT EXPLAINED"));
    if (readings) {
        char failing[32];
        int e = 0, f = 0;
        CHECK(sscanf(readings, "READINGS: %d of %d %31s", &e, &f, failing) == 3 && e == f && e > 0);
        CHECK_HAS(readings, "  HOUR-FIRST-SCAN=after-cpu-start\n"
                            "    declare: {PLCVEC_INTERP_HOUR_FIRST_SCAN, PLCVEC_HOUR_FIRST_SCAN_AFTER_CPU_START}\n\n");
    }
    free(text);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_rollup TEXT.md\n");
        return 2;
    }
    test_declaration_is_texts(argv[1]);
    test_no_mutant_is_a_reading();
    test_a_reading_that_judges_comes_first();
    printf("test_rollup: %d failures\n", failures);
    return failures ? 1 : 0;
}
