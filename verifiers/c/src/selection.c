/* Choosing which vectors to run: by family, instruction, tag, id glob and interpretation (OR
 * within a list, AND between lists) and by shard, with the rules of every plcvec runner; and the
 * PLCVEC_* variables that give those lists. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "selection.h"
#include "settings.h"

uint32_t plcvec_crc32(const char *text)
{
    /* CRC-32 (IEEE 802.3, reflected, as zlib.crc32), bitwise: ids are short and selection runs once. */
    uint32_t crc = 0xFFFFFFFFu;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        crc ^= *p;
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/* A [...] set at p (just after '['): sets *matched and returns the position after ']', or NULL
 * if the set is not closed (then '[' is an ordinary character, as in fnmatch). */
static const char *glob_set(const char *p, unsigned char c, int *matched)
{
    int negate = 0, hit = 0;
    if (*p == '!') {
        negate = 1;
        p++;
    }
    const char *start = p;
    while (*p && (*p != ']' || p == start)) {
        unsigned char lo = (unsigned char)*p, hi = lo;
        if (p[1] == '-' && p[2] && p[2] != ']') {
            hi = (unsigned char)p[2];
            p += 2;
        }
        if (lo <= c && c <= hi)
            hit = 1;
        p++;
    }
    if (*p != ']')
        return NULL;
    *matched = hit != negate;
    return p + 1;
}

int plcvec_glob(const char *pattern, const char *text)
{
    /* Iterative matching with one backtrack point for the last '*': linear in practice. */
    const char *p = pattern, *t = text, *star = NULL, *resume = NULL;
    while (*t) {
        if (*p == '*') {
            star = ++p;
            resume = t;
            continue;
        }
        if (*p == '[') {
            int matched = 0;
            const char *after = glob_set(p + 1, (unsigned char)*t, &matched);
            if (after && matched) {
                p = after;
                t++;
                continue;
            }
            if (!after && *t == '[') {
                p++;
                t++;
                continue;
            }
        } else if (*p && (*p == '?' || *p == *t)) {
            p++;
            t++;
            continue;
        }
        if (!star)
            return 0;
        p = star;
        t = ++resume;
    }
    while (*p == '*')
        p++;
    return *p == '\0';
}

static int in_list(const char *const *list, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(list[i], name) == 0)
            return 1;
    return 0;
}

int plcvec_selected(const plcvec_selection *sel, const plcvec_vector *v)
{
    if (sel->n_families && !in_list(sel->families, sel->n_families, plcvec_family_names[v->family]))
        return 0;
    if (sel->n_instructions && !in_list(sel->instructions, sel->n_instructions, plcvec_instruction_names[v->instruction]))
        return 0;
    if (sel->n_tags) {
        int any = 0;
        for (size_t i = 0; i < sel->n_tags && !any; i++)
            for (int t = 0; t < PLCVEC_TAG_COUNT; t++)
                if ((v->tags >> t & 1) && strcmp(plcvec_tag_names[t], sel->tags[i]) == 0)
                    any = 1;
        if (!any)
            return 0;
    }
    if (sel->n_ids) {
        int any = 0;
        for (size_t i = 0; i < sel->n_ids && !any; i++)
            any = plcvec_glob(sel->ids[i], v->id);
        if (!any)
            return 0;
    }
    if (sel->n_interpretations) {
        int any = 0;
        for (size_t i = 0; i < v->n_interpretations && !any; i++)
            any = in_list(sel->interpretations, sel->n_interpretations, plcvec_interpretations[v->interpretations[i]].id);
        if (!any)
            return 0;
    }
    if (sel->shard_n && plcvec_crc32(v->id) % sel->shard_n + 1 != sel->shard_k)
        return 0;
    return 1;
}

/* An unknown name is a usage error that lists the known ones: a typo in a CI file must not turn a
 * gate off by selecting nothing. */
static int check_names(const char *what, const char *const *list, size_t n, const char *const *names,
                       size_t count, char *err, size_t errlen)
{
    for (size_t i = 0; i < n; i++)
        if (!in_list(names, count, list[i])) {
            size_t len = (size_t)snprintf(err, errlen, "unknown %s '%s': the suite has no such %s; known:", what, list[i], what);
            for (size_t k = 0; k < count && len < errlen; k++)
                len += (size_t)snprintf(err + len, errlen - len, "%s %s", k ? "," : "", names[k]);
            return -1;
        }
    return 0;
}

long plcvec_select(const plcvec_selection *sel, const plcvec_vector ***out, char *err, size_t errlen)
{
    static const plcvec_selection all;
    if (!sel)
        sel = &all;
    const char *interps[PLCVEC_INTERPRETATION_COUNT];
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        interps[i] = plcvec_interpretations[i].id;
    if (check_names("family", sel->families, sel->n_families, plcvec_family_names, PLCVEC_FAMILY_COUNT, err, errlen) ||
        check_names("instruction", sel->instructions, sel->n_instructions, plcvec_instruction_names,
                    PLCVEC_INSTRUCTION_COUNT, err, errlen) ||
        check_names("tag", sel->tags, sel->n_tags, plcvec_tag_names, PLCVEC_TAG_COUNT, err, errlen) ||
        check_names("interpretation", sel->interpretations, sel->n_interpretations, interps,
                    PLCVEC_INTERPRETATION_COUNT, err, errlen))
        return -1;
    if ((sel->shard_n || sel->shard_k) && !(sel->shard_k >= 1 && sel->shard_k <= sel->shard_n)) {
        snprintf(err, errlen, "shard %u/%u: K must be between 1 and N", sel->shard_k, sel->shard_n);
        return -1;
    }
    size_t total = plcvec_count(), n = 0;
    for (size_t i = 0; i < sel->n_ids; i++) {
        size_t k = 0;
        while (k < total && !plcvec_glob(sel->ids[i], plcvec_at(k)->id))
            k++;
        if (k == total) {
            snprintf(err, errlen, "id %s: matches no vector id in the suite (ids look like %s; a glob matches the whole id)",
                     sel->ids[i], total ? plcvec_at(0)->id : "family/instruction/...");
            return -1;
        }
    }
    const plcvec_vector **list = malloc((total ? total : 1) * sizeof *list);
    if (!list) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (size_t i = 0; i < total; i++) {
        const plcvec_vector *v = plcvec_at(i);
        if (plcvec_selected(sel, v))
            list[n++] = v;
    }
    *out = list;
    return (long)n;
}

/* ---- the lists from the command line and the variables --------------------------------------- */

const char *const plcvec_filter_options[PLCVEC_N_FILTERS] = {"--family", "--instruction", "--tag", "--id",
                                                             "--interpretation"};
const char *const plcvec_filter_variables[PLCVEC_N_FILTERS] = {"PLCVEC_FAMILY", "PLCVEC_INSTRUCTION", "PLCVEC_TAG",
                                                               "PLCVEC_ID", "PLCVEC_INTERPRETATION"};

int plcvec_filters_push(plcvec_filters *f, int l, const char *name)
{
    if (f->counts[l] == f->caps[l]) {
        size_t cap = f->caps[l] ? f->caps[l] * 2 : 8;
        const char **grown = realloc(f->lists[l], cap * sizeof *grown);
        if (!grown)
            return -1;
        f->lists[l] = grown, f->caps[l] = cap;
    }
    f->lists[l][f->counts[l]++] = name;
    return 0;
}

/* One comma-separated item, trimmed of spaces, in place; NULL when it is empty. */
static char *trimmed(char *item)
{
    char *end = item + strlen(item);
    while (*item == ' ')
        item++;
    while (end > item && end[-1] == ' ')
        *--end = '\0';
    return *item ? item : NULL;
}

/* PLCVEC_FAMILY=a,b: the names, split in place of a copy. An empty item is a mistake, not "no
 * filter": `PLCVEC_FAMILY=,` must not run everything. */
int plcvec_filters_from_environment(plcvec_filters *f, int l, char *err, size_t errlen)
{
    const char *text = plcvec_setting(plcvec_filter_variables[l]);
    if (!text)
        return 0;
    size_t len = strlen(text);
    char *copy = f->copies[l] = malloc(len + 1);
    if (!copy) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(copy, text, len + 1);
    for (char *item = copy;;) {
        char *comma = strchr(item, ',');
        if (comma)
            *comma = '\0';
        char *name = trimmed(item);
        if (!name) {
            snprintf(err, errlen, "%s=%s: an empty name (the variable takes comma-separated names; unset it to select "
                                  "everything)", plcvec_filter_variables[l], text);
            return -1;
        }
        if (plcvec_filters_push(f, l, name)) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        if (!comma)
            return 0;
        item = comma + 1;
    }
}

void plcvec_filters_select(const plcvec_filters *f, plcvec_selection *sel)
{
    sel->families = f->lists[PLCVEC_F_FAMILY], sel->n_families = f->counts[PLCVEC_F_FAMILY];
    sel->instructions = f->lists[PLCVEC_F_INSTRUCTION], sel->n_instructions = f->counts[PLCVEC_F_INSTRUCTION];
    sel->tags = f->lists[PLCVEC_F_TAG], sel->n_tags = f->counts[PLCVEC_F_TAG];
    sel->ids = f->lists[PLCVEC_F_ID], sel->n_ids = f->counts[PLCVEC_F_ID];
    sel->interpretations = f->lists[PLCVEC_F_INTERPRETATION], sel->n_interpretations = f->counts[PLCVEC_F_INTERPRETATION];
}

void plcvec_filters_free(plcvec_filters *f)
{
    for (int l = 0; l < PLCVEC_N_FILTERS; l++) {
        free(f->lists[l]);
        free(f->copies[l]);
    }
    memset(f, 0, sizeof *f);
}

int plcvec_parse_shard(const char *what, const char *text, plcvec_selection *sel, char *err, size_t errlen)
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

/* Only the vectors of `family`, kept in order; -1 and err when the suite has no such family. */
static long keep_family(const char *family, const plcvec_vector **list, long n, char *err, size_t errlen)
{
    int f = 0;
    while (f < PLCVEC_FAMILY_COUNT && strcmp(plcvec_family_names[f], family) != 0)
        f++;
    if (f == PLCVEC_FAMILY_COUNT) {
        snprintf(err, errlen, "unknown family '%s': the suite has no such family", family);
        return -1;
    }
    long k = 0;
    for (long i = 0; i < n; i++)
        if ((int)list[i]->family == f)
            list[k++] = list[i];
    return k;
}

long plcvec_select_from_environment(const char *family, const plcvec_vector ***out, char *err, size_t errlen)
{
    plcvec_filters f = {0};
    plcvec_selection sel = {0};
    *out = NULL;
    long n = -1;
    int l = 0;
    while (l < PLCVEC_N_FILTERS && plcvec_filters_from_environment(&f, l, err, errlen) == 0)
        l++;
    const char *shard = plcvec_setting("PLCVEC_SHARD");
    if (l == PLCVEC_N_FILTERS && (!shard || plcvec_parse_shard("PLCVEC_SHARD", shard, &sel, err, errlen) == 0) &&
        plcvec_settings_check(err, errlen) == 0) {
        plcvec_filters_select(&f, &sel);
        n = plcvec_select(&sel, out, err, errlen);
    }
    if (n >= 0 && family && (n = keep_family(family, *out, n, err, errlen)) < 0) {
        free(*out);
        *out = NULL;
    }
    plcvec_filters_free(&f);
    return n;
}
