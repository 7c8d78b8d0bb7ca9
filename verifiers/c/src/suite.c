/* The compiled-in suite: its vectors, found by position or id, and their names (families,
 * interpretations, devices, clauses, the ids merged into another vector). Choosing which vectors
 * to run is selection.c's. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "suite.h"

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

/* The id `id` became in a `merged` map sorted by the old id, or NULL. */
static const char *merged_once(const plcvec_merged_id *table, size_t n, const char *id)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = strcmp(table[mid].id, id);
        if (c == 0)
            return table[mid].into;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return NULL;
}

const char *plcvec_merged_follow(const plcvec_merged_id *table, size_t n, const char *id)
{
    /* A chain (an id merged into one merged again) is followed to its end; a cycle, which the
     * generator never writes, ends the walk after as many steps as the map has entries. */
    const char *into = merged_once(table, n, id);
    for (size_t hops = 0; into && hops < n; hops++) {
        const char *next = merged_once(table, n, into);
        if (!next)
            break;
        into = next;
    }
    return into;
}

const char *plcvec_merged_into(const char *id)
{
    return plcvec_merged_follow(plcvec_merged_ids, plcvec_n_merged_ids, id);
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

/* Whether two short names ("s1", "D") are the same, compared in place: cheaper than a call of
 * strcmp() for two or three characters, and an implementation asks for operands and sizes by name
 * at every execution. */
static inline int same_name(const char *a, const char *b)
{
    while (*a && *a == *b)
        a++, b++;
    return *a == *b;
}

const plcvec_operand *plcvec_operand_named(const plcvec_vector *v, const char *name)
{
    for (size_t i = 0; i < v->n_operands; i++)
        if (same_name(v->operands[i].name, name))
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
        if (same_name(v->sizes[i].kind, kind))
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
