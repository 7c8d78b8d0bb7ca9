/* Known failures in the words of TEXT.md ("Known-failure messages"), the ids the suite merged into
 * another vector, and the files the library opens itself refused by name when they are not regular
 * files (CONTRACT.md, "Loading"). Expected texts are TEXT.md's, filled in by hand. */
#define _XOPEN_SOURCE 700 /* mkfifo, symlink, mkdtemp */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "suite.h"

static const plcvec_vector *vector_with_problems(plcvec_verdict *vd)
{
    static const plcvec_vector *v;
    v = plcvec_find("fx5-time-add/TADD/manual-example/program");
    CHECK(v != NULL);
    memset(vd, 0, sizeof *vd);
    vd->vector = v;
    return v;
}

static void test_messages(void)
{
    plcvec_known_failure known[] = {{"fx5-time-add/TADD/manual-example/program", "off by one", "known.toml", 3},
                                    {"fx5-time-add/TADD/manual-example/program", "in a list", NULL, 0}};
    plcvec_verdict vd;
    vector_with_problems(&vd);
    vd.status = PLCVEC_FAIL;
    plcvec_known_apply(&vd, known, 1);
    CHECK(vd.status == PLCVEC_XFAIL && strcmp(vd.message, "known failure (known.toml:3): off by one") == 0);
    vector_with_problems(&vd);
    vd.status = PLCVEC_ERROR;
    snprintf(vd.message, sizeof vd.message, "the implementation reported an error: x");
    plcvec_known_apply(&vd, known, 1);
    CHECK(vd.status == PLCVEC_XFAIL &&
          strcmp(vd.message, "known failure (known.toml:3): off by one; the implementation reported an error: x") == 0);
    vector_with_problems(&vd);
    vd.status = PLCVEC_PASS;
    plcvec_known_apply(&vd, known, 1);
    CHECK(vd.status == PLCVEC_STALE && strcmp(vd.message, "listed as a known failure (known.toml:3: off by one) but it "
                                                          "passes; remove it from the expectations file") == 0);
    vector_with_problems(&vd);
    vd.status = PLCVEC_FAIL;
    plcvec_known_apply(&vd, known + 1, 1);      /* a list in code, without a file */
    CHECK(strcmp(vd.message, "known failure (in code): in a list") == 0);
}

/* plcvec_apply_known, the name before 0.3.0, is plcvec_known_apply: the same verdict and message for
 * each status, STALE above all, the one a user's list in code meets first after an upgrade. */
static void test_old_name(void)
{
    plcvec_known_failure known[] = {{"fx5-time-add/TADD/manual-example/program", "off by one", "known.toml", 3}};
    const plcvec_status statuses[] = {PLCVEC_PASS, PLCVEC_FAIL, PLCVEC_ERROR, PLCVEC_SKIP};
    for (size_t i = 0; i < sizeof statuses / sizeof statuses[0]; i++) {
        plcvec_verdict by_new, by_old;
        vector_with_problems(&by_new);
        by_new.status = statuses[i];
        snprintf(by_new.message, sizeof by_new.message, "as judged");
        by_old = by_new;
        plcvec_known_apply(&by_new, known, 1);
        plcvec_apply_known(&by_old, known, 1);
        CHECK(by_old.status == by_new.status && strcmp(by_old.message, by_new.message) == 0);
    }
    plcvec_verdict vd;
    vector_with_problems(&vd);
    vd.status = PLCVEC_PASS;
    plcvec_apply_known(&vd, known, 1);
    CHECK(vd.status == PLCVEC_STALE && strcmp(vd.message, "listed as a known failure (known.toml:3: off by one) but it "
                                                          "passes; remove it from the expectations file") == 0);
}

/* The ids merged into another vector: the golden set's, and a map with a chain and a cycle. */
static void test_merged_ids(void)
{
    CHECK(plcvec_merged_into("cp1e-time-compare/AND <=DT/ordering/eq") != NULL &&
          strcmp(plcvec_merged_into("cp1e-time-compare/AND <=DT/ordering/eq"), "cp1e-time-compare/AND <=DT/logic/rlo-on/eq") == 0);
    CHECK(plcvec_merged_into("fx5-time-add/TADD/manual-example/program") == NULL);
    const plcvec_merged_id chain[] = {{"a", "b"}, {"b", "c"}, {"p", "q"}, {"q", "p"}};
    CHECK(strcmp(plcvec_merged_follow(chain, 4, "a"), "c") == 0);      /* a -> b -> c: named by c */
    CHECK(strcmp(plcvec_merged_follow(chain, 4, "b"), "c") == 0);
    CHECK(plcvec_merged_follow(chain, 4, "c") == NULL);
    CHECK(plcvec_merged_follow(chain, 4, "p") != NULL);                 /* a cycle ends */
}

static int never_run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    (void)ctx, (void)v, (void)out;
    return 0;
}

/* The end of a run with known failures the suite does not have: each named STALE in the list's
 * order, the merged one with the vector it became. */
static void test_stale_ids(void)
{
    plcvec_known_failure known[] = {
        {"fx5-time-add/TADD/no-such-vector", "listed by mistake", "k.toml", 2},
        {"cp1e-time-compare/AND <=DT/ordering/eq", "listed before the merge", "k.toml", 6},
    };
    plcvec_impl impl = {0};
    impl.name = "nothing";
    impl.run = never_run;
    char err[256];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    CHECK(j != NULL);
    plcvec_report *report = plcvec_report_new(j);
    FILE *log = tmpfile();
    CHECK(plcvec_report_end(report, log, known, 2, 0.0) == PLCVEC_EXIT_FAILED);
    char text[8192];
    rewind(log);
    size_t n = fread(text, 1, sizeof text - 1, log);
    text[n] = '\0';
    fclose(log);
    const char *want = "STALE fx5-time-add/TADD/no-such-vector\n"
                       "    listed as a known failure (k.toml:2) but the suite has no such vector; remove it from the "
                       "expectations file\n"
                       "STALE cp1e-time-compare/AND <=DT/ordering/eq\n"
                       "    listed as a known failure (k.toml:6) but the suite has no such vector: it was merged into "
                       "cp1e-time-compare/AND <=DT/logic/rlo-on/eq; list that id instead\n";
    CHECK(strncmp(text, want, strlen(want)) == 0);
    CHECK_HAS(text, "\n2 vectors: 0 pass, 0 fail, 0 skip, 2 stale in 0.00 s\n");
    plcvec_report_free(report);
    plcvec_judge_free(j);
}

/* A named pipe, a folder, a device and a loop of symbolic links where the known-failures file (or
 * the file to write, a device left out) belongs: refused by name, before anything waits on them. */
static void test_files_that_are_not_regular(void)
{
    char dir[] = "/tmp/plcvec-known-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char fifo[64], loop_a[64], loop_b[64], err[512], want[512];
    snprintf(fifo, sizeof fifo, "%s/known.toml", dir);
    snprintf(loop_a, sizeof loop_a, "%s/a.toml", dir);
    snprintf(loop_b, sizeof loop_b, "%s/b.toml", dir);
    CHECK(mkfifo(fifo, 0600) == 0 && symlink(loop_b, loop_a) == 0 && symlink(loop_a, loop_b) == 0);
    const struct {
        const char *path, *why;
    } cases[] = {{fifo, "not a regular file (a named pipe)"}, {dir, "not a regular file (a folder)"},
                 {"/dev/zero", "not a regular file (a character device)"}, {loop_a, "a loop of symbolic links"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        plcvec_known_failure *list = NULL;
        size_t n = 0;
        snprintf(want, sizeof want, "%s: %s", cases[i].path, cases[i].why);
        CHECK(plcvec_known_load(cases[i].path, &list, &n, err, sizeof err) == -1 && strcmp(err, want) == 0);
        /* Never a device for writing: were the check missing, the rename would replace it. */
        const char *ids[] = {"x"};
        if (strncmp(cases[i].path, "/dev/", 5) != 0)
            CHECK(plcvec_known_write(cases[i].path, ids, 1, "why", err, sizeof err) == -1 && strcmp(err, want) == 0);
    }
    struct stat st;
    CHECK(stat(fifo, &st) == 0 && S_ISFIFO(st.st_mode));    /* left as it was */
    unlink(fifo), unlink(loop_a), unlink(loop_b), rmdir(dir);
}

int main(void)
{
    test_messages();
    test_old_name();
    test_merged_ids();
    test_stale_ids();
    test_files_that_are_not_regular();
    printf("test_known: %d failures\n", failures);
    return failures ? 1 : 0;
}
