/* The PLCVEC_* settings as CONTRACT.md ("The environment") states them for every runner: an old
 * name read as its setting with the warning, a misspelling named with the nearest setting, each
 * line exactly once per process on stderr; and PLCVEC_TIMEOUT's one rule and message. The expected
 * lines are CONTRACT.md's; the nearest settings are worked out by hand (edit distances). */
#define _XOPEN_SOURCE 700 /* fork, pipe, setenv, putenv */
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "plcvec/plcvec.h"

extern char **environ;

/* In a child process with `variables` (NAME=VALUE, NULL-terminated) as its only PLCVEC_* ones:
 * read `setting` three times; the child's stderr and the value it read (or "(unset)") go to out. */
static void in_child(const char *const *variables, const char *setting, char *out, size_t size)
{
    int fds[2];
    CHECK(pipe(fds) == 0);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], STDERR_FILENO);
        for (char **e = environ; *e; e++)
            if (strncmp(*e, "PLCVEC_", 7) == 0) {
                char name[128];
                snprintf(name, sizeof name, "%.*s", (int)(strcspn(*e, "=")), *e);
                unsetenv(name);
                e = environ - 1;    /* unsetenv moved the list */
            }
        for (const char *const *v = variables; *v; v++)
            putenv((char *)*v);
        const char *value = NULL;
        for (int i = 0; i < 3; i++)
            value = plcvec_setting(setting);
        fprintf(stderr, "value: %s\n", value ? value : "(unset)");
        _exit(0);
    }
    close(fds[1]);
    size_t len = 0;
    for (ssize_t got; len + 1 < size && (got = read(fds[0], out + len, size - 1 - len)) > 0;)
        len += (size_t)got;
    out[len] = '\0';
    close(fds[0]);
    int status;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

static void expect_child(const char *const *variables, const char *setting, const char *want)
{
    char got[2048];
    in_child(variables, setting, got, sizeof got);
    if (strcmp(got, want) != 0) {
        fprintf(stderr, "with %s ...:\n--- got\n%s--- want\n%s", variables[0], got, want);
        failures++;
    }
}

static void test_warnings(void)
{
    const char *old[] = {"PLCVEC_EXPECTATIONS=old.toml", NULL};
    expect_child(old, "PLCVEC_KNOWN_FAILURES",
                 "plcvec: warning: PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES, read as it until "
                 "plcvec 0.3.0; set PLCVEC_KNOWN_FAILURES instead\nvalue: old.toml\n");
    const char *both[] = {"PLCVEC_EXPECTATIONS=old.toml", "PLCVEC_KNOWN_FAILURES=new.toml", NULL};
    expect_child(both, "PLCVEC_KNOWN_FAILURES",
                 "plcvec: warning: PLCVEC_EXPECTATIONS is ignored: it is the old name of PLCVEC_KNOWN_FAILURES, which "
                 "is set too\nvalue: new.toml\n");
    /* TAGG: one insertion from TAG. Sorted by variable: COLOUR before TAGG. COLOUR is 4 or more
     * edits from every setting. EXPECTATION is one from the old name, which counts as its setting.
     * A lower-case name is compared upper-cased. */
    const char *misspelt[] = {"PLCVEC_TAGG=boundary", "PLCVEC_COLOUR=red", "PLCVEC_EXPECTATION=x", "PLCVEC_tag=y", NULL};
    expect_child(misspelt, "PLCVEC_TAG",
                 "plcvec: warning: PLCVEC_COLOUR is not a plcvec setting; the settings are PLCVEC_VECTORS, PLCVEC_ID, "
                 "PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG, PLCVEC_INTERPRETATION, PLCVEC_SHARD, "
                 "PLCVEC_KNOWN_FAILURES, PLCVEC_WRITE_EXPECTATIONS, PLCVEC_TIMEOUT\n"
                 "plcvec: warning: PLCVEC_EXPECTATION is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?\n"
                 "plcvec: warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?\n"
                 "plcvec: warning: PLCVEC_tag is not a plcvec setting; did you mean PLCVEC_TAG?\n"
                 "value: (unset)\n");
    /* The names plcvec's own tools use, and the tests' prefix, are no misspellings. */
    const char *reserved[] = {"PLCVEC_HOSTILE=crash", "PLCVEC_CACHE_DIR=/tmp", "PLCVEC_TEST_ANYTHING=1",
                              "PLCVEC_FAMILY=fx5-time-add", NULL};
    expect_child(reserved, "PLCVEC_FAMILY", "value: fx5-time-add\n");
}

static int never_run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    (void)ctx, (void)v, (void)out;
    return 0;
}

/* PLCVEC_TIMEOUT: digits with an optional fraction, above 0, at most 86400 (CONTRACT.md). */
static void test_timeout_rule(void)
{
    static const char *const taken[] = {"10", "2.5", "0.5", "86400", "86400.000", "0.0001", "007"};
    static const char *const refused[] = {"1e9", "1e12", "86401", "86400.5", "86400.00001", "0", "0.000", "-1", "+1",
                                          " 1", "1 ", "1.", ".5", "soon", "", "99999999999999999999999999", "inf",
                                          "nan", "0x10", "1,5"};
    plcvec_impl impl = {0};
    impl.run = never_run;
    char err[512];
    for (size_t i = 0; i < sizeof taken / sizeof taken[0]; i++) {
        setenv("PLCVEC_TIMEOUT", taken[i], 1);
        plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
        if (!j)
            fprintf(stderr, "PLCVEC_TIMEOUT=%s refused: %s\n", taken[i], err);
        CHECK(j != NULL);
        plcvec_judge_free(j);
    }
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        setenv("PLCVEC_TIMEOUT", refused[i], 1);
        char want[512];
        snprintf(want, sizeof want, "PLCVEC_TIMEOUT=%s: the bound must be a number of seconds above 0 and at most "
                                    "86400, written as digits with an optional fraction (2, 0.5)", refused[i]);
        plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
        CHECK(j == NULL && strcmp(err, want) == 0);
        if (j || strcmp(err, want) != 0)
            fprintf(stderr, "PLCVEC_TIMEOUT=%s: %s\n", refused[i], j ? "taken" : err);
        plcvec_judge_free(j);
    }
    unsetenv("PLCVEC_TIMEOUT");
}

int main(void)
{
    test_warnings();        /* first: each child forks before this process has read a setting */
    test_timeout_rule();
    printf("test_settings: %d failures\n", failures);
    return failures ? 1 : 0;
}
