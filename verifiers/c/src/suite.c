/* The compiled-in suite: finding vectors and names, and choosing which vectors to run. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "table.h"

size_t plcvec_count(void)
{
    size_t n = 0;
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++)
        n += plcvec_tables[f]->count;
    return n;
}

const plcvec_vector *plcvec_at(size_t index)
{
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++) {
        if (index < plcvec_tables[f]->count)
            return &plcvec_tables[f]->vectors[index];
        index -= plcvec_tables[f]->count;
    }
    return NULL;
}

const plcvec_vector *plcvec_find(const char *id)
{
    /* Ids are "<family>/...", and each family's vectors are sorted by id: a binary search there. */
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++) {
        size_t len = strlen(plcvec_family_names[f]);
        if (strncmp(id, plcvec_family_names[f], len) != 0 || id[len] != '/')
            continue;
        const plcvec_family_table *t = plcvec_tables[f];
        size_t lo = 0, hi = t->count;
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            int c = strcmp(t->vectors[mid].id, id);
            if (c == 0)
                return &t->vectors[mid];
            if (c < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
    }
    return NULL;
}

const char *plcvec_clause(const plcvec_vector *v, size_t i)
{
    const plcvec_family_table *t = plcvec_tables[v->family];
    return i < v->n_clauses && v->clauses[i] < t->n_clauses ? t->clauses[v->clauses[i]] : NULL;
}

const char *plcvec_operand_device_name(const plcvec_operand *op)
{
    return op->is_constant ? NULL : plcvec_device(op->device)->name;
}

const plcvec_operand *plcvec_operand_named(const plcvec_vector *v, const char *name)
{
    for (size_t i = 0; i < v->n_operands; i++)
        if (strcmp(v->operands[i].name, name) == 0)
            return &v->operands[i];
    return NULL;
}

/* Devices added at run time, after the generated table: ids PLCVEC_DEVICE_COUNT and up. */
static plcvec_device_info *interned;
static int n_interned, cap_interned;

const plcvec_device_info *plcvec_device(int id)
{
    if (id >= 0 && id < PLCVEC_DEVICE_COUNT)
        return &plcvec_devices[id];
    if (id >= PLCVEC_DEVICE_COUNT && id - PLCVEC_DEVICE_COUNT < n_interned)
        return &interned[id - PLCVEC_DEVICE_COUNT];
    return NULL;
}

int plcvec_device_intern(const char *name)
{
    int id = plcvec_device_named(name);
    size_t len = strlen(name);
    if (id >= 0 || len == 0 || len > 23)
        return len > 23 ? -1 : id;
    if (n_interned == cap_interned) {
        int cap = cap_interned ? cap_interned * 2 : 16;
        plcvec_device_info *grown = realloc(interned, (size_t)cap * sizeof *grown);
        if (!grown)
            return -1;
        interned = grown;
        cap_interned = cap;
    }
    /* "D5000" -> kind "D", number 5000; a name without digits at the end has number -1. */
    size_t k = len;
    while (k > 0 && name[k - 1] >= '0' && name[k - 1] <= '9')
        k--;
    char *copy = malloc(2 * len + 2);
    if (!copy)
        return -1;
    memcpy(copy, name, len + 1);
    char *kind = copy + len + 1;
    memcpy(kind, name, k);
    kind[k] = '\0';
    long number = -1;
    if (k < len && k > 0 && len - k <= 9)
        number = strtol(name + k, NULL, 10);
    else if (k < len)
        memcpy(kind, name, len + 1);           /* all digits, or too many: a name, no number */
    interned[n_interned] = (plcvec_device_info){copy, kind, (int32_t)number};
    return PLCVEC_DEVICE_COUNT + n_interned++;
}

int plcvec_device_named(const char *name)
{
    for (int i = 0; i < n_interned; i++)
        if (strcmp(interned[i].name, name) == 0)
            return PLCVEC_DEVICE_COUNT + i;
    size_t lo = 0, hi = PLCVEC_DEVICE_COUNT;       /* the table is sorted by name */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = strcmp(plcvec_devices[mid].name, name);
        if (c == 0)
            return (int)mid;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

long plcvec_size_of(const plcvec_vector *v, const char *kind)
{
    for (size_t i = 0; i < v->n_sizes; i++)
        if (strcmp(v->sizes[i].kind, kind) == 0)
            return (long)v->sizes[i].points;
    return -1;
}

int plcvec_interpretation_named(const char *id)
{
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (strcmp(plcvec_interpretations[i].id, id) == 0)
            return i;
    return -1;
}

int plcvec_alternative_named(int interpretation, const char *alternative)
{
    if (interpretation < 0 || interpretation >= PLCVEC_INTERPRETATION_COUNT)
        return -1;
    const plcvec_interpretation_info *info = &plcvec_interpretations[interpretation];
    for (int a = 0; a < info->n_alternatives; a++)
        if (strcmp(info->alternatives[a], alternative) == 0)
            return a;
    return -1;
}

size_t plcvec_test_name(const plcvec_vector *v, char *buf, size_t size)
{
    size_t len = 0;
    for (const unsigned char *p = (const unsigned char *)v->id; *p; p++) {
        char piece[8];
        unsigned char c = *p;
        if ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))
            piece[0] = (char)c, piece[1] = '\0';
        else if (c == '/')
            strcpy(piece, "__");
        else if (c == '<')
            strcpy(piece, "LT");
        else if (c == '>')
            strcpy(piece, "GT");
        else if (c == '=')
            strcpy(piece, "EQ");
        else if (c == '+')
            strcpy(piece, "PLUS");
        else if (c == '-' || c == ' ' || c == '.')
            strcpy(piece, "_");
        else
            snprintf(piece, sizeof piece, "_x%02X", c);
        for (const char *q = piece; *q; q++, len++)
            if (len + 1 < size)
                buf[len] = *q;
    }
    if (size)
        buf[len < size ? len : size - 1] = '\0';
    return len;
}

/* ---- selection ---------------------------------------------------------------------------- */

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
