/* The PLCVEC_* settings as every plcvec runner reads them (CONTRACT.md, "The environment").
 *
 * A setting that was renamed is still read under its old name, with a warning naming the new one;
 * a PLCVEC_* variable that is neither a setting, an old name nor a name plcvec's own tools use is
 * taken for a misspelling and named with the nearest setting. Each warning is one line on stderr,
 * once per process, in variable order, whichever entry point reads a setting first (plcvec_main,
 * plcvec_run, the GoogleTest pattern, plcvec_judge_new). */
#define _POSIX_C_SOURCE 200809L /* environ */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plcvec/plcvec.h"
#include "settings.h"

extern char **environ;


static const char PREFIX[] = "PLCVEC_";

static const plcvec_old_setting *old_name(const char *name)
{
    for (size_t i = 0; i < plcvec_n_old_settings; i++)
        if (strcmp(plcvec_old_settings[i].name, name) == 0)
            return &plcvec_old_settings[i];
    return NULL;
}

static int is_known(const char *name)
{
    for (size_t i = 0; i < plcvec_n_settings; i++)
        if (strcmp(plcvec_settings[i].name, name) == 0)
            return 1;
    for (const char *const *r = plcvec_reserved_settings; *r; r++)
        if (strcmp(*r, name) == 0)
            return 1;
    for (const char *const *p = plcvec_reserved_setting_prefixes; *p; p++)
        if (strncmp(name, *p, strlen(*p)) == 0)
            return 1;
    return 0;
}

/* Levenshtein distance of the upper-cased `a` and `b` (insert, delete, replace: 1 each), capped:
 * names longer than 63 characters are far from every setting. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), row[64];
    if (la > 63 || lb > 63)
        return (size_t)-1;
    for (size_t j = 0; j <= lb; j++)
        row[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diagonal = row[0];
        row[0] = i;
        char ca = a[i - 1] >= 'a' && a[i - 1] <= 'z' ? (char)(a[i - 1] - 'a' + 'A') : a[i - 1];
        for (size_t j = 1; j <= lb; j++) {
            size_t replace = diagonal + (ca != b[j - 1]), best = row[j] + 1 < row[j - 1] + 1 ? row[j] + 1 : row[j - 1] + 1;
            diagonal = row[j];
            row[j] = replace < best ? replace : best;
        }
    }
    return row[lb];
}

/* The setting `name` is most likely a misspelling of: the first by name among the nearest of the
 * settings and old names (an old name counting as its setting), or NULL when none is near. */
static const char *nearest(const char *name)
{
    const char *best = NULL;
    size_t best_distance = (size_t)-1;
    for (size_t k = 0; k < plcvec_n_settings + plcvec_n_old_settings; k++) {
        const char *candidate = k < plcvec_n_settings ? plcvec_settings[k].name
                                                      : plcvec_old_settings[k - plcvec_n_settings].name;
        size_t d = edit_distance(name, candidate);
        if (d < best_distance || (d == best_distance && strcmp(candidate, best) < 0))
            best = candidate, best_distance = d;
    }
    if (!best || best_distance > plcvec_nearest_distance)
        return NULL;
    const plcvec_old_setting *old = old_name(best);
    return old ? old->replacement : best;
}

static void warn_about(const char *name)
{
    const plcvec_old_setting *old = old_name(name);
    if (old && getenv(old->replacement))
        fprintf(stderr, "plcvec: warning: %s is ignored: it is the old name of %s, which is set too\n", name,
                old->replacement);
    else if (old)
        fprintf(stderr, "plcvec: warning: %s is the old name of %s, read as it until plcvec %s; set %s instead\n", name,
                old->replacement, old->until, old->replacement);
    else if (nearest(name))
        fprintf(stderr, "plcvec: warning: %s is not a plcvec setting; did you mean %s?\n", name, nearest(name));
    else {
        fprintf(stderr, "plcvec: warning: %s is not a plcvec setting; the settings are", name);
        for (size_t i = 0; i < plcvec_n_settings; i++)
            fprintf(stderr, "%s %s", i ? "," : "", plcvec_settings[i].name);
        fprintf(stderr, "\n");
    }
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static void warn(void)
{
    size_t n = 0;
    for (char **e = environ; e && *e; e++)
        n += strncmp(*e, PREFIX, sizeof PREFIX - 1) == 0;
    char **names = n ? malloc(n * sizeof *names) : NULL;
    size_t k = 0;
    for (char **e = environ; names && *e; e++) {
        const char *eq = strchr(*e, '=');
        size_t len = eq ? (size_t)(eq - *e) : strlen(*e);
        if (strncmp(*e, PREFIX, sizeof PREFIX - 1) != 0 || !(names[k] = malloc(len + 1)))
            continue;
        memcpy(names[k], *e, len);
        names[k++][len] = '\0';
    }
    if (k > 1)
        qsort(names, k, sizeof *names, by_name);
    for (size_t i = 0; i < k; i++) {
        if (!is_known(names[i]))
            warn_about(names[i]);
        free(names[i]);
    }
    free(names);
    fflush(stderr);
}

static pthread_once_t warned = PTHREAD_ONCE_INIT;

void plcvec_settings_warn(void)
{
    pthread_once(&warned, warn);
}

const char *plcvec_setting(const char *name)
{
    plcvec_settings_warn();
    const char *value = getenv(name);
    for (size_t i = 0; !value && i < plcvec_n_old_settings; i++)
        if (strcmp(plcvec_old_settings[i].replacement, name) == 0)
            value = getenv(plcvec_old_settings[i].name);
    return value;
}

/* Digits with an optional fraction, above 0 and at most a day, as milliseconds (a fraction finer
 * than a millisecond rounds, but never to 0); -1 otherwise. Read digit by digit: no overflow. */
static long timeout_ms(const char *text)
{
    const char *p = text;
    long whole = 0;
    int any = 0;
    for (; *p >= '0' && *p <= '9'; p++, any = 1)
        if ((whole = whole * 10 + (*p - '0')) > plcvec_timeout_max_s)
            return -1;
    long fraction = 0;      /* in ten-thousandths of a second: one digit more than a millisecond */
    int fraction_nonzero = 0, digits = 0;
    if (*p == '.') {
        for (p++; *p >= '0' && *p <= '9'; p++, digits++) {
            if (digits < 4)
                fraction = fraction * 10 + (*p - '0');
            fraction_nonzero |= *p != '0';
        }
        if (!digits)
            return -1;
    }
    while (digits < 4)
        fraction *= 10, digits++;
    if (!any || *p || (whole == 0 && !fraction_nonzero) || (whole == plcvec_timeout_max_s && fraction_nonzero))
        return -1;
    long ms = whole * 1000 + (fraction + 5) / 10;
    return ms > 0 ? ms : 1;
}

long plcvec_settings_timeout_ms(char *err, size_t errlen)
{
    const char *text = plcvec_setting("PLCVEC_TIMEOUT");
    if (!text)
        return plcvec_timeout_default_s * 1000L;
    long ms = timeout_ms(text);
    if (ms < 0)
        snprintf(err, errlen, "PLCVEC_TIMEOUT=%s: the bound must be a number of seconds above 0 and at most %ld, "
                              "written as digits with an optional fraction (2, 0.5)", text, plcvec_timeout_max_s);
    return ms;
}

int plcvec_settings_check(char *err, size_t errlen)
{
    const char *vectors = plcvec_setting("PLCVEC_VECTORS");
    if (vectors) {
        snprintf(err, errlen, "PLCVEC_VECTORS=%s: the C library's vectors are compiled in; export that folder into a "
                              "copy of the library (plcvec export --lang c --vectors DIR --root COPY) and build the copy "
                              "(README.md, \"The vectors in the library\")", vectors);
        return -1;
    }
    return plcvec_settings_timeout_ms(err, errlen) < 0 ? -1 : 0;
}
